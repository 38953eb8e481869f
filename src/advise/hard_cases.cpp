#include "advise/hard_cases.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/run_time_files.h"

namespace lt::advise {

namespace {

struct Rule {
  const char* name;  // scenes/hard/<name>.json
  const char* reached_by;
  std::function<bool(const Scene&, const Translucency*)> reaches;
};

bool has_point_light(const Scene& s) {
  return std::any_of(s.lights.begin(), s.lights.end(),
                     [](const Light& l) { return l.type == Light::Type::Point; });
}

// A thickness that can be 0 or 1 somewhere: per vertex or from a map (any value of [0, 1]), or a
// constant with a channel at 0 or at 1 and over.
bool thickness_reaches_ends(const Translucency& t) {
  if (t.thickness_source != ThicknessSource::Constant) return true;
  const glm::dvec3 v = t.thickness * t.tint;
  return std::min({v.x, v.y, v.z}) <= 0 || std::max({v.x, v.y, v.z}) >= 1;
}

// model.md "Hard cases every path must survive", one rule per scene of scenes/hard/.
const std::vector<Rule>& rules() {
  static const std::vector<Rule> r = {
      {"coordinates_1e-6", "any mesh (coordinates near 1e-6)", [](auto&, auto) { return true; }},
      {"coordinates_1e6", "any mesh (coordinates near 1e6)", [](auto&, auto) { return true; }},
      {"degenerate_triangles", "any mesh (degenerate triangles)", [](auto&, auto) { return true; }},
      {"nonunit_normals", "any mesh (non-unit normals)", [](auto&, auto) { return true; }},
      {"zero_normals", "any mesh (zero-length normals)", [](auto&, auto) { return true; }},
      {"light_inside_mesh", "a point light (inside the mesh)",
       [](const Scene& s, auto) { return has_point_light(s); }},
      {"point_light_at_vertex", "a point light (at a vertex)",
       [](const Scene& s, auto) { return has_point_light(s); }},
      {"saturating_scale", "a light with scale x colour over 1 (HDR sums)",
       [](const Scene& s, auto) {
         return std::any_of(s.lights.begin(), s.lights.end(), [](const Light& l) {
           return l.translucency_scale * std::max({l.color.x, l.color.y, l.color.z}) > 1;
         });
       }},
      {"zero_pow_zero", "p = 0 (0^0 at t = 0)",
       [](auto&, const Translucency* t) { return t && t->power == 0; }},
      {"power_fractional", "a fractional p",
       [](auto&, const Translucency* t) { return t && t->power != std::floor(t->power); }},
      {"power_128", "p >= 128 (underflow)",
       [](auto&, const Translucency* t) { return t && t->power >= 128; }},
      {"power_1024", "p >= 1024 (underflow)",
       [](auto&, const Translucency* t) { return t && t->power >= 1024; }},
      {"distortion_large", "|d| > 1 (|H| > 1)",
       [](auto&, const Translucency* t) { return t && std::abs(t->distortion) > 1; }},
      {"distortion_negative", "d < 0",
       [](auto&, const Translucency* t) { return t && t->distortion < 0; }},
      {"thickness_zero_and_one", "a thickness that reaches 0 or 1",
       [](auto&, const Translucency* t) { return t && thickness_reaches_ends(*t); }},
  };
  return r;
}

}  // namespace

std::vector<HardCase> reachable_hard_cases(const Scene& scene, const Material& material) {
  const Translucency* t = material.translucency ? &*material.translucency : nullptr;
  std::vector<HardCase> out;
  for (const Rule& r : rules()) {
    if (r.reaches(scene, t)) {
      out.push_back(
          {lt::run_time_files::data_dir() / "scenes" / "hard" / (std::string(r.name) + ".json"),
           r.reached_by});
    }
  }
  return out;
}

}  // namespace lt::advise
