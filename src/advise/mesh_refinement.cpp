#include "advise/mesh_refinement.h"

#include <algorithm>
#include <unordered_set>
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

// An edge whichever way a triangle walks it: the lower index in the high half.
std::uint64_t edge_key(unsigned a, unsigned b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// The reference's colour at vertex i of the object.
glm::dvec3 vertex_shade(const Scene& scene, const Material& material, const TriangleMesh& m,
                        unsigned i) {
  return shade_at(scene, material, m.positions[i], m.normals[i],
                  m.has_colors() ? m.colors[i] : glm::dvec3(1),
                  m.uvs.empty() ? glm::dvec2(0) : m.uvs[i]);
}

// edge_midpoint_error_lsb with the ends' colours given.
double midpoint_error(const Scene& scene, const Material& material, const TriangleMesh& m,
                      unsigned a, unsigned b, const glm::dvec3& at_a, const glm::dvec3& at_b) {
  const Midpoint v = midpoint(m, a, b);
  const glm::dvec3 exact = shade_at(scene, material, v.p, v.n, v.colour, v.uv);
  const glm::dvec3 d = glm::abs(exact - (at_a + at_b) * 0.5) * 255.0;
  return std::max({d.x, d.y, d.z});
}

}  // namespace

double edge_midpoint_error_lsb(const Scene& scene, const SceneObject& object, unsigned a,
                               unsigned b) {
  const TriangleMesh& m = object.mesh;
  const Material& material = scene.materials[static_cast<size_t>(object.material)];
  return midpoint_error(scene, material, m, a, b, vertex_shade(scene, material, m, a),
                        vertex_shade(scene, material, m, b));
}

std::size_t refine_object(const Scene& scene, SceneObject& object, double max_lsb,
                          RefinementCache* cache) {
  TriangleMesh& m = object.mesh;
  const Material& material = scene.materials[static_cast<size_t>(object.material)];
  RefinementCache local;
  RefinementCache& known = cache ? *cache : local;
  known.vertex_colour.resize(m.positions.size());
  auto colour = [&](unsigned i) -> const glm::dvec3& {
    if (!known.vertex_colour[i]) known.vertex_colour[i] = vertex_shade(scene, material, m, i);
    return *known.vertex_colour[i];
  };
  // The error of edge a-b, estimated once for the whole refinement.
  auto error = [&](unsigned a, unsigned b) {
    const std::uint64_t key = edge_key(a, b);
    const auto it = known.edge_error.find(key);
    if (it != known.edge_error.end()) return it->second;
    const double e = midpoint_error(scene, material, m, a, b, colour(a), colour(b));
    known.edge_error.emplace(key, e);
    return e;
  };
  // The edges to split: those over the budget, then, until none is left, the longest edge of
  // every triangle that has an edge to split (longest-edge bisection [Rivara 1984, "Algorithms
  // for refining triangular grids suitable for adaptive and multigrid techniques"]). Without
  // that closure a triangle with one split edge gains an edge from its midpoint to the opposite
  // corner as long as the old ones, and a fan of such edges never gets shorter: on baked_blob
  // through gx the refinement went on adding 4 vertices a step, thousands of steps, without the
  // estimate falling under the budget.
  auto length2 = [&](unsigned a, unsigned b) {
    const glm::dvec3 d = m.positions[a] - m.positions[b];
    return glm::dot(d, d);
  };
  // The edge of t that is longest (the lower key on a tie, so the choice is the same from
  // either triangle of the edge).
  auto longest = [&](const glm::uvec3& t) {
    int best = 0;
    for (int e = 1; e < 3; ++e) {
      const double l = length2(t[e], t[(e + 1) % 3]), lb = length2(t[best], t[(best + 1) % 3]);
      if (l > lb ||
          (l == lb && edge_key(t[e], t[(e + 1) % 3]) < edge_key(t[best], t[(best + 1) % 3])))
        best = e;
    }
    return best;
  };
  std::unordered_set<std::uint64_t> marked;
  for (const glm::uvec3& t : m.triangles) {
    for (int e = 0; e < 3; ++e) {
      const unsigned a = t[e], b = t[(e + 1) % 3];
      if (max_lsb < 0 || error(a, b) > max_lsb) marked.insert(edge_key(a, b));
    }
  }
  for (bool grew = !marked.empty(); grew;) {
    grew = false;
    for (const glm::uvec3& t : m.triangles) {
      bool any = false;
      for (int e = 0; e < 3; ++e) any = any || marked.count(edge_key(t[e], t[(e + 1) % 3])) > 0;
      const int l = longest(t);
      if (any) grew = marked.insert(edge_key(t[l], t[(l + 1) % 3])).second || grew;
    }
  }
  // The midpoint vertex of every marked edge, shared by the edge's triangles.
  std::unordered_map<std::uint64_t, unsigned> split;
  const std::size_t before = m.positions.size();
  for (const glm::uvec3& t : m.triangles) {
    for (int e = 0; e < 3; ++e) {
      const unsigned a = t[e], b = t[(e + 1) % 3];
      const auto key = edge_key(a, b);
      if (split.count(key) || !marked.count(key)) continue;
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
      // Two split edges, one of them the longest (the closure): the unsplit one is e, a-b. The
      // longest edge's midpoint joins the corner opposite it and the other midpoint.
      int e = 0;
      while (mid[e] != ~0u) ++e;
      const unsigned a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
      const unsigned pb = mid[(e + 1) % 3], pc = mid[(e + 2) % 3];  // on b-c and on c-a
      if (longest(t) == (e + 1) % 3) {                              // b-c: pb joins a
        out.push_back({pc, pb, c});
        out.push_back({a, b, pb});
        out.push_back({a, pb, pc});
      } else {  // c-a: pc joins b
        out.push_back({a, b, pc});
        out.push_back({b, pb, pc});
        out.push_back({pb, c, pc});
      }
    }
  }
  m.triangles = std::move(out);
  return m.positions.size() - before;
}

}  // namespace lt::advise
