// Rows of an image shared out over worker threads, one row at a time from a shared counter:
// each worker takes the next row not yet taken. Geometry is rarely spread evenly down an image,
// and on a shared machine a core can be taken away for part of a frame; with rows handed out
// as workers become free, a worker that is slowed (by its rows or by the machine) simply takes
// fewer of them. A fixed split (worker w takes rows w, w + n, ...) instead ended every frame
// with the slowest worker's share, so one descheduled thread stretched the whole frame (a
// noise the bench timed, issue 11). Used by every CPU per-pixel stage (the reference's and
// half's shading, the gx path's TEV).
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "core/cpu_affinity.h"

namespace lt {

// How many workers a CPU stage uses: 0 means every core the process may use (the default: one
// when the bench has pinned it to a core); `bench --cpu-threads` sets it before any path is
// built.
inline std::atomic<unsigned>& worker_threads_setting() {
  static std::atomic<unsigned> n{0};
  return n;
}

inline unsigned worker_threads() {
  const unsigned set = worker_threads_setting().load();
  return set > 0 ? set : usable_core_count();
}

// Calls row(y, worker) once for every y in [0, rows), worker < worker_threads(), so the caller
// can keep per-worker counters without locks. Which worker shades which row varies from call to
// call; what a row computes must not depend on it. Returns when every row is done.
template <class Row>
void for_each_row_in_parallel(int rows, Row&& row) {
  const unsigned n = worker_threads();
  std::atomic<int> next{0};
  auto work = [&](unsigned worker) {
    for (int y = next.fetch_add(1, std::memory_order_relaxed); y < rows;
         y = next.fetch_add(1, std::memory_order_relaxed))
      row(y, worker);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& t : pool) t.join();
}

}  // namespace lt
