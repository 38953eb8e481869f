#include "regress/shard.h"

#include <regex>

#include "core/error.h"

namespace lt {

Shard parse_shard(const std::string& text) {
  static const std::regex form("([0-9]{1,5})/([0-9]{1,5})");
  std::smatch m;
  if (std::regex_match(text, m, form)) {
    const Shard s{std::stoi(m[1]), std::stoi(m[2])};
    if (s.count >= 1 && s.count <= 10000 && s.index >= 1 && s.index <= s.count) return s;
  }
  throw InputError("--shard", text, "expects I/N with 1 <= I <= N <= 10000 (e.g. 2/4)");
}

}  // namespace lt
