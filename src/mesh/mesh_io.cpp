// Mesh input and output. OpenMesh 9.0 is the mesh library, but its readers trust their input
// and lose precision: the PLY reader rounds positions to float, truncates float colours to 8 bits
// and loops forever on a truncated header; the OBJ reader writes outside its arrays on an
// out-of-range index; a corrupt OM file aborts or segfaults inside the library; and a text value
// a reader cannot parse silently shifts every value after it. So PLY has a reader of its own,
// OBJ, OFF and STL are checked before OpenMesh reads them, OM is read in a child process (one
// file per format in formats/), and OpenMesh's log streams are captured so that the user sees
// our one-line error rather than its chatter.
#include "mesh/mesh_io.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>
#include <new>
#include <optional>

#include "core/error.h"
#include "core/file_name.h"
#include "core/fs.h"
#include "core/temp_file.h"
#include "mesh/formats/obj_check.h"
#include "mesh/formats/off_check.h"
#include "mesh/formats/om_reader.h"
#include "mesh/formats/ply_reader.h"
#include "mesh/formats/ply_writer.h"
#include "mesh/formats/stl_check.h"
#include "mesh/mesh_checks.h"
#include "mesh/openmesh_log.h"
#include "mesh/reader_support.h"
#include "mesh/triangulate.h"
#include "mesh/uv_seams.h"

namespace lt {

using OpenMesh::IO::Options;

namespace {

const char* const kReadable = ".ply, .obj, .off, .stl, .stla, .stlb, .om";

LoadedMesh read_mesh_unguarded(const fs::path& path) {
  using namespace meshio;  // in the function: the core is a unity build (CMakeLists.txt)
  const std::string file = path.string();
  // Regular files within the size cap only, before anything opens it (the OM reader in its
  // child opens it by name).
  check_input_file(path, InputKind::Mesh);
  const std::string ext = lower_extension(path);
  const bool stl = ext == ".stl" || ext == ".stla" || ext == ".stlb";
  if (ext != ".ply" && ext != ".obj" && ext != ".off" && ext != ".om" && !stl) {
    throw InputError(file, "", "unknown mesh format '" + ext + "' (readable: " + kReadable + ")");
  }

  LoadedMesh loaded;
  FileFacts facts;
  if (ext == ".ply") {
    std::string data = read_input_file(path, InputKind::Mesh);
    refuse_utf16(data, file);
    const std::string bom = skip_utf8_bom(data);
    const RawMesh ply = parse_ply(data, file);
    loaded.warnings = ply.warnings;
    if (!bom.empty()) loaded.warnings.insert(loaded.warnings.begin(), bom);
    OpenMeshLogCapture capture;  // the importer reports through omerr
    build_mesh(ply, loaded, facts);
  } else if (ext == ".om") {
    OpenMeshLogCapture capture;
    // Rebuilt from the face loops: whatever halfedges the file held, the mesh we hand on has
    // the connectivity add_face makes.
    build_mesh(read_om_in_child(path, file, capture), loaded, facts);
  } else {
    std::string data = read_input_file(path, InputKind::Mesh);
    // Not in a binary STL, whose 80-byte header is free-form: only before an ASCII one's "solid".
    if (!stl) refuse_utf16(data, file);
    const bool binary_stl = stl && data.rfind(std::string(kUtf8Bom) + "solid", 0) != 0;
    const std::string bom = binary_stl ? "" : skip_utf8_bom(data);
    if (ext == ".obj") facts = check_obj(data, file);
    if (ext == ".off") facts = check_off(data, file);
    if (stl) check_stl(data, file);
    OpenMeshLogCapture capture;
    PolyMesh& mesh = loaded.mesh;
    // Vertex status lets the importer mark the copies it makes for non-manifold faces;
    // halfedge texture coordinates receive an OBJ's per-corner vt.
    mesh.request_vertex_status();
    mesh.request_halfedge_texcoords2D();
    Options options = requested_options();
    if (!bom.empty()) loaded.warnings.push_back(bom);
    // OpenMesh reads by name: a file it would misread (a byte-order mark, an OFF's comments) is
    // handed to it as a copy in the form it reads.
    const std::string& text = facts.rewritten.empty() ? data : facts.rewritten;
    std::optional<TempFile> copy;
    if (!bom.empty() || !facts.rewritten.empty()) {
      copy.emplace("mesh", ext, text.data(), text.size());
      if (!copy->written()) throw InputError(file, "", "could not write the copy OpenMesh reads");
    }
    read_with_openmesh(mesh, file, options, capture, copy ? copy->path().string() : "");
    // STL has neither vertex normals nor colours, but its reader hands the request back as if
    // the file had them (and leaves them uninitialised).
    if (stl) {
      options -= Options::VertexNormal | Options::VertexColor | Options::ColorFloat;
      options -= Options::VertexTexCoord | Options::FaceTexCoord;
    }
    loaded.read_options = options;
    const std::size_t split = repair_split_vertices(mesh, options, facts);
    if (split) {
      loaded.warnings.push_back(plural(split, "vertex", "vertices") +
                                " duplicated to split off non-manifold faces");
    }
    if (facts.vertices && mesh.n_vertices() != facts.vertices + split) {
      throw InputError(file, "",
                       "OpenMesh read " + plural(mesh.n_vertices() - split, "vertex", "vertices") +
                           " where the file has " + std::to_string(facts.vertices));
    }
    mesh.release_vertex_status();
    // OBJ gives texture coordinates per face corner: one position with several is a seam.
    if (ext == ".obj") split_uv_seams(loaded, facts);
    if (mesh.has_halfedge_texcoords2D()) mesh.release_halfedge_texcoords2D();
  }
  finish_loaded_mesh(loaded, file, facts);
  return loaded;
}

// A mesh within the size cap can still be too large for the machine (a 256 MiB file becomes a
// few GB of halfedges): that is this file's failure, so it is named.
[[noreturn]] void out_of_memory(const fs::path& path) {
  throw InputError(path.string(), "",
                   "out of memory reading this mesh (too large for this machine?)");
}

}  // namespace

LoadedMesh read_mesh(const fs::path& path) {
  try {
    return read_mesh_unguarded(path);
  } catch (const std::bad_alloc&) {
    out_of_memory(path);
  }
}

TriangleMesh to_triangle_mesh(const LoadedMesh& loaded) {
  const PolyMesh& mesh = loaded.mesh;
  TriangleMesh out;
  out.positions.reserve(mesh.n_vertices());
  out.normals.reserve(mesh.n_vertices());
  for (auto vh : mesh.vertices()) {
    out.positions.push_back(to_glm(mesh.point(vh)));
    out.normals.push_back(to_glm(mesh.normal(vh)));
  }
  if (loaded.read_options.vertex_has_texcoord()) {
    out.uvs.reserve(mesh.n_vertices());
    for (auto vh : mesh.vertices()) out.uvs.push_back(to_glm(mesh.texcoord2D(vh)));
  }
  if (loaded.read_options.vertex_has_color()) {
    out.colors.reserve(mesh.n_vertices());
    for (auto vh : mesh.vertices()) {
      const auto& c = mesh.color(vh);
      out.colors.emplace_back(c[0], c[1], c[2]);
    }
  }
  // Convex faces as a fan from their first corner, concave ones ear-clipped; both keep the
  // polygon's winding (and so its orientation).
  out.triangles = triangulate_faces(mesh);
  return out;
}

TriangleMesh load_triangle_mesh(const fs::path& path) {
  LoadedMesh loaded = read_mesh(path);
  try {
    return to_triangle_mesh(loaded);
  } catch (const std::bad_alloc&) {
    out_of_memory(path);
  }
}

void write_mesh(const fs::path& path, const PolyMesh& mesh, Options options,
                const std::vector<ExtraVertexProperty>& extras) {
  const std::string ext = lower_extension(path);
  if (ext == ".ply") {
    write_atomically(
        path, [&](const fs::path& tmp) { meshio::write_ply(tmp, path, mesh, options, extras); });
    return;
  }
  if (!extras.empty()) {
    std::string names;
    for (const auto& e : extras) names += (names.empty() ? "" : ", ") + e.name;
    throw InputError(path.string(), "",
                     "only PLY can carry the vertex properties " + names + ": write .ply");
  }
  static const char* const writable[] = {".obj", ".off", ".om", ".stl", ".stla", ".stlb", ".vtk"};
  if (std::find(std::begin(writable), std::end(writable), ext) == std::end(writable)) {
    throw InputError(
        path.string(), "",
        "unknown mesh format '" + ext + "' (writable: .ply, .obj, .off, .om, .stl, .vtk)");
  }
  write_atomically(path, [&](const fs::path& tmp) {
    meshio::OpenMeshLogCapture capture;
    // 17 significant digits: OpenMesh's default of 6 would move a vertex at 1e6 by up to 0.5.
    if (!OpenMesh::IO::write_mesh(mesh, tmp.string(), options, 17)) {
      const std::string why = capture.last_line();
      throw InputError(path.string(), "",
                       "OpenMesh could not write it" + (why.empty() ? std::string() : ": " + why));
    }
  });
}

void write_triangle_mesh(const fs::path& path, const TriangleMesh& m) {
  PolyMesh mesh;
  mesh.reserve(m.positions.size(), 3 * m.triangles.size(), m.triangles.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const auto vh = mesh.add_vertex(to_om(m.positions[i]));
    mesh.set_normal(vh, to_om(m.normals[i]));
    if (m.has_colors()) {
      const glm::dvec3& c = m.colors[i];
      mesh.set_color(vh, PolyMesh::Color(static_cast<float>(c.r), static_cast<float>(c.g),
                                         static_cast<float>(c.b)));
    }
    if (!m.uvs.empty()) mesh.set_texcoord2D(vh, to_om(m.uvs[i]));
  }
  {
    meshio::OpenMeshLogCapture capture;  // add_face reports a complex edge on its log, then refuses
    for (const glm::uvec3& t : m.triangles) {
      const auto fh = mesh.add_face(OpenMesh::VertexHandle(static_cast<int>(t[0])),
                                    OpenMesh::VertexHandle(static_cast<int>(t[1])),
                                    OpenMesh::VertexHandle(static_cast<int>(t[2])));
      if (!fh.is_valid())
        throw InputError(path.string(), "",
                         "triangle " + std::to_string(mesh.n_faces()) +
                             " is not manifold: a PLY read through OpenMesh would lose it");
    }
  }
  Options options(Options::Binary | Options::VertexNormal);
  if (m.has_colors()) {
    options += Options::VertexColor;
    options += Options::ColorFloat;
  }
  if (!m.uvs.empty()) options += Options::VertexTexCoord;
  write_mesh(path, mesh, options);
}

}  // namespace lt
