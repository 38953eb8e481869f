// Rows of an image shared out over worker threads, interleaved (worker w takes rows w, w + n,
// ...): geometry is rarely spread evenly down an image, so interleaving balances the load
// better than bands. Used by every CPU per-pixel stage (the reference's and half's shading, the
// gx path's TEV).
#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace lt {

// Every core.
inline unsigned worker_threads() {
  return std::max(1u, std::thread::hardware_concurrency());
}

// Calls row(y, worker) for every y in [0, rows), worker < worker_threads(), so the caller can
// keep per-worker counters without locks. Returns when every row is done.
template <class Row>
void for_each_row_interleaved(int rows, Row&& row) {
  const unsigned n = worker_threads();
  auto work = [&](unsigned worker) {
    for (int y = static_cast<int>(worker); y < rows; y += static_cast<int>(n)) row(y, worker);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& t : pool) t.join();
}

}  // namespace lt
