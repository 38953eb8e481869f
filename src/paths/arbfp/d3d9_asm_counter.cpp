#include "paths/arbfp/d3d9_asm_counter.h"

#include <algorithm>
#include <map>
#include <set>

namespace lt::d3d9 {

namespace {

// Dependent-read depth: an input (t#, v#) or a constant is 0; a register computed by arithmetic
// holds the deepest of its sources; a texture read whose coordinate is a computed register (not
// an input as it stands) is one level deeper than that register, and its result holds its level.
// So "texld r0, t0, s0" is level 0, "texld r1, r0, s1" level 1, as the documentation counts
// dependent reads (a read whose coordinates the shader computed) and as ARB_fragment_program
// issue 24 counts indirections (one more: its first node counts).
class DependentReads {
 public:
  void instruction(const Instruction& ins) {
    if (ins.info->kind == Kind::Setup || ins.destinations.empty()) return;
    int depth = 0;
    if (ins.info->kind == Kind::Texture && !ins.sources.empty()) {
      const Register& coordinate = ins.sources.front().reg;
      if (coordinate.type == "r") {
        depth = depth_of(coordinate) + 1;
        deepest_ = std::max(deepest_, depth);
      }
    } else {
      for (const Operand& s : ins.sources) depth = std::max(depth, depth_of(s.reg));
    }
    const Register& d = ins.destinations.front().reg;
    if (d.type == "r") depth_[d.index] = depth;
  }
  int deepest() const { return deepest_; }

 private:
  int depth_of(const Register& r) const {
    if (r.type != "r") return 0;
    const auto it = depth_.find(r.index);
    return it == depth_.end() ? 0 : it->second;
  }
  std::map<int, int> depth_;
  int deepest_ = 0;
};

}  // namespace

Counts count(const Program& program) {
  Counts c;
  std::set<int> samplers;
  std::set<int> inputs;
  DependentReads dependent;
  const bool pixel = is_pixel(program.version);
  // The inputs a profile limits: a 2_0/2_x pixel shader's texture coordinates (its two colour
  // registers v0, v1 are fixed), else the input registers v#.
  const std::string inputs_type = pixel && !is_model3(program.version) ? "t" : "v";
  for (const Instruction& ins : program.instructions) {
    const int n = slots(*ins.info, program.version, ins.compared);
    switch (ins.info->kind) {
      case Kind::Setup: break;
      case Kind::Arithmetic: c.arithmetic += n; break;
      case Kind::Texture: c.texture += n; break;
      case Kind::Flow: c.flow += n; break;
    }
    auto use = [&](const Register& r) {
      if (r.type == "r") c.temporaries = std::max(c.temporaries, r.index + 1);
      if (r.type == "c") {
        c.constants = std::max(c.constants, r.index + 1);
        c.relative_constants = c.relative_constants || r.relative;
      }
      if (r.type == "s") samplers.insert(r.index);
      if (r.type == inputs_type) inputs.insert(r.index);
    };
    for (const Operand& o : ins.destinations) use(o.reg);
    for (const Operand& o : ins.sources) use(o.reg);
    // m4x4 dst, src0, c0 reads c0..c3: a matrix macro's second source is its first row of as
    // many rows as the name's last digit ("m4x4 - vs": "src1 ... and the next three registers").
    const std::string& name = ins.info->name;
    if (name.size() == 4 && name[0] == 'm' && name[2] == 'x' && ins.sources.size() == 2) {
      Register last = ins.sources[1].reg;
      last.index += name[3] - '1';
      use(last);
    }
    if (pixel) dependent.instruction(ins);
  }
  c.samplers = static_cast<int>(samplers.size());
  c.inputs = static_cast<int>(inputs.size());
  c.dependent_reads = dependent.deepest();
  return c;
}

}  // namespace lt::d3d9
