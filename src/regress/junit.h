// JUnit XML of a regress run, in the shape GitLab's, Jenkins' and GitHub's test reporters read
// (the Ant JUnit schema): <testsuites> with one <testsuite> per scene, one <testcase> per case
// (classname "regress.SCENE", name "PATH:VARIANT"); a failed or missing case holds <failure>
// with the figures in its message and the figure table in its text, a skipped one <skipped>.
// A case that crashed or timed out is an <error>; one that warns passes with the warning as its
// <system-out>. A `label` (a platform's name) goes into every class name (regress.LABEL.SCENE)
// and suite name, so that two platforms' reports in one pipeline do not merge into one.
#pragma once

#include <string>

#include "regress/regress.h"

namespace lt {

std::string junit_xml(const RegressRun& run, const std::string& label = "");

}  // namespace lt
