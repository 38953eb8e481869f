// The count fxc writes into its own listing, read as a second, outside figure beside ours:
// "; 28 ALU, 4 TEX" (the header of a compiled Unity shader's d3d9 subprogram: Unity keeps fxc's
// statistics there) and "// approximately 31 instruction slots used (4 texture, 27 arithmetic)"
// (the last line of `fxc /Fc`). Vertex shaders say "; 28 ALU" and "approximately 28 instruction
// slots used".
#pragma once

#include <optional>
#include <string>

namespace lt::d3d9 {

struct FxcCount {
  int arithmetic = 0;
  std::optional<int> texture;  // said for pixel shaders
  std::optional<int> slots;    // the "approximately N instruction slots used" form only
  std::string form;            // "; N ALU, M TEX" or "approximately N instruction slots used"
};

// The first such comment in the text; nullopt when there is none.
std::optional<FxcCount> fxc_count(const std::string& source);

}  // namespace lt::d3d9
