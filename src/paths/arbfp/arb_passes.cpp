#include "paths/arbfp/arb_passes.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "arb/arb_ir_counter.h"
#include "core/error.h"
#include "paths/arbfp/arb_pass_search.h"

namespace lt::arbfp {

namespace {

// The pass's programs on `sub`, a copy of the scene whose lights and ambient light are set here.
Pass make_pass(Scene& sub, const Scene& scene, const Material& material,
               const MaterialSurfaces& surfaces, const PowVariant& variant,
               const std::vector<size_t>& lights, bool with_ambient) {
  Pass p;
  p.lights = lights;
  p.ambient = with_ambient && scene.ambient_light != glm::dvec3(0);
  sub.lights.clear();
  for (size_t i : lights) sub.lights.push_back(scene.lights[i]);
  sub.ambient_light = with_ambient ? scene.ambient_light : glm::dvec3(0);
  p.programs = generate_arb(sub, material, variant, surfaces, true, lights);
  p.vertex_counts = ir::count(p.programs.vertex_program);
  p.fragment_counts = ir::count(p.programs.fragment_program);
  return p;
}

// The first limit the pass goes over, "" when both programs fit.
std::string overrun(const Pass& p, const budget::Profile& fragment, const budget::Profile& vertex) {
  for (const auto& [counts, profile] :
       {std::pair{&p.fragment_counts, &fragment}, std::pair{&p.vertex_counts, &vertex}}) {
    const std::vector<budget::Overrun> over = budget::check(*counts, *profile);
    if (over.empty()) continue;
    const budget::Overrun& o = over.front();
    return std::string(counts->kind == budget::ProgramKind::Fragment ? "fragment" : "vertex") +
           " program: " + std::to_string(o.count) + " " + o.limit + " > " + std::to_string(o.max) +
           " (" + profile->name + ")";
  }
  return "";
}

// The scene's lights of one kind, in scene order.
std::vector<size_t> lights_of_kind(const Scene& scene, Light::Type type) {
  std::vector<size_t> out;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    if (scene.lights[i].type == type) out.push_back(i);
  }
  return out;
}

// The scene's lights a shape takes, in scene order.
std::vector<size_t> lights_of(const PassShape& shape, const std::vector<size_t>& points,
                              const std::vector<size_t>& directionals) {
  std::vector<size_t> out(points.begin() + static_cast<long>(shape.point),
                          points.begin() + static_cast<long>(shape.point + shape.points));
  out.insert(out.end(), directionals.begin() + static_cast<long>(shape.directional),
             directionals.begin() + static_cast<long>(shape.directional + shape.directionals));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

PassPlan plan_passes(const Scene& scene, const Material& material, const PowVariant& variant,
                     const std::string& profile) {
  PassPlan plan;
  plan.profile = profile;
  const size_t n = scene.lights.size();
  std::vector<size_t> all(n);
  for (size_t i = 0; i < n; ++i) all[i] = i;
  Scene sub = scene;
  // Scanned once for every pass shape the search tries: the sub-scenes share the objects.
  const MaterialSurfaces surfaces = material_surfaces(scene, material);
  if (profile.empty()) {
    plan.passes.push_back(make_pass(sub, scene, material, surfaces, variant, all, true));
    return plan;
  }
  const budget::Profile& chosen = budget::find_profile(profile);
  const budget::Profile& partner = budget::find_profile(chosen.partner);
  const budget::Profile& fragment = chosen.kind == budget::ProgramKind::Fragment ? chosen : partner;
  const budget::Profile& vertex = chosen.kind == budget::ProgramKind::Vertex ? chosen : partner;
  Pass whole = make_pass(sub, scene, material, surfaces, variant, all, true);
  if (overrun(whole, fragment, vertex).empty() || n == 0) {
    plan.passes.push_back(std::move(whole));
    return plan;
  }
  // A light that does not fit alone fits no pass (a program only grows with its lights).
  for (size_t i = 0; i < n; ++i) {
    const Pass alone = make_pass(sub, scene, material, surfaces, variant, {i}, i == 0);
    const std::string why = overrun(alone, fragment, vertex);
    if (why.empty()) continue;
    throw InputError(scene.file.string(), "--profile",
                     "material " + material.name + ": light " + std::to_string(i) +
                         " alone does not fit " + profile + " even in a pass of its own (" +
                         describe(alone) + ", " + why + "); no split into passes can fit");
  }
  const std::vector<size_t> points = lights_of_kind(scene, Light::Type::Point);
  const std::vector<size_t> directionals = lights_of_kind(scene, Light::Type::Directional);
  std::map<std::tuple<size_t, size_t, size_t, size_t, bool>, bool> fits_cache;
  const PassFits fits = [&](const PassShape& s, bool first) {
    const auto key = std::tuple(s.point, s.points, s.directional, s.directionals, first);
    const auto it = fits_cache.find(key);
    if (it != fits_cache.end()) return it->second;
    const Pass p = make_pass(sub, scene, material, surfaces, variant,
                             lights_of(s, points, directionals), first);
    return fits_cache[key] = overrun(p, fragment, vertex).empty();
  };
  const PassSearch search = fewest_passes(points.size(), directionals.size(), fits);
  LT_CHECK(!search.passes.empty(), "every light fits alone, so some plan fits");
  for (size_t k = 0; k < search.passes.size(); ++k) {
    plan.passes.push_back(make_pass(sub, scene, material, surfaces, variant,
                                    lights_of(search.passes[k], points, directionals), k == 0));
  }
  plan.most_lights = search.most_lights;
  plan.lower_bound = (n + search.most_lights - 1) / search.most_lights;
  return plan;
}

std::string describe(const Pass& p) {
  // Runs of consecutive numbers as "a-b".
  std::string runs;
  for (size_t i = 0; i < p.lights.size();) {
    size_t j = i;
    while (j + 1 < p.lights.size() && p.lights[j + 1] == p.lights[j] + 1) ++j;
    runs += (runs.empty() ? "" : ", ") + std::to_string(p.lights[i]) +
            (j > i ? "-" + std::to_string(p.lights[j]) : "");
    i = j + 1;
  }
  std::string s = p.lights.empty()       ? "no lights"
                  : p.lights.size() == 1 ? "light " + runs
                                         : "lights " + runs;
  return p.ambient ? s + " + ambient" : s;
}

}  // namespace lt::arbfp
