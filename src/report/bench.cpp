#include "report/bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/error.h"
#include "core/file_name.h"
#include "core/fs.h"
#include "core/stopwatch.h"
#include "metrics/heatmap.h"
#include "metrics/reference_edge_split.h"
#include "paths/common/gbuffer.h"
#include "render/evaluate.h"
#include "render/session.h"
#include "report/bench_progress.h"
#include "report/ground_truth_image.h"

namespace lt {

namespace {

// --profile goes to the paths that take one (arbfp splits into passes); the others run as ever.
PathOptions profile_options(const PathInfo& p, const BenchOptions& o) {
  PathOptions out;
  if (p.takes_profile) out.profile = o.profile;
  return out;
}

// Each figure a path reports, over the timed frames.
using StatSamples = std::array<std::vector<double>, FrameStats::kFields.size()>;

// One frame in milliseconds: it is over when the GL work is, not when the calls return.
double timed_frame(Path& path) {
  const auto t0 = SteadyClock::now();
  path.frame();
  glFinish();
  return std::chrono::duration<double, std::milli>(SteadyClock::now() - t0).count();
}

void collect_stats(const Path& path, StatSamples& stats) {
  const FrameStats st = path.frame_stats();
  for (size_t k = 0; k < FrameStats::kFields.size(); ++k) {
    const auto field = FrameStats::kFields[k].second;
    if (st.*field) stats[k].push_back(*(st.*field));
  }
}

// One round's share of the bench's measuring options: the minimums and the maximum time split
// over the rounds (at least --frames pairs and --min-time in all), the target judged on every
// round's pairs so far.
InterleaveOptions round_options(const BenchOptions& o, const std::vector<double>& earlier) {
  InterleaveOptions io;
  io.min_pairs = (o.frames + o.rounds - 1) / o.rounds;
  io.min_seconds = o.min_time_s / o.rounds;
  io.max_seconds = o.max_time_s / o.rounds;
  io.target_half_width = o.target_interval;
  io.min_warmup = o.warmup;
  io.earlier_ratios = earlier;
  return io;
}

FrameTiming time_frames(Path& path, const BenchOptions& o) {
  for (int i = 0; i < o.warmup; ++i) timed_frame(path);
  std::vector<double> ms;
  for (int i = 0; i < o.frames; ++i) ms.push_back(timed_frame(path));
  return summarize_frames(ms);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string scene_name(const fs::path& p) {
  return p.stem().string();
}

// One row a scene will have: a path and one of its variants (listed or added).
struct PlannedRow {
  const PathInfo* path;
  std::string variant;
};

// The rows of a scene: each selected variant of each path asked for, then each added one,
// except those the scene refuses (noted with the reason).
std::vector<PlannedRow> plan_rows(const Scene& scene, const std::string& sname,
                                  const std::vector<const PathInfo*>& paths, const BenchOptions& o,
                                  BenchProgress& progress) {
  std::vector<PlannedRow> candidates;
  for (const PathInfo* p : paths) {
    for (const VariantInfo& v : p->variants)
      if (selected(*p, v, o.variants)) candidates.push_back({p, v.name});
  }
  for (const AddedVariant& a : o.added_variants)
    candidates.push_back({&find_path(a.path), a.variant});
  std::vector<PlannedRow> planned;
  for (PlannedRow& row : candidates) {
    // A variant that cannot be exact for this scene (gx t=texgen under perspective) is no row:
    // render would refuse it too.
    const std::string why = row.path->refusal(scene, row.variant);
    if (!why.empty()) {
      progress.note("bench: " + sname + ": " + row.path->name + " " + row.variant +
                    " skipped: " + why);
      continue;
    }
    planned.push_back(std::move(row));
  }
  return planned;
}

// Whether `paths` (--paths; empty: every path) asks for `path`.
bool path_asked(const std::vector<std::string>& paths, const std::string& path) {
  return paths.empty() || std::find(paths.begin(), paths.end(), path) != paths.end();
}

// Pass 2 of run_bench, at 1280x720: timing only, each path in interleaved pairs with flat in the
// same session (report/interleaved_timing.h), so every ratio is the median of per-pair ratios.
// A figure is timed in rounds (round 1 of every row of every scene, then round 2, ...), each in
// a session of its own (context, framebuffer, flat and the path built afresh): its pairs sample
// the machine at times spread over the whole bench, and the placement of its objects and
// framebuffer in memory more than once. A state that holds for a whole measurement is then one
// round of several, outvoted in the median. Measured (docs/bench.md "How far the ratios repeat"):
// one of eight processes glsl on coloured_cubes read 6.0 times flat instead of 3.0-3.4, its
// interval +-2%; with the rounds inside one scene's minute, one run's thin_vs_thick CPU rows sat
// 8-14% below another run's, every interval within +-5%.
void time_at_wide_size(const std::vector<Scene>& scenes,
                       std::vector<std::vector<BenchRow>>& rows_by_scene, const PathInfo& flat,
                       const BenchOptions& o, BenchProgress& progress) {
  struct RowTiming {
    std::vector<double> ratios, path_ms;
    StatSamples stats;
    std::size_t settling_frames = 0;
    int rounds = 0;
  };
  struct SceneTiming {
    std::vector<RowTiming> rows;
    std::vector<double> flat_ms;  // every timed flat frame of the scene, over the rounds
    int rounds = 0;               // rounds with timed flat frames
    std::optional<SceneCoverage> coverage;
  };
  std::vector<SceneTiming> timing(scenes.size());
  for (std::size_t si = 0; si < scenes.size(); ++si)
    timing[si].rows.resize(rows_by_scene[si].size());
  std::size_t timed_rows = 0;
  for (const auto& scene_rows : rows_by_scene) {
    timed_rows += static_cast<std::size_t>(
        std::count_if(scene_rows.begin(), scene_rows.end(),
                      [&](const BenchRow& r) { return r.path != flat.name; }));
  }
  progress.start_phase(
      "timing at " + std::to_string(o.wide_width) + "x" + std::to_string(o.wide_height),
      timed_rows * static_cast<std::size_t>(o.rounds));
  for (int round = 0; round < o.rounds; ++round) {
    for (std::size_t si = 0; si < scenes.size(); ++si) {
      const Scene& scene = scenes[si];
      SceneTiming& st = timing[si];
      std::vector<BenchRow>& scene_rows = rows_by_scene[si];
      RenderSession session(scene, o.wide_width, o.wide_height);
      if (!st.coverage)
        st.coverage = scene_coverage(scene, covered_pixels_by_material(session.context()));
      auto count_work = [&](BenchRow& row, const Path& path) {
        const WorkModel model = path.work();
        row.work = frame_work(model, *st.coverage);
        row.work_not_counted = model.not_counted;
      };
      auto base = session.build(flat, flat.variants.front().name);
      bool timed_any = false;
      for (std::size_t i = 0; i < scene_rows.size(); ++i) {
        BenchRow& row = scene_rows[i];
        if (row.path == flat.name) {
          if (round == 0) count_work(row, *base);
          continue;
        }
        timed_any = true;
        progress.step("round " + std::to_string(round + 1) + " of " + std::to_string(o.rounds) +
                      ", " + row.scene + ", " + row.path + " " + row.variant);
        const PathInfo& p = find_path(row.path);
        auto path = session.build(p, row.variant, profile_options(p, o));
        if (round == 0) count_work(row, *path);
        RowTiming& rt = st.rows[i];
        const InterleavedTiming t = time_interleaved(
            [&](bool timed) {
              const double ms = timed_frame(*path);
              if (timed) collect_stats(*path, rt.stats);
              return ms;
            },
            [&] { return timed_frame(*base); }, round_options(o, rt.ratios));
        rt.ratios.insert(rt.ratios.end(), t.pair_ratios.begin(), t.pair_ratios.end());
        rt.path_ms.insert(rt.path_ms.end(), t.path_ms.begin(), t.path_ms.end());
        rt.settling_frames += t.settling_frames;
        ++rt.rounds;
        st.flat_ms.insert(st.flat_ms.end(), t.baseline_ms.begin(), t.baseline_ms.end());
      }
      // flat alone (the only path asked for): its own frames, in the first round.
      if (!timed_any && round == 0) {
        for (int i = 0; i < std::max(o.frames, 10); ++i) st.flat_ms.push_back(timed_frame(*base));
      }
      if (timed_any || round == 0) ++st.rounds;
    }
  }
  for (std::size_t si = 0; si < scenes.size(); ++si) {
    for (std::size_t i = 0; i < rows_by_scene[si].size(); ++i) {
      BenchRow& row = rows_by_scene[si][i];
      const RowTiming& rt = timing[si].rows[i];
      if (row.path == flat.name) {
        // Its frames from every pair of the scene, and a ratio of 1 by definition.
        row.at_wide = summarize_frames(timing[si].flat_ms);
        row.ratio = estimate_ratio(std::vector<double>(timing[si].flat_ms.size(), 1.0));
        row.ratio_to_flat = 1.0;
        row.rounds = timing[si].rounds;
        continue;
      }
      row.at_wide = summarize_frames(rt.path_ms);
      row.ratio = estimate_ratio(rt.ratios);
      row.ratio_to_flat = row.ratio.median;
      row.settling_frames = rt.settling_frames;
      row.rounds = rt.rounds;
      // Every figure a path reports, as the median over the timed frames.
      for (size_t k = 0; k < rt.stats.size(); ++k) {
        if (!rt.stats[k].empty()) row.stats.*(FrameStats::kFields[k].second) = median(rt.stats[k]);
      }
      if (row.stats.shading_seconds && row.stats.covered_pixels) {
        const double secs = *row.stats.shading_seconds;
        row.shading_mpixels_per_s = secs > 0 ? *row.stats.covered_pixels / secs / 1e6 : 0;
      }
    }
  }
}

}  // namespace

const char* to_string(TimingMode mode) {
  return mode == TimingMode::Quick ? "quick" : "precise";
}

void set_timing_mode(BenchOptions& o, TimingMode mode) {
  const BenchOptions precise;
  o.timing_mode = mode;
  o.rounds = precise.rounds;
  o.min_time_s = precise.min_time_s;
  o.target_interval = precise.target_interval;
  o.max_time_s = precise.max_time_s;
  if (mode == TimingMode::Quick) {
    // One session a figure and a quarter second of the path (at least --frames pairs, which a
    // CPU path's 100 ms frames exceed anyway), no time beyond it for the interval: a ratio to
    // within a few percent, enough to tell two variants apart, in seconds a row.
    o.rounds = 1;
    o.min_time_s = 0.25;
    o.max_time_s = o.min_time_s;
  }
}

const std::map<std::string, VariantSelection>& variant_selections() {
  static const std::map<std::string, VariantSelection> names = {
      {"all", VariantSelection::All},
      {"default", VariantSelection::Defaults},
      {"story", VariantSelection::Story}};
  return names;
}

bool selected(const PathInfo& path, const VariantInfo& variant, VariantSelection selection) {
  if (selection == VariantSelection::All || variant.name == path.variants.front().name) return true;
  return selection == VariantSelection::Story && variant.run == VariantRun::Story;
}

FrameTiming summarize_frames(std::vector<double> frame_ms) {
  FrameTiming t;
  if (frame_ms.empty()) return t;
  t.min_ms = *std::min_element(frame_ms.begin(), frame_ms.end());
  t.median_ms = median(std::move(frame_ms));
  return t;
}

AddedVariant parse_added_variant(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    throw InputError("--add-variant", text, "give PATH:VARIANT, e.g. gx:t=vertex:draw=list");
  const std::string path = text.substr(0, colon), variant = text.substr(colon + 1);
  try {
    const PathInfo& p = find_path(path);
    return {p.name, p.parse_variant(variant)};
  } catch (const InputError& e) {
    // The path's own words, under this option's name (they name --path or --variant).
    throw InputError("--add-variant", text, e.what_only());
  }
}

std::vector<Scene> load_bench_inputs(const BenchOptions& o) {
  for (const std::string& name : o.paths) find_path(name);  // unknown names are input errors
  // An added variant that is a row already would be measured twice under one name (and one
  // image file): refused, as is the same one added twice.
  for (std::size_t i = 0; i < o.added_variants.size(); ++i) {
    const AddedVariant& a = o.added_variants[i];
    const std::string given = a.path + ":" + a.variant;
    for (std::size_t j = 0; j < i; ++j) {
      if (o.added_variants[j].path == a.path && o.added_variants[j].variant == a.variant)
        throw InputError("--add-variant", given, "given twice");
    }
    const PathInfo& p = find_path(a.path);
    if (!path_asked(o.paths, p.name)) continue;
    for (const VariantInfo& v : p.variants) {
      if (v.name == a.variant && selected(p, v, o.variants))
        throw InputError("--add-variant", given,
                         "a row already: --variants selects this listed variant of " + p.name);
    }
  }
  std::vector<Scene> scenes;
  for (const fs::path& scene_path : o.scenes)
    scenes.push_back(load_scene(scene_path, o.scene_options));
  return scenes;
}

std::vector<BenchRow> run_bench(const BenchOptions& o) {
  std::vector<const PathInfo*> paths;
  for (const PathInfo& p : all_paths()) {
    if (path_asked(o.paths, p.name)) paths.push_back(&p);
  }
  // The baseline is always measured, whatever --paths says: every ratio needs it.
  const PathInfo& flat = path_with_role(PathRole::Baseline);

  // Every scene is read before anything is written: a bad one is reported with nothing created.
  const std::vector<Scene> scenes = load_bench_inputs(o);
  std::error_code ec;
  fs::create_directories(o.out_dir / "images", ec);
  if (ec)
    throw InputError(o.out_dir.string(), "", "cannot create output directory: " + ec.message());
  BenchProgress progress(o.live_progress && !o.quiet, !o.quiet);
  std::vector<std::vector<PlannedRow>> planned;
  std::size_t planned_rows = 0;
  for (size_t si = 0; si < scenes.size(); ++si) {
    planned.push_back(plan_rows(scenes[si], scene_name(o.scenes[si]), paths, o, progress));
    planned_rows += planned.back().size();
  }
  progress.start_phase("renders at each scene's size", planned_rows);
  std::vector<std::vector<BenchRow>> rows_by_scene;
  for (size_t si = 0; si < scenes.size(); ++si) {
    const fs::path& scene_path = o.scenes[si];
    const Scene& scene = scenes[si];
    const std::string sname = scene_name(scene_path);

    // Pass 1, at the scene's size: the reference image, every path's image, error, timing.
    // Pass 2, the timing at 1280x720, follows for every scene at once (time_at_wide_size).
    std::vector<BenchRow> scene_rows;
    Image ref_image;
    {
      RenderSession session(scene, scene.width, scene.height);
      ref_image = render_reference(session);
      write_image(o.out_dir / ground_truth_image(sname, ".exr"), ref_image);
      // The same at 8 bits, for the report page (a browser shows no EXR): what each card flips to.
      write_image(o.out_dir / ground_truth_image(sname, ".png"), ref_image);
      for (const auto& [p, v] : planned[si]) {
        progress.step(sname + ", " + p->name + " " + v);
        BenchRow row;
        row.scene = sname;
        row.path = p->name;
        row.variant = v;
        auto path = session.build(*p, v, profile_options(*p, o));
        row.at_scene_size = time_frames(*path, o);
        row.cost = path->cost();
        if (p->writes_fifo_log)
          row.console = console_bytes(p->budget(scene, v, profile_options(*p, o).profile));
        const Image img = path->result();
        const std::string base = sname + "__" + file_name_safe(p->name + "_" + v);
        row.image = "images/" + base + ".png";
        row.width = img.width;
        row.height = img.height;
        write_image(o.out_dir / row.image, img);
        if (p->name != flat.name) {
          const Comparison cmp = compare_images(img, ref_image, test_encoding(*path),
                                                TestEncoding::kFloat, Coverage::kBoth);
          row.error = cmp.covered;
          row.edge_split = reference_edge_split(cmp);
          row.heatmap = "images/" + base + "__heatmap.png";
          write_image(o.out_dir / row.heatmap, error_heatmap(cmp));
        }
        scene_rows.push_back(std::move(row));
      }
    }
    rows_by_scene.push_back(std::move(scene_rows));
  }
  time_at_wide_size(scenes, rows_by_scene, flat, o, progress);
  std::vector<BenchRow> rows;
  for (auto& scene_rows : rows_by_scene) {
    rows.insert(rows.end(), scene_rows.begin(), scene_rows.end());
  }
  return rows;
}

}  // namespace lt
