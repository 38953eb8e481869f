#include "regress/github_actions.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "core/error.h"
#include "core/fixed.h"

namespace lt {

namespace {

std::string replace_each(const std::string& text, const std::string& chars,
                         const std::vector<std::string>& by) {
  std::string out;
  for (char ch : text) {
    const size_t k = chars.find(ch);
    out += k == std::string::npos ? std::string(1, ch) : by[k];
  }
  return out;
}

// A Markdown table cell: '|' would end the cell and a line break the row; '<', '>' and '&'
// would be read as HTML, which GitHub's Markdown renders.
std::string summary_cell(const std::string& text) {
  return replace_each(text, "|\r\n<>&", {"\\|", " ", " ", "&lt;", "&gt;", "&amp;"});
}

std::string case_title(const RegressOptions& o, const CaseResult& r) {
  return (o.label.empty() ? "" : o.label + "/") + r.regress_case.id();
}

std::string scene_file_of(const RegressRun& run, const CaseResult& r) {
  const size_t i = r.regress_case.scene_index;
  return i < run.scene_files.size() ? run.scene_files[i] : r.regress_case.scene;
}

bool annotated(const CaseResult& r) {
  return is_failure(r.status) || r.status == CaseStatus::kWarn;
}

}  // namespace

std::string github_escape_data(const std::string& text) {
  return replace_each(text, "%\r\n", {"%25", "%0D", "%0A"});
}

std::string github_escape_property(const std::string& text) {
  return replace_each(text, "%\r\n:,", {"%25", "%0D", "%0A", "%3A", "%2C"});
}

std::string github_annotations(const RegressOptions& o, const RegressRun& run) {
  std::string lines;
  for (const CaseResult& r : run.results) {
    if (!annotated(r)) continue;
    lines += std::string(is_failure(r.status) ? "::error" : "::warning") +
             " file=" + github_escape_property(scene_file_of(run, r)) +
             ",title=" + github_escape_property(case_title(o, r)) + "::" +
             github_escape_data(r.status == CaseStatus::kWarn || r.status == CaseStatus::kFail
                                    ? r.message
                                    : std::string(to_string(r.status)) + ": " + r.message) +
             "\n";
  }
  return lines;
}

std::string github_step_summary(const RegressOptions& o, const RegressRun& run) {
  size_t failed = 0;
  for (const CaseResult& r : run.results) failed += is_failure(r.status);
  std::string s =
      "### ltrender regress" + (o.label.empty() ? "" : ": " + summary_cell(o.label)) + "\n\n";
  s += "| cases | pass | warn | fail | skipped |\n|---:|---:|---:|---:|---:|\n";
  s += "| " + std::to_string(run.results.size()) + " | " +
       std::to_string(run.count(CaseStatus::kPass)) + " | " +
       std::to_string(run.count(CaseStatus::kWarn)) + " | " + std::to_string(failed) + " | " +
       std::to_string(run.count(CaseStatus::kSkipped)) + " |\n\n";
  bool any = false;
  for (const CaseResult& r : run.results) {
    if (!annotated(r)) continue;
    if (!any)
      s += "| case | status | max LSB | edge-shift pixels | shading pixels | shading max LSB | "
           "message |\n|---|---|---:|---:|---:|---:|---|\n";
    any = true;
    const bool figures = r.figures.has_value();
    s += "| " + summary_cell(case_title(o, r)) + " | " + to_string(r.status) + " | " +
         (figures ? fixed(r.figures->max_lsb, 2) : "") + " | " +
         (figures ? std::to_string(r.verdict.edge_shift_pixels) : "") + " | " +
         (figures ? std::to_string(r.verdict.shading_pixels) : "") + " | " +
         (figures ? fixed(r.verdict.shading_max_lsb, 2) : "") + " | " + summary_cell(r.message) +
         " |\n";
  }
  return s + (any ? "\n" : "") + summary_cell(regress_summary(o, run)) + "\n";
}

void report_to_github(const RegressOptions& o, const RegressRun& run) {
  std::fputs(github_annotations(o, run).c_str(), stdout);
  std::fflush(stdout);
  const char* summary = std::getenv("GITHUB_STEP_SUMMARY");
  if (!summary || !*summary) return;
  std::ofstream out(summary, std::ios::app | std::ios::binary);
  out << github_step_summary(o, run);
  out.flush();
  if (!out)
    throw InputError("GITHUB_STEP_SUMMARY", summary, "cannot append the step summary to it");
}

bool github_ci_wanted(const std::string& ci) {
  if (ci == "github") return true;
  if (ci == "none") return false;
  if (ci != "auto") throw InputError("--ci", ci, "must be auto, github or none");
  const char* actions = std::getenv("GITHUB_ACTIONS");
  return actions && std::string(actions) == "true";
}

}  // namespace lt
