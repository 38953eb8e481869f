#include "mesh/raw_mesh.h"

#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <algorithm>

#include "mesh/reader_support.h"

namespace lt::meshio {

using OpenMesh::IO::Options;

void FileFacts::take_parsed_colors(std::vector<glm::vec3> parsed, std::size_t colored) {
  colors_checked = true;
  if (colored > 0 && colored == vertices) {
    has_colors = true;
    colors = std::move(parsed);
  } else if (colored > 0) {
    partial_colors = true;
  }
}

std::vector<std::uint32_t> build_mesh(const RawMesh& raw, LoadedMesh& loaded, FileFacts& facts) {
  PolyMesh& mesh = loaded.mesh;
  mesh.clear();
  const std::size_t nv = raw.positions.size();
  const std::size_t nf = raw.face_offsets.size() - 1;
  mesh.reserve(nv, 3 * nv, nf);
  for (const auto& p : raw.positions) mesh.add_vertex(to_om(p));

  // Which file vertex each mesh vertex came from: itself, or for the copies the importer makes
  // to split off a non-manifold face, the corner it copied (copies are made in corner order).
  std::vector<std::uint32_t> origin(nv);
  for (std::size_t v = 0; v < nv; ++v) origin[v] = static_cast<std::uint32_t>(v);

  OpenMesh::IO::ImporterT<PolyMesh> importer(mesh);
  std::vector<OpenMesh::VertexHandle> handles;
  for (std::size_t f = 0; f < nf; ++f) {
    handles.clear();
    for (auto k = raw.face_offsets[f]; k < raw.face_offsets[f + 1]; ++k) {
      handles.emplace_back(static_cast<int>(raw.face_indices[k]));
    }
    auto sorted = handles;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      ++facts.repeated_faces;
      continue;
    }
    const std::size_t before = mesh.n_vertices();
    importer.add_face(handles);
    for (std::size_t v = before; v < mesh.n_vertices(); ++v) {
      origin.push_back(raw.face_indices[raw.face_offsets[f] + (v - before)]);
    }
  }

  loaded.read_options = Options();
  if (raw.binary) loaded.read_options += Options::Binary;
  facts.vertices = nv;
  facts.normal_given.assign(mesh.n_vertices(), 0);
  if (!raw.normals.empty()) {
    loaded.read_options += Options::VertexNormal;
    for (auto vh : mesh.vertices()) {
      mesh.set_normal(vh, to_om(raw.normals[origin[vh.idx()]]));
      facts.normal_given[vh.idx()] = 1;
    }
  }
  if (!raw.colors.empty()) {
    loaded.read_options += Options::VertexColor;
    if (raw.float_colors) loaded.read_options += Options::ColorFloat;
    for (auto vh : mesh.vertices()) {
      const auto& c = raw.colors[origin[vh.idx()]];
      mesh.set_color(vh, OpenMesh::Vec3f(c.r, c.g, c.b));
    }
  }
  if (!raw.uvs.empty()) {
    loaded.read_options += Options::VertexTexCoord;
    for (auto vh : mesh.vertices()) mesh.set_texcoord2D(vh, to_om(raw.uvs[origin[vh.idx()]]));
  }
  loaded.extra_vertex_properties.clear();
  for (const auto& extra : raw.extras) {
    ExtraVertexProperty copy{extra.name, extra.ply_type, {}};
    copy.values.reserve(mesh.n_vertices());
    for (auto vh : mesh.vertices()) copy.values.push_back(extra.values[origin[vh.idx()]]);
    loaded.extra_vertex_properties.push_back(std::move(copy));
  }
  if (mesh.n_vertices() > nv) {
    loaded.warnings.push_back(plural(mesh.n_vertices() - nv, "vertex", "vertices") +
                              " duplicated to split off non-manifold faces");
  }
  return origin;
}

}  // namespace lt::meshio
