#include "paths/arbfp/arb_counter.h"

#include <cstring>
#include <set>

#include "paths/arbfp/arb_text_parser.h"

namespace lt::budget {

const char* to_string(ProgramKind k) {
  return k == ProgramKind::Vertex ? "vertex" : "fragment";
}

namespace {

using arbfp::text::Instruction;
using arbfp::text::Operand;
using arbfp::text::ParamSlot;
using arbfp::text::RegFile;

// A constant's identity for counting: its components and its size, compared as bits (as Mesa
// does, so -0 and 0 differ).
std::string constant_key(const ParamSlot& s) {
  std::string k = "const" + std::to_string(s.size);
  for (float v : s.values) {
    unsigned bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    k += ":" + std::to_string(bits);
  }
  return k;
}

// Texture indirections by the algorithm of ARB_fragment_program issue 24: a texture instruction
// starts a new indirection when its coordinate is a temporary written since the last one began,
// or when it overwrites a temporary an ALU instruction used since then.
int indirections(const std::vector<Instruction>& code) {
  int n = 1;
  std::set<int> written, alu_used;
  auto temp = [](const Operand& o) { return o.file == RegFile::Temp ? o.index : -1; };
  for (const Instruction& in : code) {
    const int dst = in.has_dst ? temp(in.dst) : -1;
    if (in.texture) {
      const int coord = temp(in.srcs.front());
      if ((coord >= 0 && written.count(coord)) || (dst >= 0 && alu_used.count(dst))) {
        ++n;
        written.clear();
        alu_used.clear();
      }
    } else {
      for (const Operand& s : in.srcs) {
        if (temp(s) >= 0) alu_used.insert(temp(s));
      }
      if (dst >= 0) alu_used.insert(dst);
    }
    if (dst >= 0) written.insert(dst);
  }
  return n;
}

// Mesa's parameter layout (src/mesa/program/prog_parameter_layout.c), replayed on the operands
// in instruction order: each referenced slot once; a relatively addressed array whole; a
// constant merged into an earlier constant holding all its components (a scalar: any one of
// them, _mesa_lookup_parameter_constant), and a new scalar packed into the first constant slot
// with a free component (_mesa_add_typed_unnamed_constant).
class MesaParameterLayout {
 public:
  explicit MesaParameterLayout(const arbfp::text::Program& p) : p_(p) {}

  int count(const std::vector<Instruction>& code) {
    for (const Instruction& in : code) {
      for (const Operand& o : in.srcs) add(o);
    }
    return static_cast<int>(slots_.size());
  }

 private:
  struct Slot {
    bool constant;
    std::vector<float> values;  // the components in use
    std::string binding;
  };

  void add(const Operand& o) {
    if (o.file == RegFile::InlineParam) return add_slot(o.slot);
    if (o.file != RegFile::Param) return;
    const auto& decl = p_.params[static_cast<size_t>(o.index)];
    if (o.element >= 0) return add_slot(decl.slots[static_cast<size_t>(o.element)]);
    // Relative addressing reads any element: the array is copied whole, once.
    if (!arrays_copied_.insert(o.index).second) return;
    for (const ParamSlot& s : decl.slots) {
      slots_.push_back({s.constant, {s.values.begin(), s.values.begin() + s.size}, s.binding});
    }
  }

  void add_slot(const ParamSlot& s) {
    if (!s.constant) {
      for (const Slot& e : slots_) {
        if (!e.constant && e.binding == s.binding) return;
      }
      slots_.push_back({false, {}, s.binding});
      return;
    }
    const std::vector<float> v(s.values.begin(), s.values.begin() + s.size);
    for (const Slot& e : slots_) {
      if (e.constant && e.values.size() >= v.size() && holds_all(e.values, v)) return;
    }
    if (v.size() == 1) {
      for (Slot& e : slots_) {
        if (e.constant && e.values.size() < 4) {
          e.values.push_back(v[0]);
          return;
        }
      }
    }
    slots_.push_back({true, v, ""});
  }

  static bool holds_all(const std::vector<float>& have, const std::vector<float>& want) {
    for (float w : want) {
      bool found = false;
      for (float h : have) found |= std::memcmp(&h, &w, sizeof h) == 0;
      if (!found) return false;
    }
    return true;
  }

  const arbfp::text::Program& p_;
  std::vector<Slot> slots_;
  std::set<int> arrays_copied_;
};

}  // namespace

ProgramCounts count_parsed(const arbfp::text::Program& p) {
  ProgramCounts c;
  c.kind = p.kind;
  std::set<std::string> attributes, inline_params;
  for (const Instruction& in : p.code) {
    // A vertex program has no texture instructions (the parser refuses them): all of it is ALU.
    ++(in.texture ? c.tex : c.alu);
    for (const Operand& o : in.srcs) {
      if (o.file == RegFile::Attrib) attributes.insert(o.binding);
      if (o.file == RegFile::InlineParam) {
        inline_params.insert(o.slot.constant ? constant_key(o.slot) : o.slot.binding);
      }
    }
  }
  c.temporaries = static_cast<int>(p.temps.size());
  c.address_registers = static_cast<int>(p.addresses.size());
  // Every declared slot (an array counts its size, used or not) plus each distinct constant or
  // binding written in an instruction: the ARB specs' PROGRAM_PARAMETERS bindings, an upper
  // bound of what any driver keeps.
  for (const auto& d : p.params) c.parameters += static_cast<int>(d.slots.size());
  c.parameters += static_cast<int>(inline_params.size());
  c.referenced_parameters = MesaParameterLayout(p).count(p.code);
  // Inputs the program reads (an ATTRIB that is declared and never read binds nothing).
  c.attributes = static_cast<int>(attributes.size());
  c.indirections = p.kind == ProgramKind::Fragment ? indirections(p.code) : 1;
  c.position_invariant = p.has_option("ARB_position_invariant");
  return c;
}

ProgramCounts count_program(const std::string& source) {
  return count_parsed(arbfp::text::parse(source));
}

}  // namespace lt::budget
