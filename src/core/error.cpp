#include "core/error.h"

#include <cstddef>

namespace lt {

namespace {

// cli.md promises one error line, and library messages (OpenImageIO's "PNG read error: ...\nPNG
// library error") hold newlines: lines are joined with "; " where the error is made, so every
// consumer (the CLI, tests, report pages) sees the one line.
std::string join_lines(const std::string& text) {
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
    : std::runtime_error(compose(file, where, join_lines(what))),
      file_(std::move(file)),
      where_(std::move(where)),
      what_(join_lines(what)) {}

// cli.md promises one line of bounded length: a NUL would end the printed line early, and a
// message quoting a generated program or a corrupt file's bytes can run to kilobytes.
constexpr std::size_t kMaxMessage = 1000;

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
  if (out.size() > kMaxMessage) {
    const std::size_t cut = out.size() - kMaxMessage;
    out.resize(kMaxMessage);
    out += "... (" + std::to_string(cut) + " more characters)";
  }
  return out;
}

void print_input_error(const std::string& what) {
  std::fprintf(stderr, "ltrender: error: %s\n", one_line(what).c_str());
}

void print_warning(const std::string& what) {
  std::fprintf(stderr, "ltrender: warning: %s\n", one_line(what).c_str());
}

void check_failed(const char* expr, const char* file, int line, const std::string& msg) {
  std::fprintf(stderr, "ltrender: internal error: %s:%d: CHECK(%s) failed: %s\n", file, line, expr,
               msg.c_str());
  std::abort();
}

}  // namespace lt
