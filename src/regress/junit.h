// JUnit XML of a regress run, in the shape GitLab's, Jenkins' and GitHub's test reporters read
// (the Ant JUnit schema): <testsuites> with one <testsuite> per scene, one <testcase> per case
// (classname "regress.SCENE", name "PATH:VARIANT"); a failed or missing case holds <failure>
// with the figures in its message and the figure table in its text, a skipped one <skipped>.
// A case that crashed or timed out is an <error>; one that warns passes with the warning as its
// <system-out>. A `label` (a platform's name) goes into every class name (regress.LABEL.SCENE)
// and suite name, so that two platforms' reports in one pipeline do not merge into one.
// With a report folder (`report_dir`), a failing or warned case whose images it kept lists them
// in its <system-out> as `[[ATTACHMENT|PATH]]` lines (render, golden, heatmap), which GitLab's
// unit test report shows in the merge request (it takes the first, for a failure or an error)
// and Jenkins' junit-attachments plugin (all of them); PATH as attachment_path says.
#pragma once

#include <filesystem>
#include <string>

#include "regress/regress.h"

namespace lt {

std::string junit_xml(const RegressRun& run, const std::string& label = "",
                      const std::filesystem::path& report_dir = {});

// An image of the report folder as an attachment names it. GitLab resolves the path from the
// project's folder, where its jobs run: a report folder given relative to it (`-o
// regress-report`) is kept as given; an absolute one is made relative to the current folder when
// it lies inside it, and kept absolute otherwise.
std::string attachment_path(const std::filesystem::path& report_dir, const std::string& image);

}  // namespace lt
