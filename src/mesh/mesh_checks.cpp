#include "mesh/mesh_checks.h"

#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "mesh/normals.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

using OpenMesh::IO::Options;

std::size_t repair_split_vertices(PolyMesh& mesh, const Options& opts, FileFacts& facts) {
  std::vector<OpenMesh::VertexHandle> copies;
  for (auto vh : mesh.vertices()) {
    if (mesh.status(vh).fixed_nonmanifold()) copies.push_back(vh);
  }
  facts.normal_given.resize(mesh.n_vertices(), opts.vertex_has_normal() ? 1 : 0);
  if (facts.has_colors) facts.colors.resize(mesh.n_vertices(), glm::vec3(0.0f));
  if (copies.empty()) return 0;
  std::map<std::array<double, 3>, int> originals;
  for (auto vh : mesh.vertices()) {
    if (mesh.status(vh).fixed_nonmanifold()) continue;
    const auto& p = mesh.point(vh);
    originals.emplace(std::array<double, 3>{p[0], p[1], p[2]}, vh.idx());
  }
  for (auto vh : copies) {
    const auto& p = mesh.point(vh);
    auto it = originals.find({p[0], p[1], p[2]});
    const auto i = static_cast<std::size_t>(vh.idx());
    if (it == originals.end()) {
      facts.normal_given[i] = 0;
      mesh.set_color(vh, OpenMesh::Vec3f(0.0f));
      continue;
    }
    const OpenMesh::VertexHandle from(it->second);
    const auto j = static_cast<std::size_t>(from.idx());
    mesh.set_normal(vh, mesh.normal(from));
    mesh.set_color(vh, mesh.color(from));
    mesh.set_texcoord2D(vh, mesh.texcoord2D(from));
    facts.normal_given[i] = facts.normal_given[j];
    if (facts.has_colors) facts.colors[i] = facts.colors[j];
  }
  return copies.size();
}

void finish_loaded_mesh(LoadedMesh& loaded, const std::string& file, FileFacts& facts) {
  PolyMesh& mesh = loaded.mesh;
  if (mesh.n_vertices() == 0) fail(file, 0, "mesh is empty (no vertices)");
  if (mesh.n_faces() == 0) {
    fail(file, 0, "mesh has " + plural(mesh.n_vertices(), "vertex", "vertices") + " but no faces");
  }
  for (auto vh : mesh.vertices()) {
    const glm::dvec3 p = to_glm(mesh.point(vh));
    if (!is_finite(p)) {
      std::ostringstream what;
      what << "vertex " << vh.idx() << " has a non-finite coordinate (" << p.x << ", " << p.y
           << ", " << p.z << ")";
      fail(file, 0, what.str());
    }
  }
  if (loaded.read_options.vertex_has_texcoord()) {
    for (auto vh : mesh.vertices()) {
      if (!is_finite(to_glm(mesh.texcoord2D(vh)))) {
        fail(file, 0,
             "vertex " + std::to_string(vh.idx()) + " has a non-finite texture coordinate");
      }
    }
  }
  if (facts.face_colours_dropped > 0) {
    loaded.warnings.push_back(plural(facts.face_colours_dropped, "face colour", "face colours") +
                              " ignored (the paths shade with vertex colours only)");
  }
  if (facts.repeated_faces > 0) {
    loaded.warnings.push_back(plural(facts.repeated_faces, "face", "faces") +
                              " naming a vertex twice dropped (a halfedge mesh cannot hold them)");
  }

  // Colours: ours where we parsed them, none where only some vertices had one.
  if (facts.partial_colors || (facts.colors_checked && !facts.has_colors)) {
    loaded.read_options -= Options::VertexColor;
    loaded.read_options -= Options::ColorFloat;
    if (facts.partial_colors)
      loaded.warnings.push_back("only some vertices have colours: colours ignored");
  } else if (facts.has_colors) {
    loaded.read_options += Options::VertexColor;
    for (auto vh : mesh.vertices()) {
      const auto& c = facts.colors[static_cast<std::size_t>(vh.idx())];
      mesh.set_color(vh, OpenMesh::Vec3f(c.r, c.g, c.b));
    }
  }
  if (loaded.read_options.vertex_has_color()) {
    for (auto vh : mesh.vertices()) {
      const auto& c = mesh.color(vh);
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
        fail(file, 0, "vertex " + std::to_string(vh.idx()) + " has a non-finite colour");
      }
    }
  }

  // Normals: keep the file's where they are usable (normalised), recompute the rest.
  std::vector<char> keep(mesh.n_vertices(), 0);
  std::size_t zero = 0, nonfinite = 0, nonunit = 0, missing = 0;
  if (loaded.read_options.vertex_has_normal()) {
    for (auto vh : mesh.vertices()) {
      const auto i = static_cast<std::size_t>(vh.idx());
      if (i >= facts.normal_given.size() || !facts.normal_given[i]) {
        ++missing;
        continue;
      }
      const glm::dvec3 n = to_glm(mesh.normal(vh));
      if (!is_finite(n)) {
        ++nonfinite;
      } else if (n == glm::dvec3(0.0)) {
        ++zero;
      } else {
        // Float normals in files are off by ~1e-7; only count what is clearly not unit length.
        if (std::fabs(glm::length(n) - 1.0) > 1e-5) ++nonunit;
        mesh.set_normal(vh, to_om(safe_normalize(n)));
        keep[i] = 1;
      }
    }
  } else {
    loaded.notes.push_back(
        "no vertex normals in the file: computed from the faces (area-weighted)");
  }
  const std::size_t without = recompute_normals(mesh, keep);
  // One warning a kind of fix, with its count.
  auto warn = [&](std::size_t n, const char* one, const char* many, const char* what) {
    if (n) loaded.warnings.push_back(plural(n, one, many) + what);
  };
  warn(zero, "zero-length normal", "zero-length normals", " recomputed from the faces");
  warn(nonfinite, "non-finite normal", "non-finite normals", " recomputed from the faces");
  warn(missing, "vertex", "vertices", " without a normal in the file: computed from the faces");
  warn(nonunit, "non-unit normal", "non-unit normals", " normalised");
  warn(without, "vertex has", "vertices have",
       " no normal (isolated, or only degenerate faces around it): left zero");
}

}  // namespace lt::meshio
