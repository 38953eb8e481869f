#include "paths/arbfp/arb_ir_counter.h"

#include <algorithm>
#include <set>

namespace lt::arbfp::ir {

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
  std::vector<budget::TemporaryUse> uses;
  auto temp = [](const Reg& r) { return r.file == File::Temp ? r.index : -1; };
  for (const Instr& in : code) {
    budget::TemporaryUse u{info(in.op).texture, in.op != Op::KIL ? temp(in.dst) : -1, -1, {}};
    for (const Reg& s : in.srcs) u.srcs.push_back(temp(s));
    if (u.texture) u.coord = u.srcs.front();
    uses.push_back(u);
  }
  c.indirections = p.kind() == ProgramKind::Fragment ? budget::texture_indirections(uses) : 1;
  const auto& o = p.options();
  c.position_invariant = std::find(o.begin(), o.end(), "ARB_position_invariant") != o.end();
  return c;
}

}  // namespace lt::arbfp::ir
