// Wall time for the figures commands report (bake's rays a second, regress's case times, the gx
// path's vertex/pixel split, bench's frame times): the steady clock, which no clock adjustment
// moves.
#pragma once

#include <chrono>

namespace lt {

using SteadyClock = std::chrono::steady_clock;

inline double seconds_since(SteadyClock::time_point start) {
  return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

}  // namespace lt
