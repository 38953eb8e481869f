#include "regress/regress.h"

#include <cstdio>
#include <map>

#include "core/error.h"
#include "core/fixed.h"
#include "core/fs.h"
#include "core/stopwatch.h"
#include "metrics/heatmap.h"
#include "render/evaluate.h"
#include "render/session.h"

namespace lt {

namespace {

// The figures, then the verdict's reasons. A reason states its own figures (the failing share,
// the max and where it is), so the figures line leaves out what a reason states: each figure
// once per line.
std::string case_message(const ErrorStats& s, const Verdict& v) {
  const bool max_in_reason = v.hard_failing_pixels > 0;
  std::string line = max_in_reason ? "" : "max " + fixed(s.max_lsb, 2) + " LSB, ";
  line += "mean " + fixed(s.mean_lsb, 3) + " LSB";
  if (!v.over_fail_percent)
    line += ", " + std::to_string(v.failing_pixels) + " pixels (" + fixed(v.failing_percent, 3) +
            "%) over fail_lsb";
  for (const std::string& reason : v.reasons) line += "; " + reason;
  return line;
}

// A directory every output needs before any work: its parent must exist (as for every output
// of ltrender) or be the report directory that -o creates (`-o out --junit out/junit.xml`), and
// an output never names an input.
void check_output_file(const fs::path& file, const std::vector<fs::path>& inputs,
                       const fs::path& report_dir) {
  if (file.empty()) return;
  std::error_code ec;
  const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  const bool in_report_dir =
      !report_dir.empty() && dir.lexically_normal() == report_dir.lexically_normal();
  if (!in_report_dir && !fs::is_directory(dir, ec))
    throw InputError(file.string(), "", "its directory does not exist");
  ensure_not_an_input(file, inputs);
}

void make_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string(), "", "cannot create the directory: " + ec.message());
}

void copy_file_atomically(const fs::path& from, const fs::path& to) {
  write_atomically(to, [&](const fs::path& tmp) {
    std::error_code ec;
    fs::copy_file(from, tmp, fs::copy_options::overwrite_existing, ec);
    if (ec) throw InputError(to.string(), "", "cannot copy " + from.string() + ": " + ec.message());
  });
}

// Everything a run needs, read and checked before the first render.
struct Plan {
  std::vector<fs::path> scene_files;
  std::vector<Scene> scenes;
  std::vector<RegressCase> cases;  // every shard's
};

// A scene a path cannot take at all (gx: two materials with one C name, a thickness map over
// 1024 texels) is refused when the path is built: bad input like a bad scene. Every case's path
// is built once here, at 1x1 (enough to build programs, as `info` does), every shard's cases,
// so that the run stops before any golden is written. A variant that cannot be exact is a
// skipped case instead (expand_cases).
void check_every_path_builds(const Plan& plan) {
  for (size_t s = 0; s < plan.scenes.size(); ++s) {
    std::optional<RenderSession> session;
    for (const RegressCase& c : plan.cases) {
      if (c.scene_index != s || !c.skip_reason.empty()) continue;
      if (!session) session.emplace(plan.scenes[s], 1, 1);
      (void)session->build(*c.path, c.variant);
    }
  }
}

Plan make_plan(const RegressOptions& o) {
  Plan plan;
  plan.scene_files = collect_scene_files(o.inputs);
  for (const fs::path& f : plan.scene_files) plan.scenes.push_back(load_scene(f, o.scene_options));
  const std::vector<PathRequest> requests = parse_path_list(o.paths);
  plan.cases = expand_cases(plan.scene_files, plan.scenes, requests);
  // Every render's size before the first one: a scene too large to render is bad input, found
  // before any golden is written.
  const bool resized = o.width > 0 || o.height > 0;
  for (const Scene& s : plan.scenes) {
    check_image_size(o.width > 0 ? o.width : s.width, o.height > 0 ? o.height : s.height,
                     resized ? "--width/--height" : s.file.string(), resized ? "" : "image");
  }
  std::vector<fs::path> inputs = plan.scene_files;
  for (const Scene& s : plan.scenes) {
    for (const SceneObject& obj : s.objects) inputs.push_back(obj.mesh_path);
  }
  check_output_file(o.junit_file, inputs, o.report_dir);
  check_output_file(o.json_file, inputs, o.report_dir);
  if (o.goldens.empty()) throw InputError("--goldens", "", "a folder of goldens is required");
  std::error_code ec;
  if (fs::exists(o.goldens, ec) && !fs::is_directory(o.goldens, ec))
    throw InputError(o.goldens.string(), "", "--goldens must be a folder");
  // Without --update a missing folder is a wrong path, not a dozen missing goldens; --update
  // creates it (the first run of a new suite).
  if (!o.update && !fs::exists(o.goldens, ec))
    throw InputError(o.goldens.string(), "",
                     "no such folder of goldens (--update creates it and writes them)");
  check_every_path_builds(plan);
  return plan;
}

// Renders one case in the scene's session, compares it with its golden and, with --update,
// writes the golden. The report's images are written when there is a report dir.
CaseResult run_case(const RegressOptions& o, const Plan& plan, RenderSession& session,
                    const RegressCase& c) {
  const auto t0 = SteadyClock::now();
  CaseResult r;
  r.regress_case = c;
  r.golden = o.goldens / c.golden_name();
  const Image render = render_frame(session, *c.path, c.variant);
  r.width = render.width;
  r.height = render.height;
  const std::string stem = fs::path(c.golden_name()).stem().string();
  if (!o.report_dir.empty()) {
    r.image = "images/" + stem + ".png";
    write_image(o.report_dir / r.image, render);
  }

  std::error_code ec;
  const bool have_golden = fs::exists(r.golden, ec);
  std::optional<Comparison> comparison;
  std::string unreadable;
  if (have_golden) {
    try {
      Image golden = read_image(r.golden);
      if (golden.width != render.width || golden.height != render.height) {
        r.message = "golden is " + std::to_string(golden.width) + "x" +
                    std::to_string(golden.height) + ", the render " + std::to_string(render.width) +
                    "x" + std::to_string(render.height);
      } else {
        comparison = compare_with_golden(render, std::move(golden));
      }
    } catch (const InputError& e) {
      r.message = std::string("cannot read the golden: ") + e.what();
    }
  }
  if (comparison) {
    r.verdict = apply_tolerance(*comparison, c.tolerance);
    r.figures = c.tolerance.region == Region::kCovered ? comparison->covered : comparison->image;
    r.comparison_json = to_json(*comparison, c.tolerance, r.verdict);
    r.details = to_table(*comparison, c.tolerance, r.verdict);
    r.message = case_message(*r.figures, r.verdict);
    if (!o.report_dir.empty()) {
      r.golden_image = "images/" + stem + "__golden.png";
      copy_file_atomically(r.golden, o.report_dir / r.golden_image);
      r.heatmap = "images/" + stem + "__heatmap.png";
      write_image(o.report_dir / r.heatmap, error_heatmap(*comparison));
    }
  }
  const bool pass = comparison && r.verdict.pass;
  if (o.update) {
    r.status = pass ? CaseStatus::kKept : have_golden ? CaseStatus::kUpdated : CaseStatus::kCreated;
    if (!pass) write_image(r.golden, render);
    if (!have_golden) r.message = "wrote " + r.golden.string();
  } else if (!have_golden) {
    r.status = CaseStatus::kMissing;
    r.message = "no golden " + r.golden.string() +
                "; create it with: " + update_command(o, c, plan.scene_files[c.scene_index]);
  } else {
    r.status = pass ? CaseStatus::kPass : CaseStatus::kFail;
  }
  r.seconds = seconds_since(t0);
  return r;
}

void print_case(const RegressOptions& o, const CaseResult& r) {
  if (o.quiet && !is_failure(r.status) && r.status != CaseStatus::kCreated &&
      r.status != CaseStatus::kUpdated)
    return;
  // Failures in capitals, so that they stand out in a CI log.
  std::string status = to_string(r.status);
  if (is_failure(r.status))
    for (char& ch : status) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  std::printf("%-7s %s%s%s\n", status.c_str(), r.regress_case.id().c_str(),
              r.message.empty() ? "" : ": ", r.message.c_str());
  std::fflush(stdout);
}

}  // namespace

const char* to_string(CaseStatus s) {
  switch (s) {
    case CaseStatus::kPass:
      return "pass";
    case CaseStatus::kFail:
      return "fail";
    case CaseStatus::kMissing:
      return "missing";
    case CaseStatus::kSkipped:
      return "skipped";
    case CaseStatus::kCreated:
      return "created";
    case CaseStatus::kUpdated:
      return "updated";
    case CaseStatus::kKept:
      return "kept";
  }
  return "?";
}

bool is_failure(CaseStatus s) {
  return s == CaseStatus::kFail || s == CaseStatus::kMissing;
}

size_t RegressRun::count(CaseStatus s) const {
  size_t n = 0;
  for (const CaseResult& r : results) n += r.status == s;
  return n;
}

bool RegressRun::failed() const {
  return count(CaseStatus::kFail) + count(CaseStatus::kMissing) > 0;
}

std::string update_command(const RegressOptions& o, const RegressCase& c,
                           const fs::path& scene_file) {
  std::string cmd = "ltrender regress " + scene_file.string() + " --goldens " + o.goldens.string() +
                    " --paths '" + c.path->name + ":" + c.variant + "'";
  if (o.width > 0) cmd += " --width " + std::to_string(o.width);
  if (o.height > 0) cmd += " --height " + std::to_string(o.height);
  if (!o.scene_options.default_lights) cmd += " --lights none";
  return cmd + " --update";
}

RegressRun run_regress(const RegressOptions& o) {
  const auto t0 = SteadyClock::now();
  const Plan plan = make_plan(o);
  RegressRun run;
  run.shard = o.shard;
  run.total_cases = plan.cases.size();
  // This shard's cases, grouped by scene so that each scene is set up once.
  std::map<size_t, std::vector<const RegressCase*>> by_scene;
  std::vector<const RegressCase*> mine;
  for (size_t i = 0; i < plan.cases.size(); ++i) {
    if (o.shard.takes(i)) mine.push_back(&plan.cases[i]);
  }
  for (const RegressCase* c : mine) by_scene[c->scene_index].push_back(c);
  if (!o.report_dir.empty()) make_directory(o.report_dir / "images");
  if (o.update) make_directory(o.goldens);

  std::map<const RegressCase*, CaseResult> done;
  for (const auto& [scene_index, cases] : by_scene) {
    const Scene& scene = plan.scenes[scene_index];
    std::optional<RenderSession> session;
    for (const RegressCase* c : cases) {
      CaseResult r;
      if (!c->skip_reason.empty()) {
        r.regress_case = *c;
        r.status = CaseStatus::kSkipped;
        r.golden = o.goldens / c->golden_name();
        r.message = c->skip_reason;
      } else {
        if (!session) {
          session.emplace(scene, o.width > 0 ? o.width : scene.width,
                          o.height > 0 ? o.height : scene.height);
        }
        r = run_case(o, plan, *session, *c);
      }
      print_case(o, r);
      done.emplace(c, std::move(r));
    }
  }
  for (const RegressCase* c : mine) run.results.push_back(std::move(done.at(c)));
  run.seconds = seconds_since(t0);
  return run;
}

}  // namespace lt
