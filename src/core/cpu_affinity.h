// The cores this process may run on, and pinning it to one of them (bench, issue 11).
//
// On the 2-core virtual machines here, a bench spread over both cores did not repeat: where the
// scheduler put llvmpipe's threads, the CPU paths' workers and the main thread decided a figure,
// and that placement changed from process to process (reference on coloured_cubes read 13.0 to
// 15.8 times flat over five processes; pinned to one core, 9.9 to 10.7). A bench pinned to one
// core measures each path's work on that core, the same way every run; the other core takes the
// rest of the machine. docs/bench.md "How far the ratios repeat" has the measurements.
#pragma once

#include <vector>

namespace lt {

// The cores the calling thread may run on (its affinity mask), in increasing order; what a
// container or `taskset` allows, not every core of the machine.
std::vector<int> allowed_cores();

// How many cores the process may use: the size of allowed_cores(), at least 1.
unsigned usable_core_count();

// Sets the affinity of every thread of the process to `cores`: those running now (each task of
// /proc/self/task) and, since a new thread inherits its creator's mask, those started later
// (llvmpipe's, the CPU paths' workers). Returns whether the calling thread's was set.
bool set_process_cores(const std::vector<int>& cores);

// set_process_cores({core}); returns false, changing nothing, if `core` is not in
// allowed_cores().
bool pin_process_to_core(int core);

}  // namespace lt
