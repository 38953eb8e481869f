// Questions the generator tests ask of a generated program's instruction list (arb_ir.h), so
// they check what the program does ("no POW", "1 TEX", "writes result.texcoord[3].xy") rather
// than how its text happens to name registers.
#pragma once

#include <algorithm>
#include <string>

#include "arb/arb_ir.h"

namespace lt::test {

inline int count_op(const arbfp::ir::Program& p, arbfp::ir::Op op) {
  const auto code = p.instructions();
  return static_cast<int>(
      std::count_if(code.begin(), code.end(), [op](const auto& in) { return in.op == op; }));
}

inline bool has_op(const arbfp::ir::Program& p, arbfp::ir::Op op) {
  return count_op(p, op) > 0;
}

// MULs of a register by itself (same swizzle and sign): t^k's repeated squaring.
inline int count_squarings(const arbfp::ir::Program& p) {
  int n = 0;
  for (const arbfp::ir::Instr& in : p.instructions()) {
    if (in.op != arbfp::ir::Op::MUL) continue;
    const arbfp::ir::Reg &a = in.srcs[0], &b = in.srcs[1];
    n += a.same_register(b) && a.swizzle == b.swizzle && a.negate == b.negate;
  }
  return n;
}

// Any instruction saturates (_SAT).
inline bool saturates(const arbfp::ir::Program& p) {
  const auto code = p.instructions();
  return std::any_of(code.begin(), code.end(), [](const auto& in) { return in.saturate; });
}

// Some instruction writes output `binding` with exactly `mask` ("" for all components).
inline bool writes_output(const arbfp::ir::Program& p, const std::string& binding,
                          const std::string& mask = "") {
  for (const arbfp::ir::Instr& in : p.instructions()) {
    if (in.dst.file == arbfp::ir::File::Output && in.dst.binding == binding &&
        in.dst.write_mask == mask) {
      return true;
    }
  }
  return false;
}

// Some instruction reads input `binding`; with `swizzle`, exactly that swizzle.
inline bool reads_attrib(const arbfp::ir::Program& p, const std::string& binding,
                         const std::string& swizzle = "*") {
  for (const arbfp::ir::Instr& in : p.instructions()) {
    for (const arbfp::ir::Reg& s : in.srcs) {
      if (s.file == arbfp::ir::File::Attrib && s.binding == binding &&
          (swizzle == "*" || s.swizzle == swizzle)) {
        return true;
      }
    }
  }
  return false;
}

// The program declares a PARAM of that name.
inline bool declares_param(const arbfp::ir::Program& p, const std::string& name) {
  const auto& params = p.params();
  return std::any_of(params.begin(), params.end(), [&](const auto& d) { return d.name == name; });
}

}  // namespace lt::test
