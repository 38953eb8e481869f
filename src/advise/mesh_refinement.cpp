#include "advise/mesh_refinement.h"

#include <algorithm>
#include <map>
#include <utility>

#include "model/translucency.h"

namespace lt::advise {

namespace {

glm::dvec3 display(const glm::dvec3& c) {
  return glm::clamp(c, glm::dvec3(0), glm::dvec3(1));
}

// The colour the reference shades at a point of the object with normal n and vertex colour.
glm::dvec3 shade_at(const Scene& scene, const Material& material, const glm::dvec3& p,
                    const glm::dvec3& n, const glm::dvec3& colour, const glm::dvec2& uv) {
  model::SurfacePoint sp;
  sp.P = p;
  sp.N = n;
  sp.V = model::view_vector(scene.camera, p - scene.camera.eye);
  sp.vertex_thickness = colour;
  sp.uv = uv;
  return display(model::shade(scene, material, sp));
}

// Vertex attributes at the midpoint of a-b: the averages (normal renormalised by shade).
struct Midpoint {
  glm::dvec3 p, n, colour{1, 1, 1};
  glm::dvec2 uv{0, 0};
};
Midpoint midpoint(const TriangleMesh& m, unsigned a, unsigned b) {
  Midpoint v;
  v.p = (m.positions[a] + m.positions[b]) * 0.5;
  v.n = m.normals[a] + m.normals[b];
  const double len = glm::length(v.n);
  v.n = len > 0 ? v.n / len : glm::dvec3(0);
  if (m.has_colors()) v.colour = (m.colors[a] + m.colors[b]) * 0.5;
  if (!m.uvs.empty()) v.uv = (m.uvs[a] + m.uvs[b]) * 0.5;
  return v;
}

std::pair<unsigned, unsigned> edge_key(unsigned a, unsigned b) {
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

double edge_midpoint_error_lsb(const Scene& scene, const SceneObject& object, unsigned a,
                               unsigned b) {
  const TriangleMesh& m = object.mesh;
  const Material& material = scene.materials[static_cast<size_t>(object.material)];
  auto at = [&](unsigned i) {
    return shade_at(scene, material, m.positions[i], m.normals[i],
                    m.has_colors() ? m.colors[i] : glm::dvec3(1),
                    m.uvs.empty() ? glm::dvec2(0) : m.uvs[i]);
  };
  const Midpoint v = midpoint(m, a, b);
  const glm::dvec3 exact = shade_at(scene, material, v.p, v.n, v.colour, v.uv);
  const glm::dvec3 d = glm::abs(exact - (at(a) + at(b)) * 0.5) * 255.0;
  return std::max({d.x, d.y, d.z});
}

std::size_t refine_object(const Scene& scene, SceneObject& object, double max_lsb) {
  TriangleMesh& m = object.mesh;
  // The midpoint vertex of every edge to split, shared by the edge's triangles.
  std::map<std::pair<unsigned, unsigned>, unsigned> split;
  const std::size_t before = m.positions.size();
  for (const glm::uvec3& t : m.triangles) {
    for (int e = 0; e < 3; ++e) {
      const unsigned a = t[e], b = t[(e + 1) % 3];
      const auto key = edge_key(a, b);
      if (split.count(key)) continue;
      if (max_lsb >= 0 && edge_midpoint_error_lsb(scene, object, a, b) <= max_lsb) continue;
      const Midpoint v = midpoint(m, a, b);
      split[key] = static_cast<unsigned>(m.positions.size());
      m.positions.push_back(v.p);
      m.normals.push_back(v.n);
      if (m.has_colors()) m.colors.push_back(v.colour);
      if (!m.uvs.empty()) m.uvs.push_back(v.uv);
    }
  }
  if (split.empty()) return 0;
  std::vector<glm::uvec3> out;
  out.reserve(m.triangles.size() * 2);
  for (const glm::uvec3& t : m.triangles) {
    unsigned mid[3];
    int count = 0, first = -1;
    for (int e = 0; e < 3; ++e) {
      const auto it = split.find(edge_key(t[e], t[(e + 1) % 3]));
      mid[e] = it == split.end() ? ~0u : it->second;
      if (it != split.end()) {
        ++count;
        if (first < 0) first = e;
      }
    }
    // Rotate so the corners read v0 v1 v2 with edge e between v_e and v_(e+1), winding kept.
    if (count == 0) {
      out.push_back(t);
    } else if (count == 3) {
      out.push_back({t[0], mid[0], mid[2]});
      out.push_back({mid[0], t[1], mid[1]});
      out.push_back({mid[2], mid[1], t[2]});
      out.push_back({mid[0], mid[1], mid[2]});
    } else if (count == 1) {
      const int e = first;
      const unsigned a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3], p = mid[e];
      out.push_back({a, p, c});
      out.push_back({p, b, c});
    } else {
      // Two split edges: the unsplit one is e; its opposite corner c joins both midpoints.
      int e = 0;
      while (mid[e] != ~0u) ++e;
      const unsigned a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
      const unsigned pb = mid[(e + 1) % 3], pc = mid[(e + 2) % 3];  // on b-c and on c-a
      out.push_back({pc, pb, c});
      out.push_back({a, b, pb});
      out.push_back({a, pb, pc});
    }
  }
  m.triangles = std::move(out);
  return m.positions.size() - before;
}

}  // namespace lt::advise
