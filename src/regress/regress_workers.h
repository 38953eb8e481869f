// Isolation of a regress run's cases (docs/regress.md "A case that crashes or hangs"): the cases
// run in worker processes, each a process of ltrender itself that runs many cases (a scene's at
// a time, in one GL context, as a run in one process does) and is replaced when one dies. A crash
// is the failure of the case the worker was rendering (`crashed`), a case past the deadline stops
// its worker (`timed out`); the run goes on with the next worker. Why processes that run many
// cases and not a process a case: a process and a GL context a case would cost more than the
// cases (docs/regress.md "Speed").
//
// Parent and worker speak over one socket, a JSON object a line: the parent sends
// {"scene": S, "cases": [ID, ...]}, the worker answers {"started": ID} before each case and
// {"result": RECORD} (case_record.h) after it.
#pragma once

#include <functional>
#include <vector>

#include "regress/regress.h"
#include "regress/regress_plan.h"

namespace lt {

// Runs plan.cases[i] for each i of `positions` (none skipped) in o.jobs workers started from
// o.worker_command, handing each result to `done` as it comes and calling `tick` at least every
// 100 ms while it waits. Throws std::runtime_error when workers die before their first case.
void run_in_workers(const RegressOptions& o, const RegressPlan& plan,
                    const std::vector<size_t>& positions,
                    const std::function<void(size_t position, CaseResult)>& done,
                    const std::function<void()>& tick);

// The worker's side: reads batches from `fd` until the parent closes it; returns the exit code.
// The worker reads the same options as its parent (it is started with the parent's command
// line), but only the scenes it is sent.
int run_regress_worker(const RegressOptions& o, int fd);

// The option that makes a regress process a worker, followed by the socket's descriptor.
inline constexpr const char* kRegressWorkerOption = "--regress-worker-fd";

}  // namespace lt
