#include "advise/advise.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>

#include "advise/hard_cases.h"
#include "advise/material_error.h"
#include "advise/mesh_refinement.h"
#include "advise/target.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "load/load_scene.h"
#include "metrics/reference_edge_split.h"
#include "paths/common/gbuffer.h"
#include "render/evaluate.h"
#include "render/session.h"
#include "report/frame_work.h"

namespace lt::advise {

const char* to_string(Stat s) {
  switch (s) {
    case Stat::Max:
      return "max";
    case Stat::P99:
      return "p99";
    case Stat::Mean:
      return "mean";
  }
  return "max";
}

double stat_of(const ErrorStats& e, Stat s) {
  switch (s) {
    case Stat::Max:
      return e.max_lsb;
    case Stat::P99:
      return e.p99_lsb;
    case Stat::Mean:
      return e.mean_lsb;
  }
  return e.max_lsb;
}

bool CandidateResult::admissible(size_t m) const {
  return refused.empty() && over_profile.empty() && rendered && non_finite[m] == 0 &&
         hard_failure(m).empty();
}

std::string CandidateResult::hard_failure(size_t m) const {
  if (!hard[m]) return "";
  for (const HardResult& h : *hard[m]) {
    if (h.non_finite_pixels > 0)
      return h.scene + ": " + std::to_string(h.non_finite_pixels) + " non-finite pixels";
  }
  return "";
}

bool Advice::every_material_has_pick() const {
  return std::all_of(materials.begin(), materials.end(),
                     [](const MaterialAdvice& m) { return m.within_budget(); });
}

size_t Advice::rendered() const {
  return static_cast<size_t>(std::count_if(candidates.begin(), candidates.end(),
                                           [](const CandidateResult& c) { return c.rendered; }));
}

namespace {

// The frame's work for one material alone: the bench's frame_work over a model whose other
// materials cost nothing.
double material_ops(const WorkModel& model, const SceneCoverage& coverage, size_t m) {
  LT_CHECK(m < model.by_material.size(), "the path counts no work: " + model.not_counted);
  WorkModel one = model;
  for (size_t k = 0; k < one.by_material.size(); ++k) {
    if (k != m) one.by_material[k] = {};
  }
  return frame_work(one, coverage)->total();
}

// Renders candidates on the hard cases, at half each scene's size (enough for every case's
// geometry to be drawn), each reference rendered once.
class HardCaseRunner {
 public:
  HardCaseRunner(const PathInfo& path, const PathOptions& options)
      : path_(path), options_(options) {}

  HardResult run(const std::string& variant, const HardCase& hc) {
    const std::string key = variant + "|" + hc.file.string();
    if (auto it = results_.find(key); it != results_.end()) return it->second;
    Loaded& l = load(hc.file);
    HardResult r;
    r.scene = hc.file.stem().string();
    // A variant the path refuses for the case cannot meet it (render refuses it too).
    const bool refused = !path_.refusal(l.scene, variant).empty();
    if (!refused) {
      RenderSession session(l.scene, l.width, l.height);
      if (l.reference.rgba.empty()) l.reference = render_reference(session);
      auto p = session.build(path_, variant, options_);
      p->frame();
      const Comparison c = compare_with_reference(*p, l.reference);
      r.non_finite_pixels = c.test_non_finite_pixels;
      r.max_lsb = c.covered.max_lsb;
    }
    return results_[key] = r;
  }

 private:
  struct Loaded {
    Scene scene;
    int width = 0, height = 0;
    Image reference;
  };
  Loaded& load(const std::filesystem::path& file) {
    auto it = scenes_.find(file.string());
    if (it != scenes_.end()) return it->second;
    Loaded l;
    l.scene = load_scene(file);
    l.width = std::max(2, l.scene.width / 2);
    l.height = std::max(2, l.scene.height / 2);
    return scenes_.emplace(file.string(), std::move(l)).first->second;
  }

  const PathInfo& path_;
  PathOptions options_;
  std::map<std::string, Loaded> scenes_;
  std::map<std::string, HardResult> results_;
};

// Checks candidate `c` on every hard case material `m` reaches (once).
void check_hard_cases(CandidateResult& c, size_t m, const MaterialAdvice& ma,
                      HardCaseRunner& runner) {
  if (c.hard[m]) return;
  std::vector<HardResult> results;
  for (const HardCase& hc : ma.hard_cases) {
    results.push_back(runner.run(c.candidate.variant, hc));
    if (results.back().non_finite_pixels > 0) break;  // excluded: the rest cannot readmit it
  }
  c.hard[m] = std::move(results);
}

// The material's error with `variant` on `scene` (whose meshes a refinement changed): its own
// session, reference and material map, as the search measures a candidate.
RefinementStep measure_refined(const Scene& scene, const PathInfo& path, const std::string& variant,
                               const PathOptions& options, int width, int height, size_t m) {
  RefinementStep step;
  for (const SceneObject& o : scene.objects) {
    if (static_cast<size_t>(o.material) == m) step.vertices += o.mesh.positions.size();
  }
  RenderSession session(scene, width, height);
  const Image reference = render_reference(session);
  const std::vector<int> material_of_pixel = material_per_pixel(session.context());
  auto built = session.build(path, variant, options);
  built->frame();
  const Comparison c = compare_material(built->result(), reference, test_encoding(*built),
                                        material_of_pixel, static_cast<int>(m));
  step.error = c.covered;
  step.edge_split = reference_edge_split(c);
  step.non_finite = non_finite_pixels(c);
  return step;
}

// Refines material m's objects step by step, adaptively (edges whose midpoint error is over the
// budget) or uniformly (every edge), measuring each step, until the budget holds, max_vertices
// is passed or (adaptive) no edge is over the budget any more. With `meshes`, the material's
// objects as the last step left them.
std::vector<RefinementStep> refine_steps(
    const Scene& scene, const PathInfo& path, const std::string& variant,
    const PathOptions& options, const Advice& a, size_t m, bool uniform,
    std::vector<std::pair<std::size_t, TriangleMesh>>* meshes = nullptr) {
  Scene refined = scene;
  std::vector<RefinementStep> steps;
  steps.push_back(measure_refined(refined, path, variant, options, a.width, a.height, m));
  const AdviseOptions& o = a.options;
  std::vector<RefinementCache> caches(refined.objects.size());
  while (stat_of(steps.back().error, o.stat) > o.max_lsb &&
         steps.back().vertices < o.max_vertices) {
    std::size_t added = 0;
    for (size_t i = 0; i < refined.objects.size(); ++i) {
      if (static_cast<size_t>(refined.objects[i].material) == m)
        added += refine_object(refined, refined.objects[i], uniform ? -1.0 : o.max_lsb, &caches[i]);
    }
    if (added == 0) break;
    steps.push_back(measure_refined(refined, path, variant, options, a.width, a.height, m));
  }
  for (size_t i = 0; meshes && i < refined.objects.size(); ++i) {
    if (static_cast<size_t>(refined.objects[i].material) == m)
      meshes->emplace_back(i, std::move(refined.objects[i].mesh));
  }
  return steps;
}

// Pareto front of the rendered admissible candidates for material m: by cost, each strictly
// more accurate than every cheaper one.
std::vector<size_t> pareto_front(const std::vector<CandidateResult>& cs, size_t m, Stat stat) {
  std::vector<size_t> idx;
  for (size_t i = 0; i < cs.size(); ++i) {
    if (cs[i].admissible(m)) idx.push_back(i);
  }
  std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) {
    if (cs[a].cost[m] != cs[b].cost[m]) return cs[a].cost[m] < cs[b].cost[m];
    const double ea = stat_of(cs[a].error[m], stat), eb = stat_of(cs[b].error[m], stat);
    return ea != eb ? ea < eb : a < b;
  });
  std::vector<size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i : idx) {
    const double e = stat_of(cs[i].error[m], stat);
    if (e < best) {
      front.push_back(i);
      best = e;
    }
  }
  return front;
}

// True when candidate a is the better pick than b for material m: cheaper, or as cheap and
// earlier in the grid (the same rule whether the search was pruned or not).
bool cheaper(const std::vector<CandidateResult>& cs, size_t a, size_t b, size_t m) {
  return cs[a].cost[m] != cs[b].cost[m] ? cs[a].cost[m] < cs[b].cost[m] : a < b;
}

}  // namespace

Advice run_advise(const AdviseOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (!std::isfinite(o.max_lsb) || o.max_lsb < 0)
    throw InputError("--max-lsb", std::to_string(o.max_lsb),
                     "the budget must be a finite LSB >= 0");
  const Target target = find_target(o.profile);
  const PathInfo& path = *target.path;
  const Scene scene = load_scene(o.scene_file);
  Advice a;
  a.options = o;
  a.path = path.name;
  a.default_variant = path.variants.front().name;
  a.width = o.width;
  a.height = o.height > 0 ? o.height
                          : std::max(1, static_cast<int>(std::lround(static_cast<double>(o.width) *
                                                                     scene.height / scene.width)));
  check_image_size(a.width, a.height, o.scene_file.string(), "--width/--height");
  const VariantSpace space = variant_space(path, scene);
  a.left_out = space.left_out;
  const size_t nm = scene.materials.size();

  std::optional<RenderSession> session;
  session.emplace(scene, a.width, a.height);
  const Image reference = render_reference(*session);
  const std::vector<int> material_of_pixel = material_per_pixel(session->context());
  std::vector<double> pixels(nm, 0.0);
  for (int m : material_of_pixel) {
    if (m >= 0) pixels[static_cast<size_t>(m)] += 1;
  }
  const SceneCoverage coverage = scene_coverage(scene, pixels);

  // The materials that show: one answer each (a material no pixel shows has no error to hold).
  std::vector<size_t> shown;
  std::vector<int> advice_of(nm, -1);
  for (size_t m = 0; m < nm; ++m) {
    if (pixels[m] == 0) continue;
    MaterialAdvice ma;
    ma.index = m;
    ma.name = scene.materials[m].name;
    ma.pixels = pixels[m];
    ma.vertices = coverage.vertices[m];
    ma.translucent = scene.materials[m].translucency.has_value();
    ma.hard_cases = reachable_hard_cases(scene, scene.materials[m]);
    advice_of[m] = static_cast<int>(a.materials.size());
    a.materials.push_back(std::move(ma));
    shown.push_back(m);
  }
  if (shown.empty())
    throw InputError(o.scene_file.string(), "",
                     "no material covers a pixel at " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + ": nothing to advise on");

  // Every candidate built once for its cost and checked against the profile: both known before
  // anything is rendered, which is what lets the search skip what cannot be the cheapest.
  auto& cs = a.candidates;
  // The paths built for their cost, kept for their render while the scene's session lives.
  std::vector<std::unique_ptr<Path>> built(space.candidates.size());
  for (const Candidate& cand : space.candidates) {
    CandidateResult r;
    r.candidate = cand;
    r.cost.assign(nm, {});
    r.error.assign(nm, {});
    r.edge_split.assign(nm, {});
    r.non_finite.assign(nm, 0);
    r.hard.assign(nm, std::nullopt);
    r.refused = path.refusal(scene, cand.variant);
    // A twin that is never cheaper is pruned without a look (unless exhaustive).
    if (!o.exhaustive && !cand.never_cheaper.empty()) r.pruned = cand.never_cheaper;
    if (r.refused.empty() && r.pruned.empty()) {
      const budget::Report b = path.budget(scene, cand.variant, target.profile);
      if (!b.fits()) r.over_profile = b.first_overrun();
      built[cs.size()] = session->build(path, cand.variant, target.options);
      const WorkModel work = built[cs.size()]->work();
      for (size_t m : shown) {
        r.cost[m] = {material_ops(work, coverage, m),
                     scene.materials[m].translucency ? cand.texture_bytes : 0.0};
      }
    }
    cs.push_back(std::move(r));
  }

  // Rendered in order of the whole scene's cost, the default first (what the pick is measured
  // against): once every material has a pick, a candidate dearer than each pick cannot be the
  // cheapest within the budget for any material.
  std::vector<size_t> order(cs.size());
  std::iota(order.begin(), order.end(), 0);
  auto total = [&](size_t i) {
    Cost t;
    for (size_t m : shown) {
      t.ops += cs[i].cost[m].ops;
      t.texture_bytes += cs[i].cost[m].texture_bytes;
    }
    return t;
  };
  std::stable_sort(order.begin() + 1, order.end(),
                   [&](size_t x, size_t y) { return total(x) < total(y); });
  std::vector<std::optional<size_t>> pick(nm);
  HardCaseRunner runner(path, target.options);
  for (size_t i : order) {
    CandidateResult& c = cs[i];
    if (!c.refused.empty() || !c.over_profile.empty() || !c.pruned.empty()) continue;
    if (!o.exhaustive && i != 0) {
      const bool dearer_everywhere = std::all_of(shown.begin(), shown.end(), [&](size_t m) {
        return pick[m] && cs[*pick[m]].cost[m] < c.cost[m];
      });
      if (dearer_everywhere) {
        std::string picks;
        for (size_t m : shown)
          picks += (picks.empty() ? "" : ", ") + scene.materials[m].name + ": " +
                   cs[*pick[m]].candidate.variant;
        c.pruned = "costs more than every material's pick within the budget (" + picks + ")";
        continue;
      }
    }
    {
      if (!built[i]) built[i] = session->build(path, c.candidate.variant, target.options);
      built[i]->frame();
      const Image image = built[i]->result();
      for (size_t m : shown) {
        const Comparison cmp = compare_material(image, reference, test_encoding(*built[i]),
                                                material_of_pixel, static_cast<int>(m));
        c.error[m] = cmp.covered;
        c.edge_split[m] = reference_edge_split(cmp);
        c.non_finite[m] = non_finite_pixels(cmp);
      }
      c.rendered = true;
      built[i].reset();  // rendered once: its GL objects are not needed again
    }
    for (size_t m : shown) {
      if (!c.admissible(m) || stat_of(c.error[m], o.stat) > o.max_lsb) continue;
      if (pick[m] && !cheaper(cs, i, *pick[m], m)) continue;
      // A new pick for m, if it survives the hard cases m reaches; those need sessions of
      // their own, so the scene's is closed meanwhile (its reference and map are kept).
      // The paths built in it go with it (their GL objects are the session's).
      for (auto& b : built) b.reset();
      session.reset();
      check_hard_cases(c, m, a.materials[static_cast<size_t>(advice_of[m])], runner);
      session.emplace(scene, a.width, a.height);
      if (c.admissible(m)) pick[m] = i;
    }
  }
  for (auto& b : built) b.reset();
  session.reset();

  // The front and, without a pick, the closest candidate: every member checked on the hard
  // cases too, until the front holds only candidates that survive them.
  for (size_t m : shown) {
    MaterialAdvice& ma = a.materials[static_cast<size_t>(advice_of[m])];
    ma.pick = pick[m];
    for (;;) {
      ma.front = pareto_front(cs, m, o.stat);
      bool changed = false;
      for (size_t i : ma.front) {
        if (cs[i].hard[m]) continue;
        check_hard_cases(cs[i], m, ma, runner);
        changed = changed || !cs[i].admissible(m);
      }
      if (!changed) break;
    }
    if (!ma.pick) {
      // The most accurate survivor is the front's last member (the front is by cost, each
      // more accurate than the one before).
      if (!ma.front.empty()) ma.closest = ma.front.back();
    }
    if (!ma.pick && ma.closest && o.max_vertices > 0) {
      // The closest candidate first; when its refined mesh stalls over the budget (its own
      // error, a LUT's steps say, is over it once the silhouette is fixed), the other
      // admissible candidates, cheapest first, until one holds.
      std::vector<size_t> to_try = {*ma.closest};
      for (size_t i = 0; i < cs.size(); ++i) {
        if (i != *ma.closest && cs[i].rendered && cs[i].admissible(m)) to_try.push_back(i);
      }
      std::stable_sort(to_try.begin() + 1, to_try.end(),
                       [&](size_t x, size_t y) { return cheaper(cs, x, y, m); });
      Refinement r;
      for (size_t i : to_try) {
        if (cs[i].hard[m] == std::nullopt) check_hard_cases(cs[i], m, ma, runner);
        if (!cs[i].admissible(m)) continue;
        if (r.adaptive.size() > 0) r.tried.push_back(r.candidate);
        r.candidate = i;
        r.meshes.clear();
        r.adaptive = refine_steps(scene, path, cs[i].candidate.variant, target.options, a, m, false,
                                  &r.meshes);
        for (size_t k = 0; k < r.adaptive.size(); ++k) {
          if (r.adaptive[k].non_finite == 0 && stat_of(r.adaptive[k].error, o.stat) <= o.max_lsb) {
            r.holds_at = k;
            break;
          }
        }
        if (r.holds_at) break;
      }
      r.uniform =
          refine_steps(scene, path, cs[r.candidate].candidate.variant, target.options, a, m, true);
      ma.refinement = std::move(r);
    }
  }
  add_storage_advice(a, scene, path, target.options, target.profile);
  add_texture_advice(a, scene, path, target.options, target.profile);
  a.seconds = seconds_since(start);
  return a;
}

}  // namespace lt::advise
