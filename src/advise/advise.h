// `ltrender advise`: for each material of a scene, the cheapest variant of the path that serves a
// target profile whose error against the reference stays within a budget the user names
// (docs/advise.md). Every candidate is rendered and compared by the evaluate step bench and
// export use (render/evaluate.h), costed on the work axis (Path::work, report/frame_work.h) and
// the texture bytes of its lobe, checked against the profile's budget (PathInfo::budget) and,
// before it is picked, on the hard cases the material can reach (hard_cases.h). Never timed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "advise/hard_cases.h"
#include "advise/storage_advice.h"
#include "advise/texture_advice.h"
#include "advise/variant_space.h"
#include "metrics/compare.h"
#include "scene/triangle_mesh.h"

namespace lt::advise {

// Which figure of a material's error the budget holds (metrics.md; covered pixels of the
// material, in 8-bit LSB).
enum class Stat { Max, P99, Mean };
const char* to_string(Stat s);
double stat_of(const ErrorStats& e, Stat s);

struct AdviseOptions {
  std::filesystem::path scene_file;
  std::string profile;
  double max_lsb = 1;
  Stat stat = Stat::Max;
  int width = 128, height = 0;  // 0: the scene's aspect at `width`
  // Evaluate every candidate of the grid: no pruning (the test's check of the pruned search).
  bool exhaustive = false;
  // > 0: for a material without a pick, refine its meshes where per-vertex evaluation errs most
  // (mesh_refinement.h) until the budget holds or the material has this many vertices.
  std::size_t max_vertices = 0;
};

// What a material costs with one candidate: the work axis (operations a frame executes for the
// material's covered pixels and drawn vertices), then the lobe's texture bytes. Compared in that
// order: a texture byte is cheaper than any operation a frame runs.
struct Cost {
  double ops = 0, texture_bytes = 0;
  auto operator<=>(const Cost&) const = default;
};

// One hard case rendered with a candidate.
struct HardResult {
  std::string scene;  // file stem
  size_t non_finite_pixels = 0;
  double max_lsb = 0;
};

struct CandidateResult {
  Candidate candidate;
  std::string refused;       // the path's refusal for the scene; not built
  std::string over_profile;  // the budget's first overrun; not rendered
  std::string pruned;        // why it was not rendered (empty when it was)
  bool rendered = false;
  std::vector<Cost> cost;         // per material (scene.materials order)
  std::vector<ErrorStats> error;  // per material, when rendered
  // Per material, when rendered: its pixels over 1 LSB as edge shifts and shading
  // (reference_edge_split.h), shown beside `error`.
  std::vector<EdgeShiftSplit> edge_split;
  std::vector<size_t> non_finite;                            // per material, when rendered
  std::vector<std::optional<std::vector<HardResult>>> hard;  // per material, once checked
  // For `material`: a choice (built, within the profile, rendered, finite on the scene and on
  // every hard case checked so far).
  bool admissible(size_t material) const;
  // The hard case that excludes it for `material` ("power_128: 12 non-finite pixels"), or "".
  std::string hard_failure(size_t material) const;
};

// One mesh density of a material's objects, rendered with the refinement's variant.
struct RefinementStep {
  std::size_t vertices = 0;   // of the material's objects
  ErrorStats error;           // the material's pixels
  EdgeShiftSplit edge_split;  // its pixels over 1 LSB classed (reference_edge_split.h)
  std::size_t non_finite = 0;
};

// Mesh density as a candidate (issue 29): the variant that came closest, on meshes refined
// where the per-vertex error is largest (adaptive), and for comparison split everywhere
// (uniform, 1 triangle to 4 a step), each until the budget holds or max_vertices.
struct Refinement {
  std::size_t candidate = 0;  // the variant, an index into Advice::candidates
  // Candidates whose adaptive refinement was tried first and stalled over the budget.
  std::vector<std::size_t> tried;
  std::vector<RefinementStep> adaptive, uniform;
  // The first adaptive step within the budget: the pick, its cost the vertices added.
  std::optional<std::size_t> holds_at;
  // The material's objects (index into scene.objects) and their meshes at the last adaptive
  // step (the one at holds_at when the budget holds): what `-o DIR` writes (refined_scene.h).
  std::vector<std::pair<std::size_t, TriangleMesh>> meshes;
  // The pick's step and its cost, the vertices it adds (holds_at must be set).
  const RefinementStep& pick_step() const { return adaptive[*holds_at]; }
  std::size_t vertices_added() const { return pick_step().vertices - adaptive.front().vertices; }
};

struct MaterialAdvice {
  size_t index = 0;  // in scene.materials: the index of cost, error, ... of a candidate
  std::string name;
  double pixels = 0, vertices = 0;
  bool translucent = false;
  std::vector<HardCase> hard_cases;      // reachable
  std::vector<size_t> front;             // Pareto front (cost, error): candidate indices, by cost
  std::optional<size_t> pick;            // the cheapest admissible candidate within the budget
  std::optional<size_t> closest;         // without a pick: the admissible one of least error
  std::optional<Refinement> refinement;  // with --max-vertices, for a material without a pick
  std::optional<StorageAdvice> storage;  // a console path's, for a material with a pick
  // A console path's texture formats, for a pick whose material samples a map or the LUT.
  std::optional<TextureAdvice> textures;
  // A pick, or a refined mesh within the budget.
  bool within_budget() const { return pick || (refinement && refinement->holds_at); }
};

struct Advice {
  AdviseOptions options;
  std::string path, default_variant;
  int width = 0, height = 0;
  std::vector<CandidateResult> candidates;  // the grid, the path's default first
  std::vector<std::string> left_out;        // axes not searched, with why
  std::vector<MaterialAdvice> materials;    // every material some object draws
  double seconds = 0;                       // what the search took (reported, never a cost)
  bool every_material_has_pick() const;
  size_t rendered() const;
};

// True when some material of `a` has a pick (the storage and texture steps start from one).
inline bool has_any_pick(const Advice& a) {
  for (const MaterialAdvice& ma : a.materials)
    if (ma.pick) return true;
  return false;
}

// Throws InputError for a bad scene, profile or budget (exit 2).
Advice run_advise(const AdviseOptions& options);

}  // namespace lt::advise
