// The bench's progress for a person watching a terminal: one line, redrawn in place, naming the
// phase, the step N of M, the scene, the path and variant, and about how long the phase has left.
// Nothing at all when the output is not a terminal (a CI log gets the notes and the result).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace lt {

// Seconds left in a phase of `total` steps of which `done` took `elapsed_s`, at the pace so far;
// none before the first step is done (nothing to go by).
std::optional<double> seconds_left(std::size_t done, std::size_t total, double elapsed_s);

// "about 2 min 10 s left", "about 40 s left", "" when `seconds` is empty.
std::string time_left_words(std::optional<double> seconds);

// "bench: timing (round 1 of 1) 12 of 80: backlit_sphere, gx t=vertex:lut=16, about 40 s left".
std::string progress_line(const std::string& phase, std::size_t step, std::size_t total,
                          const std::string& what, std::optional<double> seconds_left);

class BenchProgress {
 public:
  // live: draw the line (stderr is a terminal); notes: print notes (not --quiet).
  BenchProgress(bool live, bool notes, std::FILE* out = stderr);
  ~BenchProgress();
  BenchProgress(const BenchProgress&) = delete;
  BenchProgress& operator=(const BenchProgress&) = delete;

  // A phase of `total` steps; its clock starts now.
  void start_phase(std::string phase, std::size_t total);
  // Step `done + 1` of the phase is starting: `what` it is.
  void step(const std::string& what);
  // A line that stays (a skipped variant), above the progress line.
  void note(const std::string& line);

 private:
  void clear_line();

  bool live_, notes_;
  std::FILE* out_;
  std::string phase_;
  std::size_t total_ = 0, done_ = 0;
  std::chrono::steady_clock::time_point phase_start_;
  bool drawn_ = false;
};

}  // namespace lt
