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

void check_failed(const char* expr, const char* file, int line, const std::string& msg) {
  std::fprintf(stderr, "ltrender: internal error: %s:%d: CHECK(%s) failed: %s\n", file, line, expr,
               msg.c_str());
  std::abort();
}

}  // namespace lt
