#include "mesh/uv_seams.h"

#include <utility>
#include <vector>

namespace lt::meshio {

using OpenMesh::IO::Options;

std::size_t split_uv_seams(LoadedMesh& loaded, FileFacts& facts) {
  PolyMesh& mesh = loaded.mesh;
  const bool corner_uvs = loaded.read_options.face_has_texcoord();
  loaded.read_options -= Options::FaceTexCoord;
  if (facts.uv_mix_line) {
    loaded.uvs_dropped = "its faces mix corners with and without texture coordinates (vt), " +
                         std::string("first at line ") + std::to_string(facts.uv_mix_line);
    loaded.warnings.push_back(loaded.uvs_dropped + ": the mesh is read without UVs");
  }
  if (!corner_uvs || !mesh.has_halfedge_texcoords2D() || facts.uv_mix_line) {
    loaded.read_options -= Options::VertexTexCoord;
    return 0;
  }
  const std::size_t nv = mesh.n_vertices();
  const bool colors = loaded.read_options.vertex_has_color();
  // The mesh as arrays, vertex v first as itself; `source` names the mesh vertex of each.
  RawMesh raw;
  std::vector<std::uint32_t> source(nv);
  auto add_copy_of = [&](OpenMesh::VertexHandle vh) {
    raw.positions.push_back(to_glm(mesh.point(vh)));
    raw.normals.push_back(to_glm(mesh.normal(vh)));
    const auto& c = mesh.color(vh);
    if (colors) raw.colors.emplace_back(c[0], c[1], c[2]);
    raw.uvs.emplace_back(0.0);
  };
  for (auto vh : mesh.vertices()) {
    add_copy_of(vh);
    source[static_cast<std::size_t>(vh.idx())] = static_cast<std::uint32_t>(vh.idx());
  }
  // Per mesh vertex, the UVs its corners had so far and the array vertex each became.
  std::vector<std::vector<std::pair<glm::dvec2, std::uint32_t>>> seen(nv);
  for (auto fh : mesh.faces()) {
    for (auto heh : mesh.fh_range(fh)) {
      const auto vh = mesh.to_vertex_handle(heh);
      const glm::dvec2 uv = to_glm(mesh.texcoord2D(heh));
      auto& known = seen[static_cast<std::size_t>(vh.idx())];
      std::uint32_t index = 0;
      bool found = false;
      for (const auto& [k_uv, k_index] : known) {
        if (k_uv == uv) {
          index = k_index;
          found = true;
          break;
        }
      }
      if (!found) {
        if (known.empty()) {
          index = static_cast<std::uint32_t>(vh.idx());
        } else {
          index = static_cast<std::uint32_t>(raw.positions.size());
          add_copy_of(vh);
          source.push_back(static_cast<std::uint32_t>(vh.idx()));
        }
        raw.uvs[index] = uv;
        known.emplace_back(uv, index);
      }
      raw.face_indices.push_back(index);
    }
    raw.face_offsets.push_back(static_cast<std::uint32_t>(raw.face_indices.size()));
  }
  loaded.read_options += Options::VertexTexCoord;
  const std::size_t copies = raw.positions.size() - nv;
  if (copies == 0) {
    // No seam: the connectivity stands, only the UVs move to the vertices.
    for (auto vh : mesh.vertices()) {
      mesh.set_texcoord2D(vh, to_om(raw.uvs[static_cast<std::size_t>(vh.idx())]));
    }
    return 0;
  }
  // Rebuilt through the importer like every other mesh, so the split faces get the halfedges
  // add_face makes; the attributes the checks collected follow each vertex to its copies.
  LoadedMesh rebuilt;
  FileFacts rebuilt_facts;
  const std::vector<std::uint32_t> origin = build_mesh(raw, rebuilt, rebuilt_facts);
  const std::vector<char> given = facts.normal_given;
  const std::vector<glm::vec3> parsed_colors = facts.colors;
  facts.normal_given.assign(origin.size(), 0);
  if (facts.has_colors) facts.colors.assign(origin.size(), glm::vec3(0.0f));
  for (std::size_t j = 0; j < origin.size(); ++j) {
    const std::size_t from = source[origin[j]];
    if (from < given.size()) facts.normal_given[j] = given[from];
    if (facts.has_colors && from < parsed_colors.size()) facts.colors[j] = parsed_colors[from];
  }
  mesh = rebuilt.mesh;
  for (auto& w : rebuilt.warnings) loaded.warnings.push_back(std::move(w));
  return copies;
}

}  // namespace lt::meshio
