#include "d3d9/d3d9_fxc_comment.h"

#include <regex>

namespace lt::d3d9 {

std::optional<FxcCount> fxc_count(const std::string& source) {
  static const std::regex unity(R"(^\s*;\s*(\d+) ALU(?:, (\d+) TEX)?)", std::regex::multiline);
  static const std::regex listing(
      R"(//\s*approximately (\d+) instruction slots? used(?: \((\d+) texture, (\d+) arithmetic\))?)");
  std::smatch m;
  if (std::regex_search(source, m, unity)) {
    FxcCount f;
    f.form = "; N ALU, M TEX";
    f.arithmetic = std::stoi(m[1]);
    if (m[2].matched) f.texture = std::stoi(m[2]);
    return f;
  }
  if (std::regex_search(source, m, listing)) {
    FxcCount f;
    f.form = "approximately N instruction slots used";
    f.slots = std::stoi(m[1]);
    // Without the parenthesis (a vertex shader) every slot is arithmetic.
    f.arithmetic = m[3].matched ? std::stoi(m[3]) : *f.slots;
    if (m[2].matched) f.texture = std::stoi(m[2]);
    return f;
  }
  return std::nullopt;
}

}  // namespace lt::d3d9
