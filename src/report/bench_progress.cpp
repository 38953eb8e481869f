#include "report/bench_progress.h"

#include <cmath>

#include "core/stopwatch.h"

namespace lt {

std::optional<double> seconds_left(std::size_t done, std::size_t total, double elapsed_s) {
  if (done == 0 || done > total) return std::nullopt;
  return elapsed_s / static_cast<double>(done) * static_cast<double>(total - done);
}

std::string time_left_words(std::optional<double> seconds) {
  if (!seconds) return "";
  // Whole seconds under a minute; above it, to 10 s: the pace of the next rows is a guess, and
  // a figure that ticks every second reads as more precise than it is.
  const long s = std::lround(*seconds);
  if (s < 60) return "about " + std::to_string(s) + " s left";
  const long tens = (s + 5) / 10 * 10;
  return "about " + std::to_string(tens / 60) + " min " + std::to_string(tens % 60) + " s left";
}

std::string progress_line(const std::string& phase, std::size_t step, std::size_t total,
                          const std::string& what, std::optional<double> seconds) {
  std::string line =
      "bench: " + phase + " " + std::to_string(step) + " of " + std::to_string(total) + ": " + what;
  if (const std::string left = time_left_words(seconds); !left.empty()) line += ", " + left;
  return line;
}

BenchProgress::BenchProgress(bool live, bool notes, std::FILE* out)
    : live_(live), notes_(notes), out_(out) {}

BenchProgress::~BenchProgress() {
  clear_line();
}

void BenchProgress::start_phase(std::string phase, std::size_t total) {
  phase_ = std::move(phase);
  total_ = total;
  done_ = 0;
  phase_start_ = std::chrono::steady_clock::now();
}

void BenchProgress::step(const std::string& what) {
  if (!live_) return;
  const double elapsed = seconds_since(phase_start_);
  // A pace from under two seconds of work says little (the first rows' start-up dominates it).
  const std::optional<double> left =
      elapsed >= 2.0 ? seconds_left(done_, total_, elapsed) : std::nullopt;
  const std::string line = progress_line(phase_, done_ + 1, total_, what, left);
  ++done_;
  // \r and "erase to the end of the line" (ECMA-48 EL): the line is redrawn, never scrolled.
  std::fprintf(out_, "\r\033[K%s", line.c_str());
  std::fflush(out_);
  drawn_ = true;
}

void BenchProgress::note(const std::string& line) {
  if (!notes_) return;
  clear_line();
  std::fprintf(out_, "%s\n", line.c_str());
}

void BenchProgress::clear_line() {
  if (!drawn_) return;
  std::fprintf(out_, "\r\033[K");
  std::fflush(out_);
  drawn_ = false;
}

}  // namespace lt
