#include "arb/arb_ir_counter.h"

#include <cstring>
#include <set>

namespace lt::arbfp::ir {

namespace {

// A constant's identity for counting: its components and its size, compared as bits (as Mesa
// does, so -0 and 0 differ).
std::string constant_key(const ParamSlot& s) {
  std::string k = "const";
  k.append(std::to_string(s.size));
  for (float v : s.values) {
    unsigned bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    k.append(":").append(std::to_string(bits));
  }
  return k;
}

// Mesa's parameter list, replayed in its two steps (measured against NATIVE_PARAMETERS by the
// fuzz test). Parsing (program_parse.y) adds, in statement order: a single PARAM's constant
// merged into an earlier constant that holds all its components (any swizzle:
// _mesa_lookup_parameter_constant), an array's constants as new slots, state and program bindings
// once each, an instruction's constant merged like a single PARAM's, or a new scalar packed into
// the first constant slot with a free component (_mesa_add_typed_unnamed_constant). The layout
// (prog_parameter_layout.c) then keeps what instructions reference, in their order and with the
// same merging: a relatively addressed array whole, once.
class MesaParameterList {
 public:
  int count(const Program& p) {
    const std::vector<Param>& params = p.params();
    const std::vector<Instr> code = p.instructions();
    std::vector<std::vector<int>> decl_slots(params.size());
    std::vector<std::vector<int>> operand_slots(code.size());
    size_t next_decl = 0;
    for (size_t i = 0; i <= code.size(); ++i) {
      for (; next_decl < params.size() && params[next_decl].after_instructions <= i; ++next_decl) {
        const Param& d = params[next_decl];
        for (const ParamSlot& s : d.slots) {
          decl_slots[next_decl].push_back(parsed_.add(s, /*merge=*/!d.array));
        }
      }
      if (i == code.size()) break;
      for (const Reg& o : code[i].srcs) {
        operand_slots[i].push_back(o.file == File::Literal ? parsed_.add(o.literal, true) : -1);
      }
    }
    List layout;
    std::set<int> arrays_copied;
    for (size_t i = 0; i < code.size(); ++i) {
      for (size_t k = 0; k < code[i].srcs.size(); ++k) {
        const Reg& o = code[i].srcs[k];
        if (o.file == File::Literal) {
          layout.add(parsed_.as_slot(operand_slots[i][k]), true);
        } else if (o.file == File::Param && o.element >= 0) {
          layout.add(parsed_.as_slot(
                         decl_slots[static_cast<size_t>(o.index)][static_cast<size_t>(o.element)]),
                     true);
        } else if (o.file == File::Param && arrays_copied.insert(o.index).second) {
          for (int e : decl_slots[static_cast<size_t>(o.index)]) {
            layout.add(parsed_.as_slot(e), false);
          }
        }
      }
    }
    return layout.size();
  }

 private:
  class List {
   public:
    // The slot's index; `merge` looks for an earlier slot to share (constants) first.
    int add(const ParamSlot& s, bool merge) {
      if (!s.constant) {
        for (size_t e = 0; merge && e < slots_.size(); ++e) {
          if (!slots_[e].constant && slots_[e].binding == s.binding) return static_cast<int>(e);
        }
        slots_.push_back({false, {}, s.binding});
        return static_cast<int>(slots_.size() - 1);
      }
      const std::vector<float> v(s.values.begin(), s.values.begin() + s.size);
      for (size_t e = 0; merge && e < slots_.size(); ++e) {
        const Slot& have = slots_[e];
        if (have.constant && have.values.size() >= v.size() && holds_all(have.values, v)) {
          return static_cast<int>(e);
        }
      }
      for (size_t e = 0; merge && v.size() == 1 && e < slots_.size(); ++e) {
        if (slots_[e].constant && slots_[e].values.size() < 4) {
          slots_[e].values.push_back(v[0]);
          return static_cast<int>(e);
        }
      }
      slots_.push_back({true, v, ""});
      return static_cast<int>(slots_.size() - 1);
    }
    // Slot e as it stands now (a packed slot holds every scalar packed into it).
    ParamSlot as_slot(int e) const {
      const Slot& have = slots_[static_cast<size_t>(e)];
      ParamSlot s;
      s.constant = have.constant;
      s.binding = have.binding;
      s.size = static_cast<int>(have.values.size());
      for (size_t k = 0; k < have.values.size(); ++k) s.values[k] = have.values[k];
      return s;
    }
    int size() const { return static_cast<int>(slots_.size()); }

   private:
    struct Slot {
      bool constant;
      std::vector<float> values;  // the components in use
      std::string binding;
    };
    static bool holds_all(const std::vector<float>& have, const std::vector<float>& want) {
      for (float w : want) {
        bool found = false;
        for (float h : have) found |= std::memcmp(&h, &w, sizeof h) == 0;
        if (!found) return false;
      }
      return true;
    }
    std::vector<Slot> slots_;
  };

  List parsed_;
};

// What the texture-indirection count reads of one instruction: the temporaries (-1 for none or
// not a temporary).
struct TemporaryUse {
  bool texture = false;   // TEX, TXP, TXB, KIL
  int dst = -1;           // the destination temporary (none for KIL)
  int coord = -1;         // texture instructions: the coordinate's temporary
  std::vector<int> srcs;  // ALU instructions: the sources' temporaries
};

// Texture indirections by the algorithm of ARB_fragment_program issue 24: a texture instruction
// starts a new indirection when its coordinate is a temporary written since the last one began,
// or when it overwrites a temporary an ALU instruction used since then.
int texture_indirections(const std::vector<TemporaryUse>& code) {
  int n = 1;
  std::set<int> written, alu_used;
  for (const TemporaryUse& in : code) {
    if (in.texture) {
      if ((in.coord >= 0 && written.count(in.coord)) || (in.dst >= 0 && alu_used.count(in.dst))) {
        ++n;
        written.clear();
        alu_used.clear();
      }
    } else {
      for (int t : in.srcs) {
        if (t >= 0) alu_used.insert(t);
      }
      if (in.dst >= 0) alu_used.insert(in.dst);
    }
    if (in.dst >= 0) written.insert(in.dst);
  }
  return n;
}

}  // namespace

budget::ProgramCounts count(const Program& p) {
  budget::ProgramCounts c;
  c.kind = p.kind();
  const std::vector<Instr> code = p.instructions();
  std::set<std::string> attributes, literals;
  for (const Instr& in : code) {
    // A vertex program has no texture instructions (Program::check): all of it is ALU.
    ++(info(in.op).texture ? c.tex : c.alu);
    for (const Reg& s : in.srcs) {
      if (s.file == File::Attrib) attributes.insert(s.binding);
      if (s.file == File::Literal) {
        literals.insert(s.literal.constant ? constant_key(s.literal) : s.literal.binding);
      }
    }
  }
  c.temporaries = static_cast<int>(p.temps().size());
  c.address_registers = static_cast<int>(p.addresses().size());
  // Every declared slot (an array counts its size, used or not; a generated PARAM is one) plus
  // each distinct constant or binding written in an instruction: the ARB specs'
  // PROGRAM_PARAMETERS bindings, an upper bound of what any driver keeps.
  bool slots_known = true;
  for (const Param& d : p.params()) {
    c.parameters += d.slots.empty() ? 1 : static_cast<int>(d.slots.size());
    slots_known &= !d.slots.empty();
  }
  c.parameters += static_cast<int>(literals.size());
  if (slots_known) c.referenced_parameters = MesaParameterList().count(p);
  // Inputs the program reads (an ATTRIB that is declared and never read binds nothing).
  c.attributes = static_cast<int>(attributes.size());
  std::vector<TemporaryUse> uses;
  auto temp = [](const Reg& r) { return r.file == File::Temp ? r.index : -1; };
  for (const Instr& in : code) {
    TemporaryUse u{info(in.op).texture, in.op != Op::KIL ? temp(in.dst) : -1, -1, {}};
    for (const Reg& s : in.srcs) u.srcs.push_back(temp(s));
    if (u.texture) u.coord = u.srcs.front();
    uses.push_back(u);
  }
  c.indirections = p.kind() == ProgramKind::Fragment ? texture_indirections(uses) : 1;
  c.position_invariant = p.has_option("ARB_position_invariant");
  return c;
}

}  // namespace lt::arbfp::ir
