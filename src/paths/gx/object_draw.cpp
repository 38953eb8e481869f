#include "paths/gx/object_draw.h"

#include "mesh/triangle_strips.h"

namespace lt::gx {

bool draws_strip(GxVariant::Draw draw) {
  return draw == GxVariant::Draw::Strips || draw == GxVariant::Draw::List;
}

bool draws_indexed(GxVariant::Draw draw) {
  return draw != GxVariant::Draw::Direct;
}

std::vector<u32> sent_vertex_order(const TriangleMesh& mesh, GxVariant::Draw draw) {
  std::vector<u32> list;
  list.reserve(3 * mesh.triangles.size());
  for (const glm::uvec3& tri : mesh.triangles) list.insert(list.end(), {tri.x, tri.y, tri.z});
  if (!draws_strip(draw)) return list;
  return triangle_strip(list, mesh.positions.size());
}

std::vector<glm::uvec3> setup_order(const TriangleMesh& mesh, GxVariant::Draw draw) {
  if (!draws_strip(draw)) return mesh.triangles;
  std::vector<glm::uvec3> out;
  for (const auto& t : strip_triangles(sent_vertex_order(mesh, draw)))
    out.emplace_back(t[0], t[1], t[2]);
  return out;
}

}  // namespace lt::gx
