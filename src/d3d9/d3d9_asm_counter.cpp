#include "d3d9/d3d9_asm_counter.h"

#include <algorithm>
#include <map>
#include <set>

namespace lt::d3d9 {

namespace {

// Dependent texture reads as "texld - ps_2_0 and up" orders them: a sampling instruction is
// first-order dependent when its coordinate src0 is a temporary r# or its destination was written
// before; n-th order when it reads or writes an r# whose contents depend (perhaps indirectly) on
// an (n-1)-th order one. So each r# holds the order its contents depend on (arithmetic: the
// highest of its sources; inputs and constants 0), and a read is one order above the deepest of
// its coordinate (an r#) and its earlier destination. Levels = 1 + the highest order, the first
// (non-dependent) level included, as ps_2_0's "4 levels" and ARB's indirections count them.
class DependentReads {
 public:
  void instruction(const Instruction& ins) {
    if (ins.info->kind == Kind::Setup || ins.destinations.empty()) return;
    const Register& d = ins.destinations.front().reg;
    int order = 0;
    if (ins.info->kind == Kind::Texture && !ins.sources.empty()) {
      const Register& coordinate = ins.sources.front().reg;
      const bool from_temporary = coordinate.type == "r";
      const bool rewritten = d.type == "r" && order_.count(d.index);
      if (from_temporary || rewritten) {
        order =
            1 + std::max(from_temporary ? order_of(coordinate) : 0, rewritten ? order_of(d) : 0);
      }
      levels_ = std::max(levels_, order + 1);
    } else {
      for (const Operand& s : ins.sources) order = std::max(order, order_of(s.reg));
    }
    if (d.type == "r") order_[d.index] = order;
  }
  int levels() const { return levels_; }

 private:
  int order_of(const Register& r) const {
    if (r.type != "r") return 0;
    const auto it = order_.find(r.index);
    return it == order_.end() ? 0 : it->second;
  }
  std::map<int, int> order_;  // r# -> the order its contents depend on
  int levels_ = 0;
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
      case Kind::Setup:
        break;
      case Kind::Arithmetic:
        c.arithmetic += n;
        break;
      case Kind::Texture:
        c.texture += n;
        break;
      case Kind::Flow:
        c.flow += n;
        break;
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
  c.dependent_levels = dependent.levels();
  return c;
}

}  // namespace lt::d3d9
