#include "mesh/mesh_builder.h"

#include "core/error.h"
#include "mesh/normals.h"

namespace lt::meshgen {

PolyMesh to_mesh(const Geometry& g) {
  LT_CHECK(g.uvs.empty() || g.uvs.size() == g.positions.size(), "one UV per generated vertex");
  PolyMesh mesh;
  mesh.reserve(g.positions.size(), 3 * g.positions.size(), g.triangles.size());
  for (std::size_t i = 0; i < g.positions.size(); ++i) {
    const auto& p = g.positions[i];
    auto vh = mesh.add_vertex(PolyMesh::Point(p.x, p.y, p.z));
    mesh.set_color(vh, PolyMesh::Color(0.0f, 0.0f, 0.0f));
    if (!g.uvs.empty()) mesh.set_texcoord2D(vh, to_om(g.uvs[i]));
  }
  for (const auto& t : g.triangles) {
    mesh.add_face(OpenMesh::VertexHandle(t[0]), OpenMesh::VertexHandle(t[1]),
                  OpenMesh::VertexHandle(t[2]));
  }
  LT_CHECK(mesh.n_faces() == g.triangles.size(), "generated mesh is not manifold");
  compute_normals(mesh);
  for (auto vh : mesh.vertices()) {
    const auto& n = g.normals[static_cast<std::size_t>(vh.idx())];
    mesh.set_normal(vh, PolyMesh::Normal(n.x, n.y, n.z));
  }
  return mesh;
}

void add_quad(Geometry& g, int a, int b, int c, int d) {
  g.triangles.push_back({a, b, c});
  g.triangles.push_back({a, c, d});
}

}  // namespace lt::meshgen
