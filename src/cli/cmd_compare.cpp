// `ltrender compare TEST REF`: the metrics of metrics.md and an idiff-style verdict. Exit 0 pass,
// 1 over threshold (or NaN/Inf in TEST), 2 bad input. All figures come from metrics/compare.h;
// this file only reads options, writes the heatmap and prints.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "image/image.h"
#include "metrics/compare.h"
#include "metrics/heatmap.h"

namespace lt::cli {

namespace {

struct CompareOptions {
  std::string test, reference;
  // Numbers are taken as text and parsed here so that a bad value names its option in the one
  // line of cli.md, and so that "inf" is accepted for --hard-fail-lsb.
  std::string fail_lsb = "1", fail_percent = "0", hard_fail_lsb = "inf", heatmap_max_lsb = "8";
  std::string region = "covered";
  std::string heatmap;
  bool json = false;
};

// A number >= 0 (infinity allowed only where `allow_inf`), or InputError naming the option.
double parse_threshold(const std::string& option, const std::string& text, bool allow_inf) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  const bool whole = end != begin && *end == '\0';
  if (!whole || std::isnan(v) || (std::isinf(v) && !allow_inf) || v < 0.0) {
    throw InputError(
        option, "",
        "expects a number >= 0" + std::string(allow_inf ? " or inf" : "") + ", got '" + text + "'");
  }
  return v;
}

int run_compare(const CompareOptions& opt) {
  Tolerance tolerance;
  tolerance.fail_lsb = parse_threshold("--fail-lsb", opt.fail_lsb, false);
  tolerance.fail_percent = parse_threshold("--fail-percent", opt.fail_percent, false);
  if (tolerance.fail_percent > 100.0) {
    throw InputError("--fail-percent", "",
                     "expects a percentage in [0, 100], got '" + opt.fail_percent + "'");
  }
  tolerance.hard_fail_lsb = parse_threshold("--hard-fail-lsb", opt.hard_fail_lsb, true);
  tolerance.region = opt.region == "image" ? Region::kImage : Region::kCovered;
  const double heatmap_max = parse_threshold("--heatmap-max-lsb", opt.heatmap_max_lsb, false);
  if (heatmap_max <= 0.0) {
    throw InputError("--heatmap-max-lsb", "",
                     "expects a number > 0, got '" + opt.heatmap_max_lsb + "'");
  }

  // Check the heatmap target before any work: a bad target must not cost a comparison, and an
  // input is never overwritten (cli.md).
  const fs::path heatmap_path = opt.heatmap;
  if (!opt.heatmap.empty()) {
    if (heatmap_path.extension() != ".png" && heatmap_path.extension() != ".PNG") {
      throw InputError(opt.heatmap, "", "heatmap must be a .png");
    }
    ensure_not_an_input(heatmap_path, {opt.test, opt.reference});
  }

  const Comparison comparison = compare_files(opt.test, opt.reference);
  const Verdict verdict = apply_tolerance(comparison, tolerance);

  // Written on pass and on fail (a failing comparison is when it is wanted), never on bad input:
  // every InputError above is thrown before this point.
  if (!opt.heatmap.empty()) write_image(heatmap_path, error_heatmap(comparison, heatmap_max));

  if (opt.json) {
    std::string text = to_json(comparison, tolerance, verdict).dump(2);
    std::fputs((text + "\n").c_str(), stdout);
  } else {
    std::fputs(to_table(comparison, tolerance, verdict).c_str(), stdout);
  }
  std::fflush(stdout);

  if (!verdict.pass) {
    // main prints this as the one "ltrender: check failed:" line on stderr and exits 1.
    std::string what = "compare: " + opt.test;
    for (const auto& reason : verdict.reasons) what += "; " + reason;
    throw CheckFailed(what);
  }
  return 0;
}

}  // namespace

Action add_compare(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "compare", "Error of TEST against the reference REF in LSB of 8 bits (docs/spec/metrics.md)");
  auto opt = std::make_shared<CompareOptions>();
  sub->add_option("TEST", opt->test, "Image under test (8-bit PNG, or EXR compared unquantised)")
      ->required()
      ->type_name("FILE");
  sub->add_option("REF", opt->reference,
                  "Reference image (EXR; alpha is the coverage mask); an 8-bit REF with a float "
                  "TEST is refused as the two swapped")
      ->required()
      ->type_name("FILE");
  sub->add_option("--fail-lsb", opt->fail_lsb,
                  "Per-pixel error (max over RGB) that counts as failing")
      ->type_name("LSB")
      ->capture_default_str();
  sub->add_option("--fail-percent", opt->fail_percent,
                  "Fail if more than this percent of pixels have error > --fail-lsb")
      ->type_name("PERCENT")
      ->capture_default_str();
  sub->add_option("--hard-fail-lsb", opt->hard_fail_lsb, "Fail if any pixel's error exceeds this")
      ->type_name("LSB|inf")
      ->capture_default_str();
  sub->add_option("--region", opt->region,
                  "Pixels the thresholds judge: covered (reference alpha > 0.5) or image")
      ->check(CLI::IsMember({"covered", "image"}))
      ->type_name("REGION")
      ->capture_default_str();
  sub->add_option("--heatmap", opt->heatmap, "Write a per-pixel error heatmap (.png)")
      ->type_name("OUT.png");
  sub->add_option("--heatmap-max-lsb", opt->heatmap_max_lsb, "Error drawn white in the heatmap")
      ->type_name("LSB")
      ->capture_default_str();
  sub->add_flag("--json", opt->json, "Print the figures as one JSON object");
  return [opt]() -> int { return run_compare(*opt); };
}

}  // namespace lt::cli
