#include "paths/arbfp/arb_ir_counter.h"

#include <algorithm>
#include <set>

namespace lt::arbfp::ir {

namespace {

// Texture indirections by the algorithm of ARB_fragment_program issue 24: a texture instruction
// starts a new indirection when its coordinate is a temporary written since the last one began,
// or when it overwrites a temporary an ALU instruction used since then.
int indirections(const std::vector<Instr>& code) {
  int n = 1;
  std::set<int> written, alu_used;  // temporaries, by declaration index
  auto temp = [](const Reg& r) { return r.file == File::Temp ? r.index : -1; };
  for (const Instr& in : code) {
    const bool has_dst = in.op != Op::KIL;
    const int dst = has_dst ? temp(in.dst) : -1;
    if (info(in.op).texture) {
      const int coord = temp(in.srcs.front());
      if ((coord >= 0 && written.count(coord)) || (dst >= 0 && alu_used.count(dst))) {
        ++n;
        written.clear();
        alu_used.clear();
      }
    } else {
      for (const Reg& s : in.srcs) {
        if (temp(s) >= 0) alu_used.insert(temp(s));
      }
      if (dst >= 0) alu_used.insert(dst);
    }
    if (dst >= 0) written.insert(dst);
  }
  return n;
}

}  // namespace

budget::ProgramCounts count(const Program& p) {
  budget::ProgramCounts c;
  c.kind = p.kind();
  const std::vector<Instr> code = p.instructions();
  std::set<std::string> attributes;
  for (const Instr& in : code) {
    // A vertex program has no texture instructions (Program::check): all of it is ALU.
    ++(info(in.op).texture ? c.tex : c.alu);
    for (const Reg& s : in.srcs) {
      if (s.file == File::Attrib) attributes.insert(s.binding);
    }
  }
  c.temporaries = static_cast<int>(p.temps().size());
  // One slot per PARAM: the IR has no arrays, inline literals or direct state bindings.
  c.parameters = static_cast<int>(p.params().size());
  c.attributes = static_cast<int>(attributes.size());
  c.indirections = p.kind() == ProgramKind::Fragment ? indirections(code) : 1;
  const auto& o = p.options();
  c.position_invariant = std::find(o.begin(), o.end(), "ARB_position_invariant") != o.end();
  return c;
}

}  // namespace lt::arbfp::ir
