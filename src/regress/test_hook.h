// A test hook of regress's workers (docs/regress.md "Test hook"): LTRENDER_REGRESS_TEST_HOOK
// names cases that abort or hang in the worker that runs them, so that ltrender's own tests can
// check that a crash or a hang costs that case and not the run. "abort@ID;hang@ID" (ID as
// `RegressCase::id()` prints it). Only workers read it: a run in one process never aborts for it.
#pragma once

#include <string>

namespace lt {

inline constexpr const char* kRegressTestHookVariable = "LTRENDER_REGRESS_TEST_HOOK";

// Aborts (SIGABRT) or sleeps until killed when the hook names `case_id`; returns otherwise.
void run_regress_test_hook(const std::string& case_id);

}  // namespace lt
