#include "core/error.h"

namespace lt {

namespace {
std::string compose(const std::string& file, const std::string& where, const std::string& what) {
  std::string s = file;
  if (!where.empty()) s += ":" + where;
  return s + ": " + what;
}
}  // namespace

InputError::InputError(std::string file, std::string where, std::string what)
    : std::runtime_error(compose(file, where, what)),
      file_(std::move(file)),
      where_(std::move(where)),
      what_(std::move(what)) {}

std::string one_line(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  std::string out;
  for (char c : s) {
    if (c == '\0') {
      out += "\\0";
    } else {
      out += (c == '\n' || c == '\r') ? ' ' : c;
    }
  }
  return out;
}

void print_input_error(const std::string& what) {
  std::fprintf(stderr, "ltrender: error: %s\n", one_line(what).c_str());
}

void check_failed(const char* expr, const char* file, int line, const std::string& msg) {
  std::fprintf(stderr, "ltrender: internal error: %s:%d: CHECK(%s) failed: %s\n", file, line, expr,
               msg.c_str());
  std::abort();
}

}  // namespace lt
