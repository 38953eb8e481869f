// Two kinds of failure, never mixed (pbrt's rule):
//  - InputError: the user's input is bad (file, key or line named). The CLI prints one line
//    `ltrender: error: <file>[:<where>]: <what>` and exits 2.
//  - LT_CHECK: our own bug. It prints both the condition and a message and aborts.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace lt {

class InputError : public std::runtime_error {
 public:
  // `where` is a key path ("materials.marble.translucency.power"), a line ("12") or empty.
  InputError(std::string file, std::string where, std::string what);

  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& what_only() const { return what_; }

 private:
  std::string file_, where_, what_;
};

// A check the user asked for failed (compare over threshold, budget exceeded): exit code 1.
class CheckFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// cli.md promises one line per error: newlines become spaces, a NUL prints as \0, and a message
// over 1,000 characters is cut, saying how many it left out.
std::string one_line(std::string s);
// Prints `ltrender: error: <what>` as one line on stderr (what main does for an InputError); for
// commands that go on after a bad input (budget of several files).
void print_input_error(const std::string& what);
// Prints `ltrender: warning: <what>` as one line on stderr: the input is used, but not as it
// stands (a primitive skipped, lights added).
void print_warning(const std::string& what);

[[noreturn]] void check_failed(const char* expr, const char* file, int line,
                               const std::string& msg);

}  // namespace lt

#define LT_CHECK(cond, msg)                                            \
  do {                                                                 \
    if (!(cond)) ::lt::check_failed(#cond, __FILE__, __LINE__, (msg)); \
  } while (0)
