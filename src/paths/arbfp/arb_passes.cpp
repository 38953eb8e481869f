#include "paths/arbfp/arb_passes.h"

#include "core/error.h"
#include "paths/arbfp/arb_ir_counter.h"

namespace lt::arbfp {

namespace {

// The pass's programs on `sub`, a copy of the scene whose lights and ambient light are set here.
Pass make_pass(Scene& sub, const Scene& scene, const Material& material, const PowVariant& variant,
               size_t first, size_t count) {
  Pass p;
  p.first = first;
  p.count = count;
  p.ambient = first == 0 && scene.ambient_light != glm::dvec3(0);
  sub.lights.assign(scene.lights.begin() + static_cast<long>(first),
                    scene.lights.begin() + static_cast<long>(first + count));
  sub.ambient_light = first == 0 ? scene.ambient_light : glm::dvec3(0);
  p.programs = generate_arb(sub, material, variant, true, first);
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

}  // namespace

PassPlan plan_passes(const Scene& scene, const Material& material, const PowVariant& variant,
                     const std::string& profile) {
  PassPlan plan;
  plan.profile = profile;
  const size_t n = scene.lights.size();
  Scene sub = scene;
  if (profile.empty()) {
    plan.passes.push_back(make_pass(sub, scene, material, variant, 0, n));
    return plan;
  }
  const budget::Profile& chosen = budget::find_profile(profile);
  const budget::Profile& partner = budget::find_profile(chosen.partner);
  const budget::Profile& fragment = chosen.kind == budget::ProgramKind::Fragment ? chosen : partner;
  const budget::Profile& vertex = chosen.kind == budget::ProgramKind::Vertex ? chosen : partner;
  Pass whole = make_pass(sub, scene, material, variant, 0, n);
  if (overrun(whole, fragment, vertex).empty() || n == 0) {
    plan.passes.push_back(std::move(whole));
    return plan;
  }
  for (size_t first = 0; first < n;) {
    Pass best = make_pass(sub, scene, material, variant, first, 1);
    const std::string why = overrun(best, fragment, vertex);
    if (!why.empty()) {
      throw InputError(scene.file.string(), "--profile",
                       "material " + material.name + ": light " + std::to_string(first) +
                           " alone does not fit " + profile + " even in a pass of its own (" +
                           describe(best) + ", " + why + "); no split into passes can fit");
    }
    for (size_t count = 2; first + count <= n; ++count) {
      Pass more = make_pass(sub, scene, material, variant, first, count);
      if (!overrun(more, fragment, vertex).empty()) break;
      best = std::move(more);
    }
    first += best.count;
    plan.passes.push_back(std::move(best));
  }
  return plan;
}

std::string describe(const Pass& p) {
  std::string s;
  if (p.count == 1) {
    s = "light " + std::to_string(p.first);
  } else if (p.count > 1) {
    s = "lights " + std::to_string(p.first) + "-" + std::to_string(p.first + p.count - 1);
  } else {
    s = "no lights";
  }
  return p.ambient ? s + " + ambient" : s;
}

}  // namespace lt::arbfp
