// Wall time since `start`, in seconds, on the steady clock (which never jumps with the system
// clock): how every phase, render and bake is timed.
#pragma once

#include <chrono>

namespace lt {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lt
