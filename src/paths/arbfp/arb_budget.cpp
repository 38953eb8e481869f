#include "paths/arbfp/arb_budget.h"

#include <iomanip>
#include <set>
#include <sstream>

#include "core/error.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_ir_counter.h"
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

void add_arbfp(const Scene& scene, const std::string& variant, BudgetReport& r) {
  const arbfp::PowVariant v = arbfp::parse_variant(variant);
  for (size_t m : used_materials(scene)) {
    const Material& mat = scene.materials[m];
    const arbfp::ArbPrograms p = arbfp::generate_arb(scene, mat, v);
    const std::string name = "material " + mat.name;
    r.programs.push_back({name + ": vertex program",
                          arbfp::ir::count(p.vertex_program),
                          r.vertex_profile->name,
                          {}});
    r.programs.push_back({name + ": fragment program",
                          arbfp::ir::count(p.fragment_program),
                          r.fragment_profile->name,
                          {}});
    if (!mat.translucency) continue;
    // The term's cost light by light: programs for the scene's first k lights, with and
    // without the term; light k's share is the growth of that difference.
    TermCost tc;
    tc.material = mat.name;
    Scene partial = scene;
    TermCost::Cost previous;
    for (size_t k = 1; k <= scene.lights.size(); ++k) {
      partial.lights.assign(scene.lights.begin(), scene.lights.begin() + static_cast<long>(k));
      const ProgramCounts with =
          arbfp::ir::count(arbfp::generate_arb(partial, mat, v, true).fragment_program);
      const ProgramCounts without =
          arbfp::ir::count(arbfp::generate_arb(partial, mat, v, false).fragment_program);
      const TermCost::Cost diff{with.alu - without.alu, with.tex - without.tex};
      tc.per_light.push_back({diff.alu - previous.alu, diff.tex - previous.tex});
      previous = diff;
    }
    tc.total = previous;
    r.term_costs.push_back(tc);
  }
}

void add_pass_plan(const Scene& scene, const std::string& variant, const std::string& profile,
                   BudgetReport& r) {
  const arbfp::PowVariant v = arbfp::parse_variant(variant);
  try {
    for (size_t m : used_materials(scene)) {
      const Material& mat = scene.materials[m];
      const arbfp::PassPlan plan = arbfp::plan_passes(scene, mat, v, profile);
      for (const arbfp::Pass& p : plan.passes) {
        r.pass_plan.push_back({mat.name, arbfp::describe(p), p.vertex_counts, p.fragment_counts});
      }
      if (plan.passes.size() > 1) {
        r.pass_lower_bounds.push_back({mat.name, plan.lower_bound, plan.most_lights});
      }
    }
  } catch (const InputError& e) {
    r.pass_plan.clear();
    r.pass_plan_error = e.what();
  }
}

}  // namespace

double TermCost::further_light_alu() const {
  if (per_light.size() < 2) return 0;
  return static_cast<double>(total.alu - per_light.front().alu) /
         static_cast<double>(per_light.size() - 1);
}

bool BudgetReport::fits() const {
  return first_overrun().empty();
}

std::string BudgetReport::first_overrun() const {
  for (const CountedProgram& p : programs) {
    if (p.over.empty()) continue;
    const Overrun& o = p.over.front();
    return p.name + ": " + std::to_string(o.count) + " " + o.limit + " > " + std::to_string(o.max) +
           " (" + p.profile + ")";
  }
  return "";
}

BudgetReport run_budget(const Scene& scene, const std::string& path, const std::string& variant,
                        const std::string& profile) {
  const PathInfo& info = find_path(path);  // unknown path: InputError listing the paths
  BudgetReport r;
  r.scene = scene.file.string();
  r.path = info.name;
  const Profile& chosen = find_profile(profile);
  const Profile& partner = find_profile(chosen.partner);
  r.fragment_profile = chosen.kind == ProgramKind::Fragment ? &chosen : &partner;
  r.vertex_profile = chosen.kind == ProgramKind::Vertex ? &chosen : &partner;
  // Programs with instructions: arbfp. (combiners counts stages: paths/combiners/combiner_budget.h,
  // dispatched by the budget command.)
  if (info.name != "arbfp") {
    throw InputError("--path", path,
                     "path " + info.name + " has no budget (arbfp: programs, combiners: stages)");
  }
  r.variant = resolve_variant(info, variant);
  add_arbfp(scene, r.variant, r);
  add_pass_plan(scene, r.variant, chosen.name, r);
  for (CountedProgram& p : r.programs) {
    const Profile& prof =
        p.counts.kind == ProgramKind::Fragment ? *r.fragment_profile : *r.vertex_profile;
    p.profile = prof.name;
    p.over = check(p.counts, prof);
  }
  return r;
}

namespace {
std::string limit(int count, int max) {
  std::string s = std::to_string(count);
  if (max >= 0) s.append("/").append(std::to_string(max));
  if (max >= 0 && count > max) s.append("!");
  return s;
}
}  // namespace

std::string format_table(const BudgetReport& r) {
  std::ostringstream s;
  s << "budget: " << r.scene << ", path " << r.path << " (" << r.variant << "), profiles "
    << r.fragment_profile->name << " (fragment) + " << r.vertex_profile->name << " (vertex)\n"
    << "  " << r.fragment_profile->source << "\n  " << r.vertex_profile->source << "\n"
    << "count/limit, ! = over; vertex slots include the 4 DP4 of ARB_position_invariant\n\n";
  s << std::left << std::setw(44) << "program" << std::setw(9) << "ALU" << std::setw(8) << "TEX"
    << std::setw(9) << "slots" << std::setw(8) << "temps" << std::setw(9) << "params"
    << std::setw(9) << "attribs" << std::setw(8) << "indir"
    << "status\n";
  for (const CountedProgram& p : r.programs) {
    const Profile& pr =
        p.counts.kind == ProgramKind::Fragment ? *r.fragment_profile : *r.vertex_profile;
    const ProgramCounts& c = p.counts;
    s << std::setw(44) << p.name << std::setw(9) << limit(c.alu, pr.alu) << std::setw(8)
      << limit(c.tex, pr.tex) << std::setw(9)
      << limit(c.instructions() + (c.position_invariant ? 4 : 0), pr.instructions) << std::setw(8)
      << limit(c.temporaries, pr.temporaries) << std::setw(9) << limit(c.parameters, pr.parameters)
      << std::setw(9) << limit(c.attributes, pr.attributes) << std::setw(8)
      << (c.kind == ProgramKind::Fragment ? limit(c.indirections, pr.indirections) : "-");
    if (p.over.empty()) {
      s << "fits " << p.profile;
    } else {
      s << "OVER " << p.profile << ":";
      for (const Overrun& o : p.over)
        s << " " << o.limit << " " << o.count << " > " << o.max << ";";
    }
    s << "\n";
  }
  if (!r.term_costs.empty()) {
    s << "\ntranslucency term's own cost (fragment program with the term minus without it):\n";
    for (const TermCost& t : r.term_costs) {
      s << "  material " << t.material << ": total " << t.total.alu << " ALU + " << t.total.tex
        << " TEX;";
      for (size_t k = 0; k < t.per_light.size(); ++k) {
        s << (k == 0 ? " first light (incl. view vector) "
                     : ", light " + std::to_string(k + 1) + " ")
          << t.per_light[k].alu << " ALU + " << t.per_light[k].tex << " TEX";
      }
      if (t.per_light.size() > 1) {
        s << "; further lights amortised " << std::setprecision(3) << t.further_light_alu()
          << " ALU each";
      }
      s << "\n";
    }
  }
  s << "\npass plan for render --profile " << r.fragment_profile->name << ":";
  if (!r.pass_plan_error.empty()) s << " none: " << r.pass_plan_error;
  s << "\n";
  for (const PlannedPass& p : r.pass_plan) {
    s << "  material " << p.material << ": " << p.lights << ": fragment " << p.fragment.alu
      << " ALU + " << p.fragment.tex << " TEX, " << p.fragment.temporaries << " temps, "
      << p.fragment.parameters << " params; vertex " << p.vertex.instructions() << " ALU\n";
  }
  for (const BudgetReport::PassBound& b : r.pass_lower_bounds) {
    s << "  material " << b.material << ": fewest passes searched over every mix of point and "
      << "directional lights per pass (arb_pass_search.h); no pass tried fits more than "
      << b.most_lights << " lights: capacity bound >= " << b.lower_bound << " passes\n";
  }
  s << "\n" << (r.fits() ? "fits" : "OVER BUDGET: " + r.first_overrun()) << "\n";
  return s.str();
}

nlohmann::json to_json(const BudgetReport& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["path"] = r.path;
  j["variant"] = r.variant;
  j["fragment_profile"] = r.fragment_profile->name;
  j["vertex_profile"] = r.vertex_profile->name;
  j["fits"] = r.fits();
  j["programs"] = nlohmann::json::array();
  for (const CountedProgram& p : r.programs) {
    const ProgramCounts& c = p.counts;
    nlohmann::json over = nlohmann::json::array();
    for (const Overrun& o : p.over)
      over.push_back({{"limit", o.limit}, {"count", o.count}, {"max", o.max}});
    j["programs"].push_back(
        {{"name", p.name},
         {"kind", to_string(c.kind)},
         {"profile", p.profile},
         {"alu", c.alu},
         {"tex", c.tex},
         {"instruction_slots", c.instructions() + (c.position_invariant ? 4 : 0)},
         {"temporaries", c.temporaries},
         {"parameters", c.parameters},
         {"attributes", c.attributes},
         {"indirections", c.indirections},
         {"over", over}});
  }
  j["term_cost"] = nlohmann::json::array();
  for (const TermCost& t : r.term_costs) {
    nlohmann::json per = nlohmann::json::array();
    for (const TermCost::Cost& c : t.per_light) per.push_back({{"alu", c.alu}, {"tex", c.tex}});
    j["term_cost"].push_back({{"material", t.material},
                              {"total", {{"alu", t.total.alu}, {"tex", t.total.tex}}},
                              {"per_light", per},
                              {"further_light_alu", t.further_light_alu()}});
  }
  j["passes"] = nlohmann::json::array();
  for (const PlannedPass& p : r.pass_plan) {
    j["passes"].push_back(
        {{"material", p.material},
         {"lights", p.lights},
         {"fragment",
          {{"alu", p.fragment.alu},
           {"tex", p.fragment.tex},
           {"temporaries", p.fragment.temporaries},
           {"parameters", p.fragment.parameters}}},
         {"vertex",
          {{"instruction_slots", p.vertex.instructions() + (p.vertex.position_invariant ? 4 : 0)},
           {"temporaries", p.vertex.temporaries}}}});
  }
  if (!r.pass_plan_error.empty()) j["passes_error"] = r.pass_plan_error;
  j["pass_bounds"] = nlohmann::json::array();
  for (const BudgetReport::PassBound& b : r.pass_lower_bounds) {
    j["pass_bounds"].push_back(
        {{"material", b.material}, {"lower_bound", b.lower_bound}, {"most_lights", b.most_lights}});
  }
  return j;
}

}  // namespace lt::budget
