#include "regress/run_case.h"

#include <optional>

#include "core/error.h"
#include "core/fixed.h"
#include "core/fs.h"
#include "core/stopwatch.h"
#include "metrics/heatmap.h"
#include "paths/path_bounds.h"
#include "regress/regress_plan.h"
#include "render/evaluate.h"

namespace lt {

namespace {

// The figures, then the verdict's reasons. A reason states its own figures (the failing share,
// the max and where it is), so the figures line leaves out what a reason states: each figure
// once per line. A case that passes within the warn tier says why it warns.
std::string case_message(const ErrorStats& s, const Verdict& v) {
  const bool max_in_reason = v.hard_failing_pixels > 0;
  std::string line = max_in_reason ? "" : "max " + fixed(s.max_lsb, 2) + " LSB, ";
  line += "mean " + fixed(s.mean_lsb, 3) + " LSB";
  if (!v.over_fail_percent)
    line += ", " + std::to_string(v.failing_pixels) + " pixels (" + fixed(v.failing_percent, 3) +
            "%) over fail_lsb";
  // Which of them moved with an edge and which changed shade (compare.h split_edge_shifts).
  if (v.failing_pixels > 0)
    line += (v.over_fail_percent ? ", over fail_lsb: " : " (") +
            std::to_string(v.edge_shift_pixels) + " edge shifts, " +
            std::to_string(v.shading_pixels) + " shading" + (v.over_fail_percent ? "" : ")");
  for (const std::string& reason : v.reasons) line += "; " + reason;
  for (const std::string& warning : v.warnings) line += "; warn: " + warning;
  return line;
}

void copy_file_atomically(const fs::path& from, const fs::path& to) {
  write_atomically(to, [&](const fs::path& tmp) {
    std::error_code ec;
    fs::copy_file(from, tmp, fs::copy_options::overwrite_existing, ec);
    if (ec) throw InputError(to.string(), "", "cannot copy " + from.string() + ": " + ec.message());
  });
}

// One approved image a render is held to, and how the render fares against it.
struct Candidate {
  fs::path file;
  bool exists = false;
  std::optional<Comparison> comparison;
  Verdict verdict;
  std::string problem;  // no comparison: why (another size, unreadable)
  std::string summary() const {
    if (!comparison) return problem;
    return (verdict.pass ? "pass, " : "fail, ") + std::string("max ") +
           fixed(comparison->image.max_lsb, 2) + " LSB";
  }
};

Candidate held_to(const fs::path& file, const Image& render, const RegressCase& c) {
  Candidate k;
  k.file = file;
  std::error_code ec;
  k.exists = fs::exists(file, ec);
  if (!k.exists) return k;
  try {
    Image golden = read_image(file);
    if (golden.width != render.width || golden.height != render.height) {
      k.problem = "golden is " + std::to_string(golden.width) + "x" +
                  std::to_string(golden.height) + ", the render " + std::to_string(render.width) +
                  "x" + std::to_string(render.height);
    } else {
      k.comparison = compare_with_golden(render, std::move(golden));
      k.verdict = apply_tolerance(*k.comparison, c.tolerance);
    }
  } catch (const InputError& e) {
    k.problem = std::string("cannot read the golden: ") + e.what();
  }
  return k;
}

// --artifacts: whether the report folder keeps this case's images.
bool keeps_images(const RegressOptions& o, CaseStatus status) {
  if (o.report_dir.empty()) return false;
  switch (o.artifacts) {
    case RegressOptions::Artifacts::kAll:
      return true;
    case RegressOptions::Artifacts::kFailures:
      return is_failure(status) || status == CaseStatus::kWarn;
    case RegressOptions::Artifacts::kNone:
      return false;
  }
  return true;
}

// Whether the first golden of `c` is within its path's bound against the ground truth
// (paths/path_bounds.h; a recorded image is not yet a reference): what `render`, `path`'s frame,
// breaks of it, or empty. `note` says when it is within, or that the path has no bound for any
// scene (its error depends on the scene: every gx variant) and the golden is unchecked.
std::string outside_path_bound(RenderSession& session, const Path& path, const Image& render,
                               const RegressCase& c, std::string& note) {
  const std::string name = c.path->name + ":" + c.variant;
  const PathBound* bound = general_path_bound(c.path->name, c.variant);
  if (!bound) {
    note = "unchecked: " + name +
           " has a bound on the demo scenes only (its error depends on the scene)";
    return "";
  }
  const TestEncoding encoding = test_encoding(path);  // before the reference is drawn
  const Comparison error = compare_with_reference(render, encoding, render_reference(session));
  std::string broken;
  for (const std::string& b : pixel_bound_violations(*bound, error))
    broken += (broken.empty() ? "" : ", ") + b;
  if (broken.empty()) {
    note = "within " + name + "'s bound to the reference (covered max " +
           fixed(error.covered.max_lsb, 2) + " of " + fixed(bound->max_lsb, 2) + " LSB)";
    return "";
  }
  return "outside " + name + "'s bound to the reference (" + broken + "; " + bound->reason + ")";
}

}  // namespace

CaseResult skipped_case(const RegressOptions& o, const RegressCase& c) {
  CaseResult r;
  r.regress_case = c;
  r.status = CaseStatus::kSkipped;
  r.golden = o.goldens / c.golden_name();
  r.message = c.skip_reason;
  return r;
}

// Renders one case in the scene's session, compares it with its golden and, with --update,
// writes the golden. The report's images are written when there is a report dir.
CaseResult run_case(const RegressOptions& o, const fs::path& scene_file, RenderSession& session,
                    const RegressCase& c) {
  const auto t0 = SteadyClock::now();
  CaseResult r;
  r.regress_case = c;
  r.golden = o.goldens / c.golden_name();
  const std::unique_ptr<Path> path = session.build(*c.path, c.variant);
  path->frame();
  const Image render = path->result();
  r.width = render.width;
  r.height = render.height;

  // The approved images: this renderer's override (docs/regress.md "Goldens per renderer"),
  // then the shared golden. The case passes against either.
  std::vector<Candidate> candidates;
  const fs::path shared = o.goldens / c.golden_name();
  if (!o.golden_key.empty())
    candidates.push_back(held_to(o.goldens / o.golden_key / c.golden_name(), render, c));
  candidates.push_back(held_to(shared, render, c));
  const Candidate* chosen = nullptr;
  for (const Candidate& k : candidates) {
    if (k.exists && k.comparison && k.verdict.pass) {
      chosen = &k;
      break;
    }
  }
  const bool pass = chosen != nullptr;
  if (!chosen) {
    for (const Candidate& k : candidates) {
      if (k.exists && !chosen) chosen = &k;
    }
  }
  r.golden = chosen ? chosen->file : shared;
  if (chosen) {
    r.message = chosen->problem;
    if (chosen->comparison) {
      r.verdict = chosen->verdict;
      r.figures = c.tolerance.region == Region::kCovered ? chosen->comparison->covered
                                                         : chosen->comparison->image;
      r.comparison_json = to_json(*chosen->comparison, c.tolerance, r.verdict);
      r.details = to_table(*chosen->comparison, c.tolerance, r.verdict);
      r.message = case_message(*r.figures, r.verdict);
    }
  }
  // A failure names every image it was held to.
  size_t existing = 0;
  for (const Candidate& k : candidates) existing += k.exists;
  if (!pass && existing > 1) {
    std::string held;
    for (const Candidate& k : candidates) {
      if (!k.exists) continue;
      held += (held.empty() ? "" : ", ") + k.file.string() + " (" + k.summary() + ")";
    }
    r.message += "; held to " + held;
    r.details = "held to " + held + "\n" + r.details;
  }
  // The page's images, once the status says whether --artifacts keeps them: the render, and
  // with a comparison the golden it was held to (before --update replaces it) and the heatmap.
  const auto write_page_images = [&] {
    if (!keeps_images(o, r.status)) return;
    const std::string stem = fs::path(c.golden_name()).stem().string();
    r.image = "images/" + stem + ".png";
    write_image(o.report_dir / r.image, render);
    if (chosen && chosen->comparison) {
      r.golden_image = "images/" + stem + "__golden.png";
      copy_file_atomically(chosen->file, o.report_dir / r.golden_image);
      r.heatmap = "images/" + stem + "__heatmap.png";
      write_image(o.report_dir / r.heatmap, error_heatmap(*chosen->comparison));
    }
  };
  const bool have_shared = candidates.back().exists;
  if (o.update) {
    // The shared golden is written only where there is none; where it fails, this renderer's
    // override is (so another renderer's approved image is never replaced).
    if (pass) {
      r.status = CaseStatus::kKept;
      write_page_images();
    } else {
      const bool to_override = have_shared && !o.golden_key.empty();
      r.golden = to_override ? candidates.front().file : shared;
      const bool existed = to_override ? candidates.front().exists : have_shared;
      std::string note;
      const std::string outside =
          have_shared ? "" : outside_path_bound(session, *path, render, c, note);
      // Outside the bound the golden is still written, but warned: the bound table was measured
      // on the demo scenes, and a scene of another kind (a texture filtered at another size, a
      // power past what a LUT holds) may be right outside it; the reviewer decides.
      r.status = !outside.empty() ? CaseStatus::kWarn
                 : existed        ? CaseStatus::kUpdated
                                  : CaseStatus::kCreated;
      write_page_images();
      if (to_override) make_directory(r.golden.parent_path());
      write_image(r.golden, render);
      if (!existed)
        r.message = "wrote " + r.golden.string() +
                    (!outside.empty() ? "; warn: " + outside + "; review it before committing it"
                     : note.empty()   ? ""
                                      : "; " + note);
    }
  } else if (existing == 0) {
    r.status = CaseStatus::kMissing;
    r.message =
        "no golden " + shared.string() + "; create it with: " + update_command(o, c, scene_file);
  } else {
    r.status = !pass ? CaseStatus::kFail : r.verdict.warn ? CaseStatus::kWarn : CaseStatus::kPass;
  }
  if (!o.update) write_page_images();
  r.seconds = seconds_since(t0);
  return r;
}

}  // namespace lt
