// The bench's plumbing (not its speed: timing lives in `ltrender bench`): every path and variant
// gets a row, flat is the baseline of its own ratio, the reference agrees with itself, and every
// report file is written.
#include "report/bench.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "advise_error_check.h"
#include "core/error.h"
#include "core/fixed.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

// quad.json (48x32, one backlit quad) and its mesh in `dir`.
void write_quad_scene(const fs::path& dir) {
  test::write_file(dir / "quad.obj", test::quad_obj());
  test::write_file(dir / "quad.json", R"({
    "image": {"width": 48, "height": 32},
    "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40},
    "materials": {"m": {"albedo": [0.8, 0.8, 0.8],
                        "translucency": {"power": 4, "distortion": 0.2, "thickness": 0.5}}},
    "lights": [{"type": "directional", "direction": [0.3, 0, 1], "translucency_scale": 2}],
    "objects": [{"mesh": "quad.obj", "material": "m"}]})");
}

TEST(Bench, SummarizeFramesTakesMedianAndMin) {
  const FrameTiming odd = summarize_frames({5, 1, 3});
  EXPECT_EQ(odd.median_ms, 3);
  EXPECT_EQ(odd.min_ms, 1);
  const FrameTiming even = summarize_frames({4, 1, 3, 10});
  EXPECT_EQ(even.median_ms, 3.5);
}

// A bench of quad.json in `dir` into dir/out that checks rows, not figures: the fewest frames,
// the pair count deciding the time (no minimum, no more for the interval), a small wide size.
BenchOptions rows_only_options(const fs::path& dir) {
  BenchOptions o;
  o.scenes = {dir / "quad.json"};
  o.out_dir = dir / "out";
  o.frames = 10;
  o.warmup = 1;
  o.min_time_s = 0;
  o.max_time_s = 0;
  o.wide_width = 64;
  o.wide_height = 36;
  o.quiet = true;
  return o;
}

TEST(Bench, WritesOneRowPerPathVariantAndEveryReport) {
  test::TempDir dir;
  write_quad_scene(dir.path());
  const BenchOptions o = rows_only_options(dir.path());
  const auto rows = run_bench(o);
  // One row per variant the scene allows (gx refuses t=texgen and lobe=xf-spec under a
  // perspective camera: render would refuse them too).
  const Scene scene = load_scene(dir / "quad.json");
  size_t expected = 0, refused = 0;
  for (const PathInfo& p : all_paths()) {
    for (const VariantInfo& v : p.variants) {
      const bool no = !p.refusal(scene, v.name).empty();
      (no ? refused : expected) += 1;
    }
  }
  EXPECT_EQ(refused, 2u);
  ASSERT_EQ(rows.size(), expected);
  for (const BenchRow& r : rows) {
    EXPECT_GT(r.at_scene_size.median_ms, 0) << r.path;
    EXPECT_LE(r.at_scene_size.min_ms, r.at_scene_size.median_ms);
    EXPECT_GT(r.ratio_to_flat, 0);
    // Interleaved pairs: at least --frames of them, the median inside its interval.
    EXPECT_GE(r.ratio.pairs, static_cast<std::size_t>(o.frames)) << r.path;
    EXPECT_LE(r.ratio.low, r.ratio.median) << r.path;
    EXPECT_LE(r.ratio.median, r.ratio.high) << r.path;
    EXPECT_EQ(r.ratio.median, r.ratio_to_flat) << r.path;
    if (r.path == "flat") {
      EXPECT_EQ(r.ratio_to_flat, 1.0);
      EXPECT_FALSE(r.error);
    } else {
      ASSERT_TRUE(r.error) << r.path;
    }
    if (r.path == "reference") {
      EXPECT_EQ(r.error->max_lsb, 0.0);  // float against itself, unquantised
      EXPECT_GT(r.shading_mpixels_per_s.value(), 0);
    }
    EXPECT_TRUE(fs::exists(o.out_dir / r.image)) << r.image;
  }
  write_bench_reports(o, rows);
  for (const char* f : {"report.md", "report.csv", "report.json", "chart.svg", "chart_work.svg",
                        "contact.png", "index.html"}) {
    EXPECT_TRUE(fs::exists(o.out_dir / f)) << f;
  }
  std::ifstream in(o.out_dir / "report.json");
  const auto j = nlohmann::json::parse(in);
  ASSERT_EQ(j["rows"].size(), expected);
  // The writers say what was measured: every row in the table, the CSV and the JSON, and each
  // path's own figures under their names.
  const auto slurp = [&](const char* f) {
    std::ifstream s(o.out_dir / f);
    return std::string(std::istreambuf_iterator<char>(s), {});
  };
  const std::string md = slurp("report.md"), csv = slurp("report.csv");
  // The report page has one card per row, each flipping with the scene's 8-bit reference.
  const std::string html = slurp("index.html");
  size_t cards = 0;
  for (size_t p = 0; (p = html.find("<article class=\"card\"", p)) != std::string::npos; ++p)
    ++cards;
  EXPECT_EQ(cards, expected);
  EXPECT_TRUE(fs::exists(o.out_dir / "images" / "quad__reference.png"));
  EXPECT_NE(html.find("<figure class=\"chart\"><svg"), std::string::npos);
  // A path has one colour in both charts, though the work chart lacks glsl's points (arbfp,
  // after glsl, took glsl's colour there). The legend entry is "<text ... fill='#rrggbb'>N  path".
  const auto colour_of = [](const std::string& svg, const std::string& path) {
    const size_t at = svg.find("  " + path + " ");
    const size_t fill = at == std::string::npos ? at : svg.rfind("fill='#", at);
    return fill == std::string::npos ? std::string("none") : svg.substr(fill + 6, 7);
  };
  const std::string speed = slurp("chart.svg"), work = slurp("chart_work.svg");
  ASSERT_EQ(work.find("  glsl "), std::string::npos);  // the case the colours must survive
  for (const std::string path : {"reference", "arbfp", "combiners", "half", "gx"}) {
    EXPECT_NE(colour_of(speed, path), "none") << path;
    EXPECT_EQ(colour_of(speed, path), colour_of(work, path)) << path;
  }
  EXPECT_NE(colour_of(speed, "glsl"), colour_of(speed, "arbfp"));
  EXPECT_EQ(static_cast<size_t>(std::count(csv.begin(), csv.end(), '\n')), expected + 1);
  // Scripts read the CSV by column: the old columns keep their order, new ones come last.
  EXPECT_EQ(csv.rfind("scene,path,variant,ms_median,ms_min,ms_median_wide,ms_min_wide,"
                      "ratio_to_flat,",
                      0),
            0u);
  EXPECT_NE(csv.find(",cost,ratio_low,ratio_high,ratio_pairs,work_ops,work_pixel_ops,"
                     "work_vertex_ops,settling_frames,edge_shift_pixels,shading_pixels,"
                     "shading_max_lsb,"),
            std::string::npos);
  for (size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& r = rows[i];
    EXPECT_NE(md.find("| quad | " + r.path + " | " + r.variant + " | "), std::string::npos)
        << r.path << " " << r.variant;
    EXPECT_NE(csv.find("quad," + r.path + "," + r.variant + ","), std::string::npos);
    EXPECT_EQ(j["rows"][i]["path"], r.path);
    EXPECT_DOUBLE_EQ(j["rows"][i]["ratio_interval"]["low"].get<double>(), r.ratio.low);
    EXPECT_DOUBLE_EQ(j["rows"][i]["ratio_interval"]["high"].get<double>(), r.ratio.high);
    EXPECT_EQ(j["rows"][i]["ratio_interval"]["pairs"].get<std::size_t>(), r.ratio.pairs);
    EXPECT_EQ(j["rows"][i]["ratio_interval"]["settling_frames"].get<std::size_t>(),
              r.settling_frames);
    for (const auto& [name, value] : r.stats.set_fields()) {
      EXPECT_DOUBLE_EQ(j["rows"][i]["stats"][name].get<double>(), value) << r.path << " " << name;
    }
    if (r.path == "gx") {
      EXPECT_GT(r.stats.tev_stage_pixels.value(), 0);
      EXPECT_NE(md.find("M stage-pixels"), std::string::npos);
    }
    if (r.path == "reference") EXPECT_GT(j["rows"][i]["stats"]["shading_mpixels_per_s"], 0);
    // The error's pixels over 1 LSB, classed: edge shifts and shading add up to the share
    // `% > 1 LSB` counts (figured apart, by the error's own statistics); with no edge shift the
    // shading max is the max. The JSON carries the three, the page shows them on each card.
    if (r.error) {
      ASSERT_TRUE(r.edge_split) << r.path;
      const auto& e = j["rows"][i]["error"];
      const std::size_t edge = e.at("edge_shift_pixels"), shading = e.at("shading_pixels");
      EXPECT_EQ(edge, r.edge_split->edge_shift_pixels);
      EXPECT_NEAR(static_cast<double>(edge + shading),
                  r.error->percent_over_1_lsb * static_cast<double>(r.error->pixels) / 100.0, 1e-6)
          << r.path << " " << r.variant;
      EXPECT_LE(e.at("shading_max_lsb").get<double>(), r.error->max_lsb);
      if (edge == 0) EXPECT_EQ(e.at("shading_max_lsb").get<double>(), r.error->max_lsb);
      EXPECT_NE(html.find("<dt>shading max</dt><dd>" + fixed(r.edge_split->shading_max_lsb, 2) +
                          " LSB</dd><dt>edge "
                          "shifts</dt><dd>" +
                          std::to_string(edge) + " px &gt; 1 LSB</dd>"),
                std::string::npos)
          << r.path << " " << r.variant;
    } else {
      EXPECT_FALSE(j["rows"][i].contains("error"));
    }
    // The work axis: every path that counts has a figure (GLSL says why it has none); where a
    // path also counts as it draws (gx, the CPU paths' covered pixels), the two agree.
    if (r.path == "glsl") {
      EXPECT_FALSE(r.work) << r.path;
      EXPECT_FALSE(j["rows"][i]["work"]["not_counted"].get<std::string>().empty());
      continue;
    }
    ASSERT_TRUE(r.work) << r.path << " " << r.variant;
    EXPECT_GT(r.work->pixel_ops, 0) << r.path;
    EXPECT_DOUBLE_EQ(j["rows"][i]["work"]["ops"].get<double>(), r.work->total());
    if (r.path == "gx") {
      EXPECT_EQ(r.work->pixel_ops, r.stats.tev_stage_pixels.value()) << r.variant;
      EXPECT_EQ(r.work->vertex_ops, r.stats.xf_light_vertices.value()) << r.variant;
    }
    // One light: one evaluation a covered pixel (the CPU paths count those pixels as they shade);
    // flat writes one colour a covered pixel.
    const auto reference = std::find_if(rows.begin(), rows.end(),
                                        [](const BenchRow& x) { return x.path == "reference"; });
    ASSERT_NE(reference, rows.end());
    if (r.path == "reference" || r.path == "half" || r.path == "flat")
      EXPECT_EQ(r.work->pixel_ops, reference->stats.covered_pixels.value()) << r.path;
  }
  EXPECT_NE(md.find("work (M ops)"), std::string::npos);

  // The console's figures: a gx row carries what `ltrender budget --path gx --variant V` counts
  // for the scene (the budget's own command, run apart), for two variants that send different
  // attributes; the other paths carry none. The page and chart_console.svg plot FIFO bytes.
  EXPECT_NE(csv.find(",shading_max_lsb,console_vertex_bytes,console_fifo_bytes,"),
            std::string::npos);
  size_t checked = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& row = j["rows"][i];
    if (rows[i].path != "gx") {
      EXPECT_FALSE(row.contains("console")) << rows[i].path;
      continue;
    }
    ASSERT_TRUE(row.contains("console")) << rows[i].variant;
    if (rows[i].variant != "t=vertex" && rows[i].variant != "t=texgen:view=object") continue;
    const test::RunResult budget =
        test::run_ltrender("budget " + (dir / "quad.json").string() + " --path gx --variant " +
                           rows[i].variant + " --json");
    ASSERT_EQ(budget.exit_code, 0) << budget.err;
    const auto details = nlohmann::json::parse(budget.out).at("details");
    for (const char* key : {"vertex_bytes", "fifo_bytes", "xf_vertices", "triangles",
                            "texture_bytes", "tlut_bytes"}) {
      EXPECT_EQ(row["console"].at(key), details.at(key)) << rows[i].variant << " " << key;
    }
    EXPECT_GT(row["console"]["fifo_bytes"].get<std::size_t>(), 0u);
    ++checked;
  }
  EXPECT_EQ(checked, 2u);
  EXPECT_NE(html.find("Console bytes against error"), std::string::npos);
  EXPECT_NE(slurp("chart_console.svg").find("x: geometric mean FIFO bytes a frame"),
            std::string::npos);
}

}  // namespace
}  // namespace lt

namespace lt {
namespace {

// `bench --add-variant`: a gx variant no list holds (positions s16 with 8 fractional bits,
// normals s8) is a row beside the default's, with the console's bytes of its own storage and
// the error of its own render. The bytes by hand: a direct vertex sends its position as three
// s16 (6 bytes, not 12) and its normal as three s8 (3, not 12), 15 bytes less a vertex, and the
// FIFO carries 15 bytes less for each vertex the XF receives. The error measured again outside
// the bench (advise_error_check.h: render_scene and compare_images, as the bench states it
// measures a gx row: 8-bit frame, float reference, covered pixels).
TEST(BenchAddedVariant, AStoredGxVariantIsARowWithItsOwnBytesAndError) {
  test::TempDir dir;
  write_quad_scene(dir.path());
  BenchOptions o = rows_only_options(dir.path());
  o.paths = {"gx"};
  o.variants = VariantSelection::Defaults;
  o.added_variants = {parse_added_variant("gx:t=vertex:vtx=s16/8:nrm=s8")};
  o.rounds = 1;
  const std::vector<BenchRow> rows = run_bench(o);
  ASSERT_EQ(rows.size(), 2u);  // gx's default, then the added one (flat times, but no row)
  const BenchRow& f32 = rows[0];
  const BenchRow& stored = rows[1];
  EXPECT_EQ(f32.variant, "t=vertex");
  EXPECT_EQ(stored.variant, "t=vertex:vtx=s16/8:nrm=s8");
  ASSERT_TRUE(f32.console && stored.console);
  EXPECT_EQ(f32.console->vertex_bytes - stored.console->vertex_bytes, 15u);
  EXPECT_EQ(stored.console->xf_vertices, f32.console->xf_vertices);
  EXPECT_EQ(f32.console->fifo_bytes - stored.console->fifo_bytes,
            15u * stored.console->xf_vertices);
  ASSERT_TRUE(stored.error);
  test::expect_advise_error_is_measured_again(
      dir / "quad.json", nlohmann::json{{"width", 48}, {"height", 32}}, stored.variant,
      nlohmann::json{{"max", stored.error->max_lsb}, {"mean", stored.error->mean_lsb}});
  // report.md's console table has the row.
  write_bench_reports(o, rows);
  const std::string md = test::read_file(o.out_dir / "report.md");
  EXPECT_NE(md.find("| quad | gx | t=vertex:vtx=s16/8:nrm=s8 | " +
                    std::to_string(stored.console->vertex_bytes) + " | "),
            std::string::npos)
      << md;
}

// What --add-variant refuses, naming itself and the text: no path, an unknown path, a variant
// the path refuses; a row the bench makes anyway, or the same one twice (before anything is
// written: load_bench_inputs); and through the command, exit 2 with nothing written.
TEST(BenchAddedVariant, RefusesWhatIsNoNewRow) {
  for (const char* bad : {"t=vertex", "nope:t=vertex", "gx:t=bogus", "gx:"}) {
    try {
      parse_added_variant(bad);
      ADD_FAILURE() << bad << " was taken";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "--add-variant") << bad;
      EXPECT_EQ(e.where(), bad);
    }
  }
  test::TempDir dir;
  write_quad_scene(dir.path());
  BenchOptions o;
  o.scenes = {dir / "quad.json"};
  o.paths = {"gx"};
  o.variants = VariantSelection::Defaults;
  o.added_variants = {parse_added_variant("gx:t=vertex")};
  EXPECT_THROW(load_bench_inputs(o), InputError);  // the default: a row already
  o.added_variants = {parse_added_variant("gx:t=vertex:lut=64")};
  EXPECT_NO_THROW(load_bench_inputs(o));  // listed, but --variants default leaves it out
  o.added_variants.push_back(o.added_variants.front());
  EXPECT_THROW(load_bench_inputs(o), InputError);
  const fs::path out = dir / "out";
  const auto r = test::run_ltrender("bench " + (dir / "quad.json").string() +
                                    " --paths gx --add-variant gx:t=vertex -o " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--add-variant:gx:t=vertex: a row already"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// A bad scene anywhere in the list is reported (exit 2, one line) before anything is written.
TEST(BenchCli, BadSceneWritesNothing) {
  test::TempDir dir;
  test::write_file(dir / "bad.json", "{\"image\": {\"width\": 0}}");
  const auto out = dir / "out";
  const auto r = test::run_ltrender(
      "bench " + (test::source_dir() / "scenes" / "backlit_sphere.json").string() + " " +
      (dir / "bad.json").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.json:image.width"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// --pin-core: the whole bench on one core by default, and the report says so (with llvmpipe in
// the calling thread and one CPU worker); a core the process may not use, or a word that is no
// core, is an input error naming the option, with nothing written.
TEST(Bench, PinsToOneCoreAndSaysSo) {
  test::TempDir dir;
  write_quad_scene(dir.path());
  const std::string bench = "bench " + (dir / "quad.json").string() +
                            " --paths reference --frames 10 --min-time 0 --max-time 0 --quiet ";
  auto report = [&](const std::string& name) {
    std::ifstream in(dir / name / "report.json");
    return nlohmann::json::parse(in);
  };
  ASSERT_EQ(test::run_ltrender(bench + "-o " + (dir / "pinned").string()).exit_code, 0);
  const auto pinned = report("pinned");
  EXPECT_EQ(pinned["pinning"].get<std::string>().rfind("pinned to core ", 0), 0u);
  EXPECT_EQ(pinned["cpu_threads"], 1);
  EXPECT_NE(pinned["llvmpipe_threads"].get<std::string>().find("LP_NUM_THREADS=0"),
            std::string::npos);
  ASSERT_EQ(test::run_ltrender(bench + "--pin-core none -o " + (dir / "free").string()).exit_code,
            0);
  EXPECT_EQ(report("free")["pinning"].get<std::string>().rfind("not pinned", 0), 0u);
  for (const char* bad : {"4000", "abc", "1x"}) {
    const auto r =
        test::run_ltrender(bench + "--pin-core " + bad + " -o " + (dir / "bad").string());
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("ltrender: error: --pin-core"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "bad")) << bad;
  }
}

// The measuring options take finite numbers only: a NaN time or interval would leave the
// stopping rule without an end (CLI11's own range check lets NaN through).
TEST(Bench, NotANumberForATimeOrIntervalIsAnInputError) {
  test::TempDir dir;
  write_quad_scene(dir.path());
  for (const char* option : {"--min-time", "--max-time", "--target-interval"}) {
    for (const char* value : {"nan", "inf", "-1"}) {
      const auto r =
          test::run_ltrender("bench " + (dir / "quad.json").string() + " --paths flat --quiet " +
                             option + " " + value + " -o " + (dir / "out").string());
      EXPECT_EQ(r.exit_code, 2) << option << " " << value;
      EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_FALSE(fs::exists(dir / "out")) << option << " " << value;
    }
  }
}

// `ltrender bench --quick` end to end on one small scene: the report says the timing was quick,
// and every figure was timed in one round (the rounds the bench ran, as the report records
// them; never the wall time). Also `--variants`: which rows a bench has.
TEST(BenchQuick, TheReportSaysQuickAndEveryRowWasTimedInOneRound) {
  test::TempDir dir;
  write_quad_scene(dir.path());
  const fs::path out = dir / "out";
  // glsl at its default variant only (not pow=exact:f32); flat is timed but no row of its own.
  const test::RunResult r =
      test::run_ltrender("bench " + (dir / "quad.json").string() +
                         " --quick --paths glsl --variants default -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Not a terminal: no progress line (its carriage returns), only the result.
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(test::read_file(out / "report.json"));
  EXPECT_EQ(j["timing_mode"], "quick");
  EXPECT_EQ(j["rounds"], 1);
  EXPECT_TRUE(j["timing_overrides"].empty());
  std::set<std::string> rows;
  for (const auto& row : j["rows"]) {
    rows.insert(row["path"].get<std::string>() + " " + row["variant"].get<std::string>());
    EXPECT_EQ(row["ratio_interval"]["rounds"], 1) << row["path"];
    // One round still holds --frames pairs (10 by default).
    EXPECT_GE(row["ratio_interval"]["pairs"].get<int>(), 10) << row["path"];
  }
  EXPECT_EQ(rows, (std::set<std::string>{"glsl pow=exact"}));
  const std::string md = test::read_file(out / "report.md");
  EXPECT_NE(md.find("quick timing (bench --quick): 1 round"), std::string::npos) << md;
  const std::string page = test::read_file(out / "index.html");
  EXPECT_NE(page.find("quick timing (bench --quick)"), std::string::npos);
}

TEST(BenchQuick, AnOptionAfterQuickIsInTheReport) {
  test::TempDir dir;
  write_quad_scene(dir.path());
  const fs::path out = dir / "out";
  const test::RunResult r =
      test::run_ltrender("bench " + (dir / "quad.json").string() +
                         " --quick --rounds 2 --paths flat -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(test::read_file(out / "report.json"));
  EXPECT_EQ(j["timing_mode"], "quick");
  EXPECT_EQ(j["rounds"], 2);
  EXPECT_EQ(j["timing_overrides"], nlohmann::json::array({"--rounds"}));
  EXPECT_NE(test::read_file(out / "report.md").find("; given: --rounds"), std::string::npos);
}

TEST(BenchQuick, AnUnknownVariantSelectionIsAUsageError) {
  const test::RunResult r = test::run_ltrender("bench --variants some -o /nonexistent/out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--variants"), std::string::npos) << r.err;
}

TEST(BenchVariants, DefaultIsEachPathsFirstStoryAddsTheMarkedOnes) {
  for (const PathInfo& p : all_paths()) {
    for (const VariantInfo& v : p.variants) {
      const bool first = v.name == p.variants.front().name;
      EXPECT_TRUE(selected(p, v, VariantSelection::All)) << p.name << " " << v.name;
      EXPECT_EQ(selected(p, v, VariantSelection::Defaults), first) << p.name << " " << v.name;
      EXPECT_EQ(selected(p, v, VariantSelection::Story), first || v.run == VariantRun::Story)
          << p.name << " " << v.name;
    }
  }
}

TEST(BenchVariants, TheStoryHasTheLutTheTexgenAndTheXfLobe) {
  // Issue 28: ./run.sh's quick run shows the variants the docs' story is about.
  std::set<std::string> story;
  for (const PathInfo& p : all_paths())
    for (const VariantInfo& v : p.variants)
      if (selected(p, v, VariantSelection::Story)) story.insert(p.name + " " + v.name);
  for (const char* expected :
       {"gx t=vertex", "gx t=vertex:lut=16", "gx t=texgen", "gx lobe=xf-spec", "combiners t=vertex",
        "combiners t=texgen", "combiners lobe=cube", "arbfp pow=mul", "arbfp pow=lut:256:u8",
        "arbfp pow=sg-simplified", "glsl pow=exact", "reference exact", "flat constant",
        "half pow=exact"})
    EXPECT_EQ(story.count(expected), 1u) << expected;
  // And not every variant: the convention axes and the other LUT widths wait for --full.
  EXPECT_EQ(story.count("gx t=vertex:lut=64"), 0u);
  EXPECT_EQ(story.count("gx t=vertex:colors=round"), 0u);
  EXPECT_EQ(story.count("arbfp pow=lut:16:u8"), 0u);
}

}  // namespace
}  // namespace lt
