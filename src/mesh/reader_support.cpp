#include "mesh/reader_support.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/error.h"
#include "core/fs.h"

namespace lt::meshio {

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

bool parse_double(std::string_view token, double& out) {
  if (token.empty() || token.size() > 256) return false;
  std::string s(token);
  char* end = nullptr;
  errno = 0;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

bool parse_int(std::string_view token, long long& out) {
  if (token.empty() || token.size() > 32) return false;
  std::string s(token);
  char* end = nullptr;
  errno = 0;
  out = std::strtoll(s.c_str(), &end, 10);
  return end == s.c_str() + s.size() && errno != ERANGE;
}

bool fits_openmesh_float(double v) {
  return std::isfinite(v) && std::fabs(v) <= static_cast<double>(std::numeric_limits<float>::max());
}

std::vector<std::string_view> split_whitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

std::vector<std::string_view> split_lines(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string quoted(std::string_view token) {
  std::string s;
  s.reserve(token.size() + 2);
  s.append(1, '\'').append(token).append(1, '\'');
  return s;
}

std::string skip_utf8_bom(std::string& text) {
  if (!starts_with_utf8_bom(text)) return "";
  text.erase(0, kUtf8Bom.size());
  return "a UTF-8 byte-order mark starts the file: skipped";
}

void refuse_utf16(const std::string& text, const std::string& file) {
  if (text.rfind("\xFE\xFF", 0) == 0 || text.rfind("\xFF\xFE", 0) == 0)
    fail(file, 1, "UTF-16 text (it starts with a byte-order mark): save it as UTF-8 or ASCII");
}

[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& what) {
  throw InputError(file, line ? std::to_string(line) : "", what);
}

}  // namespace lt::meshio
