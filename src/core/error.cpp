#include "core/error.h"

namespace lt {

namespace {

// cli.md promises one error line, and library messages (OpenImageIO's "PNG read error: ...\nPNG
// library error") hold newlines: lines are joined with "; " where the error is made, so every
// consumer (the CLI, tests, report pages) sees the one line.
std::string one_line(const std::string& text) {
  std::string out;
  bool pending_break = false;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      pending_break = !out.empty();
      continue;
    }
    if (pending_break) {
      while (!out.empty() && out.back() == ' ') out.pop_back();
      if (!out.empty() && out.back() != ';' && out.back() != ':') out += ";";
      out += ' ';
      pending_break = false;
    }
    out += c;
  }
  return out;
}

std::string compose(const std::string& file, const std::string& where, const std::string& what) {
  std::string s = file;
  if (!where.empty()) s += ":" + where;
  return s + ": " + what;
}
}  // namespace

InputError::InputError(std::string file, std::string where, std::string what)
    : std::runtime_error(compose(file, where, one_line(what))),
      file_(std::move(file)),
      where_(std::move(where)),
      what_(one_line(what)) {}

void check_failed(const char* expr, const char* file, int line, const std::string& msg) {
  std::fprintf(stderr, "ltrender: internal error: %s:%d: CHECK(%s) failed: %s\n", file, line, expr,
               msg.c_str());
  std::abort();
}

}  // namespace lt
