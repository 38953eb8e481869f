#include "paths/arbfp/arb_budget.h"

#include <iomanip>
#include <set>
#include <sstream>

#include "arb/arb_ir_counter.h"
#include "core/error.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_passes.h"
#include "paths/path.h"

namespace lt::budget {

namespace {

// Materials some object draws with, in scene order (the paths build programs only for these).
std::vector<size_t> used_materials(const Scene& scene) {
  std::set<size_t> used;
  for (const SceneObject& o : scene.objects) used.insert(static_cast<size_t>(o.material));
  return {used.begin(), used.end()};
}

// The term's cost light by light: programs for the scene's first k lights, with and without the
// term; light k's share is the growth of that difference.
TermCost term_cost(const Scene& scene, const Material& mat, const arbfp::PowVariant& v) {
  TermCost tc;
  tc.material = mat.name;
  Scene partial = scene;
  const arbfp::MaterialSurfaces surfaces = arbfp::material_surfaces(scene, mat);
  TermCost::Cost previous;
  for (size_t k = 1; k <= scene.lights.size(); ++k) {
    partial.lights.assign(scene.lights.begin(), scene.lights.begin() + static_cast<long>(k));
    const ProgramCounts with =
        arbfp::ir::count(arbfp::generate_arb(partial, mat, v, surfaces, true).fragment_program);
    const ProgramCounts without =
        arbfp::ir::count(arbfp::generate_arb(partial, mat, v, surfaces, false).fragment_program);
    const TermCost::Cost diff{with.alu - without.alu, with.tex - without.tex};
    tc.per_light.push_back({diff.alu - previous.alu, diff.tex - previous.tex});
    previous = diff;
  }
  tc.total = previous;
  return tc;
}

Item program_item(const std::string& material, const std::string& name, const ProgramCounts& c,
                  const Profile& profile) {
  Item item;
  item.scope = Scope::Program;
  item.name = "material " + material + ": " + name;
  item.material = material;
  item.profile = profile.name;
  item.resources = program_resources(c, profile);
  return item;
}

Item term_item(const TermCost& t) {
  Item item;
  item.scope = Scope::Material;
  item.name = "material " + t.material + ": translucency term";
  item.material = t.material;
  item.resources = {{"alu", "ALU instructions", t.total.alu, {}, "", {}},
                    {"tex", "TEX instructions", t.total.tex, {}, "", {}}};
  for (size_t k = 0; k < t.per_light.size(); ++k) {
    const std::string n = std::to_string(k + 1);
    item.resources.push_back({"light_" + n + "_alu",
                              "light " + n + " ALU",
                              t.per_light[k].alu,
                              {},
                              k == 0 ? "the first light includes the view vector" : "",
                              {}});
    item.resources.push_back(
        {"light_" + n + "_tex", "light " + n + " TEX", t.per_light[k].tex, {}, "", {}});
  }
  std::ostringstream note;
  note << "the fragment program with the term minus without it";
  if (t.per_light.size() > 1) {
    note << "; further lights amortised " << std::setprecision(3) << t.further_light_alu()
         << " ALU each";
  }
  item.note = note.str();
  return item;
}

Item pass_item(const arbfp::Pass& p, const std::string& material) {
  const ProgramCounts &f = p.fragment_counts, &v = p.vertex_counts;
  Item item;
  item.scope = Scope::Pass;
  item.name = "material " + material + ": " + arbfp::describe(p);
  item.material = material;
  item.resources = {{"fragment_alu", "fragment ALU", f.alu, {}, "", {}},
                    {"fragment_tex", "fragment TEX", f.tex, {}, "", {}},
                    {"fragment_temporaries", "fragment temporaries", f.temporaries, {}, "", {}},
                    {"fragment_parameters", "fragment parameters", f.parameters, {}, "", {}},
                    {"vertex_alu", "vertex ALU", v.instructions(), {}, "", {}},
                    {"vertex_instruction_slots",
                     "vertex instruction slots",
                     v.instructions() + (v.position_invariant ? 4 : 0),
                     {},
                     "",
                     {}},
                    {"vertex_temporaries", "vertex temporaries", v.temporaries, {}, "", {}}};
  return item;
}

Item pass_bound_item(const arbfp::PassPlan& plan, const std::string& material) {
  Item item;
  item.scope = Scope::Material;
  item.name = "material " + material + ": passes";
  item.material = material;
  item.resources = {
      {"passes", "passes", static_cast<int>(plan.passes.size()), {}, "", {}},
      {"capacity_bound", "capacity bound", static_cast<int>(plan.lower_bound), {}, "", {}},
      {"most_lights_per_pass",
       "most lights per pass",
       static_cast<int>(plan.most_lights),
       {},
       "",
       {}}};
  item.note =
      "fewest passes searched over every mix of point and directional lights per pass "
      "(arb_pass_search.h); no pass tried fits more than the most lights per pass, so no plan "
      "has fewer passes than the capacity bound";
  return item;
}

// The passes `render --profile` draws (one per material when its programs fit); a note instead
// when some light does not fit even alone.
void add_pass_plan(const Scene& scene, const arbfp::PowVariant& v, const std::string& profile,
                   Report& r) {
  std::vector<Item> items;
  try {
    for (size_t m : used_materials(scene)) {
      const Material& mat = scene.materials[m];
      const arbfp::PassPlan plan = arbfp::plan_passes(scene, mat, v, profile);
      for (const arbfp::Pass& p : plan.passes) items.push_back(pass_item(p, mat.name));
      if (plan.passes.size() > 1) items.push_back(pass_bound_item(plan, mat.name));
    }
  } catch (const InputError& e) {
    r.notes.push_back("pass plan for render --profile " + profile + ": none: " + e.what());
    return;
  }
  r.notes.push_back("pass rows: the pass plan render --profile " + profile + " draws");
  r.items.insert(r.items.end(), items.begin(), items.end());
}

}  // namespace

double TermCost::further_light_alu() const {
  if (per_light.size() < 2) return 0;
  return static_cast<double>(total.alu - per_light.front().alu) /
         static_cast<double>(per_light.size() - 1);
}

std::vector<TermCost> term_costs(const Scene& scene, const std::string& variant) {
  const arbfp::PowVariant v = arbfp::parse_variant(variant);
  std::vector<TermCost> out;
  for (size_t m : used_materials(scene)) {
    const Material& mat = scene.materials[m];
    if (mat.translucency) out.push_back(term_cost(scene, mat, v));
  }
  return out;
}

Report run_budget(const Scene& scene, const std::string& variant, const std::string& profile) {
  const Profile& chosen = find_profile(profile.empty() ? "ps_2_0" : profile);
  const Profile& partner = find_profile(chosen.partner);
  const Profile& fragment = chosen.kind == ProgramKind::Fragment ? chosen : partner;
  const Profile& vertex = chosen.kind == ProgramKind::Vertex ? chosen : partner;
  Report r;
  r.file = scene.file.string();
  r.input = "scene";
  r.path = "arbfp";
  r.variant = resolve_variant(find_path("arbfp"), variant);
  r.profiles = {{fragment.name, "fragment programs", fragment.source},
                {vertex.name, "vertex programs", vertex.source}};
  const arbfp::PowVariant v = arbfp::parse_variant(r.variant);
  for (size_t m : used_materials(scene)) {
    const Material& mat = scene.materials[m];
    const arbfp::ArbPrograms p = arbfp::generate_arb(scene, mat, v);
    r.items.push_back(
        program_item(mat.name, "vertex program", arbfp::ir::count(p.vertex_program), vertex));
    r.items.push_back(
        program_item(mat.name, "fragment program", arbfp::ir::count(p.fragment_program), fragment));
  }
  for (const TermCost& t : term_costs(scene, r.variant)) r.items.push_back(term_item(t));
  add_pass_plan(scene, v, chosen.name, r);
  return r;
}

}  // namespace lt::budget
