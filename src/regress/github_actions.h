// A regress run as GitHub Actions shows it (docs/regress.md "In CI"): one `::error` workflow
// command per failing case and one `::warning` per warned case, which GitHub turns into
// annotations on the run and the pull request, and a Markdown table appended to the job's step
// summary ($GITHUB_STEP_SUMMARY). The same for a run and for `regress merge`'s merged run.
#pragma once

#include <string>

#include "regress/regress.h"

namespace lt {

// GitHub's workflow-commands doc: a command's message escapes '%', '\r' and '\n' (%25, %0D,
// %0A); a property (file=, title=) escapes ':' and ',' (%3A, %2C) too.
std::string github_escape_data(const std::string& text);
std::string github_escape_property(const std::string& text);

// The workflow commands, one line each ("\n"-terminated), in the run's case order.
std::string github_annotations(const RegressOptions& options, const RegressRun& run);

// The step summary: the counts, then one row per failing or warned case with its max, edge-shift
// and shading figures.
std::string github_step_summary(const RegressOptions& options, const RegressRun& run);

// Prints the annotations to stdout and appends the summary to the file $GITHUB_STEP_SUMMARY
// names (appended: the job's other steps write there too), when that variable is set. Throws
// InputError naming the variable when the file cannot be appended to.
void report_to_github(const RegressOptions& options, const RegressRun& run);

// --ci: `github` or `none`; `auto` (the default) is github where GitHub Actions runs the job
// (GITHUB_ACTIONS=true, which it sets in every step), as pytest's and other tools' annotation
// plugins decide. Throws InputError naming --ci for another value.
bool github_ci_wanted(const std::string& ci_option);

}  // namespace lt
