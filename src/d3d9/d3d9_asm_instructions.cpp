#include "d3d9/d3d9_asm_instructions.h"

#include <array>
#include <vector>

namespace lt::d3d9 {

namespace {

constexpr int kNo = -1;  // the version lacks the instruction
constexpr int kVersions = 7;

// Slots per version in the order of Version: vs_1_1, vs_2_0, vs_2_x, vs_3_0, ps_2_0, ps_2_x,
// ps_3_0.
using Slots = std::array<int, kVersions>;

struct Entry {
  InstructionInfo info;
  int sources;
  Slots slots;
};

// clang-format off
const std::vector<Entry>& table() {
  static const std::vector<Entry> entries = {
      // Setup: no slots in any version.
      {{"def", Kind::Setup}, 4, {0, 0, 0, 0, 0, 0, 0}},
      // defi and defb come with the integer and boolean registers: vs_2_0 and ps_2_x up.
      {{"defi", Kind::Setup}, 4, {kNo, 0, 0, 0, kNo, 0, 0}},
      {{"defb", Kind::Setup}, 1, {kNo, 0, 0, 0, kNo, 0, 0}},
      {{"dcl", Kind::Setup}, 0, {0, 0, 0, 0, 0, 0, 0}},
      // Arithmetic, one slot each unless the tables say more.
      {{"abs"}, 1, {kNo, 1, 1, 1, 1, 1, 1}},
      {{"add"}, 2, {1, 1, 1, 1, 1, 1, 1}},
      {{"cmp"}, 3, {kNo, kNo, kNo, kNo, 1, 1, 1}},
      {{"crs"}, 2, {kNo, 2, 2, 2, 2, 2, 2}},
      {{"dp2add"}, 3, {kNo, kNo, kNo, kNo, 2, 2, 2}},
      {{"dp3"}, 2, {1, 1, 1, 1, 1, 1, 1}},
      {{"dp4"}, 2, {1, 1, 1, 1, 1, 1, 1}},
      {{"dst"}, 2, {1, 1, 1, 1, kNo, kNo, kNo}},
      // vs_1_1's exp and log are full-precision macros of 10 slots; from vs_2_0 on, 1.
      {{"exp"}, 1, {10, 1, 1, 1, 1, 1, 1}},
      {{"expp"}, 1, {1, 1, 1, 1, kNo, kNo, kNo}},
      // frc: vs_1_1's table gives 3 slots (a macro); vs_2_0's table gives 1, but fxc counts 3
      // for vs_2_0: its "; N ALU" comment is 2 more per frc than a 1-slot count, and equal with
      // 3, on every vs_2_0 program with frc of the corpus's source (59 of 365; 6 of them in
      // tests/data/d3d9). We count what the compiler holds a program to (vs_2_x as vs_2_0: no
      // program to say otherwise); vs_3_0's table and fxc say 1.
      {{"frc"}, 1, {3, 3, 3, 1, 1, 1, 1}},
      {{"lit"}, 1, {3, 3, 3, 3, kNo, kNo, kNo}},
      {{"log"}, 1, {10, 1, 1, 1, 1, 1, 1}},
      {{"logp"}, 1, {1, 1, 1, 1, kNo, kNo, kNo}},
      {{"lrp"}, 3, {kNo, 2, 2, 2, 2, 2, 2}},
      {{"m3x2"}, 2, {2, 2, 2, 2, 2, 2, 2}},
      {{"m3x3"}, 2, {3, 3, 3, 3, 3, 3, 3}},
      {{"m3x4"}, 2, {4, 4, 4, 4, 4, 4, 4}},
      {{"m4x3"}, 2, {3, 3, 3, 3, 3, 3, 3}},
      {{"m4x4"}, 2, {4, 4, 4, 4, 4, 4, 4}},
      {{"mad"}, 3, {1, 1, 1, 1, 1, 1, 1}},
      {{"max"}, 2, {1, 1, 1, 1, 1, 1, 1}},
      {{"min"}, 2, {1, 1, 1, 1, 1, 1, 1}},
      {{"mov"}, 1, {1, 1, 1, 1, 1, 1, 1}},
      // vs_1_1 loads a0 with mov; mova is vs_2_0's.
      {{"mova"}, 1, {kNo, 1, 1, 1, kNo, kNo, kNo}},
      {{"mul"}, 2, {1, 1, 1, 1, 1, 1, 1}},
      {{"nop", Kind::Arithmetic, false}, 0, {1, 1, 1, 1, 1, 1, 1}},
      {{"nrm"}, 1, {kNo, 3, 3, 3, 3, 3, 3}},
      {{"pow"}, 2, {kNo, 3, 3, 3, 3, 3, 3}},
      {{"rcp"}, 1, {1, 1, 1, 1, 1, 1, 1}},
      {{"rsq"}, 1, {1, 1, 1, 1, 1, 1, 1}},
      {{"sge"}, 2, {1, 1, 1, 1, kNo, kNo, kNo}},
      {{"sgn"}, 3, {kNo, 3, 3, 3, kNo, kNo, kNo}},
      // sincos: 8 slots wherever it exists; its sources are in source_count().
      {{"sincos"}, 1, {kNo, 8, 8, 8, 8, 8, 8}},
      {{"slt"}, 2, {1, 1, 1, 1, kNo, kNo, kNo}},
      // Gradients: ps_2_x (D3DPS20CAPS_GRADIENTINSTRUCTIONS) and ps_3_0, 2 slots in both tables.
      {{"dsx"}, 1, {kNo, kNo, kNo, kNo, kNo, 2, 2}},
      {{"dsy"}, 1, {kNo, kNo, kNo, kNo, kNo, 2, 2}},
      {{"setp", Kind::Arithmetic, true, true}, 2, {kNo, kNo, 1, 1, kNo, 1, 1}},
      // Texture: pixel shaders' texture slots (ps_2_0 counts texkill as one, as ARB counts KIL).
      {{"texld", Kind::Texture}, 2, {kNo, kNo, kNo, kNo, 1, 1, 1}},
      {{"texldb", Kind::Texture}, 2, {kNo, kNo, kNo, kNo, 1, 1, 1}},
      {{"texldp", Kind::Texture}, 2, {kNo, kNo, kNo, kNo, 1, 1, 1}},
      {{"texkill", Kind::Texture, false}, 1, {kNo, kNo, kNo, kNo, 1, 1, 1}},
      {{"texldd", Kind::Texture}, 4, {kNo, kNo, kNo, kNo, kNo, 3, 3}},
      {{"texldl", Kind::Texture}, 2, {kNo, kNo, kNo, 2, kNo, kNo, 2}},
      // Flow control: static from vs_2_0 and ps_2_x, dynamic (comparisons, predicates, break)
      // from vs_2_x and ps_2_x; loop/endloop in pixel shaders only from ps_3_0.
      {{"if", Kind::Flow, false, true}, 1, {kNo, 3, 3, 3, kNo, 3, 3}},
      {{"else", Kind::Flow, false}, 0, {kNo, 1, 1, 1, kNo, 1, 1}},
      {{"endif", Kind::Flow, false}, 0, {kNo, 1, 1, 1, kNo, 1, 1}},
      {{"rep", Kind::Flow, false}, 1, {kNo, 3, 3, 3, kNo, 3, 3}},
      {{"endrep", Kind::Flow, false}, 0, {kNo, 2, 2, 2, kNo, 2, 2}},
      {{"loop", Kind::Flow, false}, 2, {kNo, 3, 3, 3, kNo, kNo, 3}},
      {{"endloop", Kind::Flow, false}, 0, {kNo, 2, 2, 2, kNo, kNo, 2}},
      {{"break", Kind::Flow, false, true}, 0, {kNo, kNo, 1, 1, kNo, 1, 1}},
      {{"breakp", Kind::Flow, false}, 1, {kNo, kNo, 3, 3, kNo, 3, 3}},
      {{"call", Kind::Flow, false}, 1, {kNo, 2, 2, 2, kNo, 2, 2}},
      {{"callnz", Kind::Flow, false}, 2, {kNo, 3, 3, 3, kNo, 3, 3}},
      {{"ret", Kind::Flow, false}, 0, {kNo, 1, 1, 1, kNo, 1, 1}},
      {{"label", Kind::Flow, false}, 1, {kNo, 0, 0, 0, kNo, 0, 0}},
  };
  return entries;
}
// clang-format on

const Entry& entry_of(const InstructionInfo& info) {
  for (const Entry& e : table()) {
    if (&e.info == &info) return e;
  }
  return table().front();  // unreachable: infos come from the table
}

}  // namespace

const InstructionInfo* find_instruction(const std::string& name) {
  for (const Entry& e : table()) {
    if (e.info.name == name) return &e.info;
  }
  return nullptr;
}

int slots(const InstructionInfo& info, Version version, bool compared) {
  const int n = entry_of(info).slots[static_cast<size_t>(version)];
  // break_comp is 3 slots where break is 1 (ps_2_x and vs_2_x tables); if_comp is if's 3.
  return compared && info.name == "break" && n != kNo ? 3 : n;
}

int source_count(const InstructionInfo& info, Version version, bool compared) {
  const Entry& e = entry_of(info);
  // sincos before shader model 3 names two constant registers holding the series' coefficients
  // (D3DSINCOSCONST1/2: "sincos - vs", "sincos - ps"); 3_0 dropped them.
  if (info.name == "sincos" && !is_model3(version)) return 3;
  // A comparison turns break into break_comp and if into if_comp: two operands compared.
  if (compared && (info.name == "break" || info.name == "if")) return 2;
  return e.sources;
}

std::string versions_with(const InstructionInfo& info) {
  std::string out;
  for (int v = 0; v < kVersions; ++v) {
    if (entry_of(info).slots[static_cast<size_t>(v)] == kNo) continue;
    out += (out.empty() ? "" : ", ") + to_string(static_cast<Version>(v));
  }
  return out;
}

}  // namespace lt::d3d9
