// JUnit XML of a regress run, in the shape GitLab's, Jenkins' and GitHub's test reporters read
// (the Ant JUnit schema): <testsuites> with one <testsuite> per scene, one <testcase> per case
// (classname "regress.SCENE", name "PATH:VARIANT"); a failed or missing case holds <failure>
// with the figures in its message and the figure table in its text, a skipped one <skipped>.
#pragma once

#include <string>

#include "regress/regress.h"

namespace lt {

std::string junit_xml(const RegressRun& run);

}  // namespace lt
