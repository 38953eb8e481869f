// What a regress run leaves for machines and people: --json, --junit and the report page.
#include <cstdio>

#include "core/fixed.h"
#include "core/fs.h"
#include "regress/case_record.h"
#include "regress/junit.h"
#include "regress/regress.h"
#include "report/report_page.h"

namespace lt {

namespace {

fs::path relative_to_json(const RegressOptions& o) {
  const fs::path base = fs::absolute(o.json_file).parent_path();
  return fs::absolute(o.report_dir).lexically_normal().lexically_relative(base.lexically_normal());
}

nlohmann::ordered_json run_json(const RegressOptions& o, const RegressRun& run) {
  nlohmann::ordered_json j;
  j["goldens"] = o.goldens.string();
  j["label"] = o.label;
  j["run"] = {{"golden_key", o.golden_key},
              {"scenes", run.scenes},
              {"scene_files", run.scene_files},
              {"paths", run.requested},
              {"width", run.width},
              {"height", run.height}};
  // Where this run's page is, from the JSON's folder (`regress merge` finds the images there).
  j["report"] = o.report_dir.empty() || o.json_file.empty()
                    ? nlohmann::ordered_json()
                    : nlohmann::ordered_json(relative_to_json(o).string());
  j["shard"] = run.shard.to_string();
  j["total_cases"] = run.total_cases;
  // While the run goes on the file holds the cases finished so far: "complete" says whether
  // every case of the shard is in it.
  j["complete"] = run.complete;
  j["shard_cases"] = run.shard_cases;
  j["seconds"] = run.seconds;
  nlohmann::ordered_json counts;
  for (CaseStatus s : kCaseStatuses) {
    counts[to_string(s)] = run.count(s);
  }
  j["counts"] = counts;
  j["failed"] = run.failed();
  j["cases"] = nlohmann::ordered_json::array();
  for (const CaseResult& r : run.results) j["cases"].push_back(case_record(r));
  return j;
}

// A case as the page shows it: its render, flipped with its golden, the golden's heatmap.
PageCard case_card(const CaseResult& r) {
  const RegressCase& c = r.regress_case;
  PageCard card;
  card.scene = c.scene;
  card.path = c.path->name;
  card.variant = c.variant;
  card.image = r.image;
  card.flip_image = r.golden_image;
  card.flip_label = "golden";
  card.heatmap = r.heatmap;
  card.verdict = to_string(r.status);
  card.width = r.width;
  card.height = r.height;
  if (r.figures) {
    card.error_lsb = r.figures->max_lsb;
    card.figures = {{"max", fixed(r.figures->max_lsb, 2, " LSB")},
                    {"mean", fixed(r.figures->mean_lsb, 3, " LSB")},
                    {"p99", fixed(r.figures->p99_lsb, 2, " LSB")},
                    {"over fail_lsb", std::to_string(r.verdict.failing_pixels) + " px (" +
                                          fixed(r.verdict.failing_percent, 3, "%") + ")"},
                    {"edge shifts", std::to_string(r.verdict.edge_shift_pixels) + " px"},
                    {"shading", std::to_string(r.verdict.shading_pixels) + " px, max " +
                                    fixed(r.verdict.shading_max_lsb, 2, " LSB")},
                    {"tolerance", fixed(c.tolerance.fail_lsb, 2) + " LSB on " +
                                      fixed(c.tolerance.fail_percent, 2) + "%, none over " +
                                      fixed(c.tolerance.hard_fail_lsb, 2)}};
  }
  card.figures.push_back({"time", fixed(r.seconds, 3, " s")});
  for (const std::string& reason : r.verdict.reasons) card.notes.push_back(reason);
  for (const std::string& warning : r.verdict.warnings) card.notes.push_back("warn: " + warning);
  if (!r.figures && !r.message.empty()) card.notes.push_back(r.message);
  return card;
}

}  // namespace

std::string regress_summary(const RegressOptions& o, const RegressRun& run) {
 std::string s = std::to_string(run.results.size()) + " cases against " + o.goldens.string() +
                  (o.golden_key.empty() ? "" : " (key " + o.golden_key + ")") + " (shard " + run.shard.to_string() + " of " + std::to_string(run.total_cases) +
                  " cases): ";
  bool first = true;
  for (CaseStatus st : kCaseStatuses) {
    if (run.count(st) == 0) continue;
    s += (first ? "" : ", ") + std::to_string(run.count(st)) + " " + to_string(st);
    first = false;
  }
  return s + " in " + fixed(run.seconds, 1, " s");
}

void write_regress_junit_and_json(const RegressOptions& o, const RegressRun& run) {
  if (!o.json_file.empty()) write_text_file(o.json_file, run_json(o, run).dump(2) + "\n");
  if (!o.junit_file.empty()) write_text_file(o.junit_file, junit_xml(run, o.label, o.report_dir));
}

void write_regress_outputs(const RegressOptions& o, const RegressRun& run) {
  write_regress_junit_and_json(o, run);
  if (!o.report_dir.empty()) {
    ReportPage page;
    page.title = o.label.empty() ? "ltrender regress" : "ltrender regress: " + o.label;
    page.summary = regress_summary(o, run);
    for (const CaseResult& r : run.results) page.cards.push_back(case_card(r));
    write_report_page(o.report_dir, page);
  }
}

}  // namespace lt
