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
  int count(const arbfp::text::Program& p) {
    std::vector<std::vector<int>> decl_slots(p.params.size());
    std::vector<std::vector<int>> operand_slots(p.code.size());
    size_t next_decl = 0;
    for (size_t i = 0; i <= p.code.size(); ++i) {
      for (; next_decl < p.params.size() && p.params[next_decl].after_instructions <= i;
           ++next_decl) {
        const auto& d = p.params[next_decl];
        for (const ParamSlot& s : d.slots) {
          decl_slots[next_decl].push_back(parsed_.add(s, /*merge=*/!d.array));
        }
      }
      if (i == p.code.size()) break;
      for (const Operand& o : p.code[i].srcs) {
        operand_slots[i].push_back(o.file == RegFile::InlineParam ? parsed_.add(o.slot, true) : -1);
      }
    }
    List layout;
    std::set<int> arrays_copied;
    for (size_t i = 0; i < p.code.size(); ++i) {
      for (size_t k = 0; k < p.code[i].srcs.size(); ++k) {
        const Operand& o = p.code[i].srcs[k];
        if (o.file == RegFile::InlineParam) {
          layout.add(parsed_.as_slot(operand_slots[i][k]), true);
        } else if (o.file == RegFile::Param && o.element >= 0) {
          layout.add(parsed_.as_slot(
                         decl_slots[static_cast<size_t>(o.index)][static_cast<size_t>(o.element)]),
                     true);
        } else if (o.file == RegFile::Param && arrays_copied.insert(o.index).second) {
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

}  // namespace

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
  c.referenced_parameters = MesaParameterList().count(p);
  // Inputs the program reads (an ATTRIB that is declared and never read binds nothing).
  c.attributes = static_cast<int>(attributes.size());
  std::vector<TemporaryUse> uses;
  auto temp = [](const Operand& o) { return o.file == RegFile::Temp ? o.index : -1; };
  for (const Instruction& in : p.code) {
    TemporaryUse u{in.texture, in.has_dst ? temp(in.dst) : -1, -1, {}};
    for (const Operand& s : in.srcs) u.srcs.push_back(temp(s));
    if (in.texture) u.coord = u.srcs.front();
    uses.push_back(u);
  }
  c.indirections = p.kind == ProgramKind::Fragment ? texture_indirections(uses) : 1;
  c.position_invariant = p.has_option("ARB_position_invariant");
  return c;
}

ProgramCounts count_program(const std::string& source) {
  return count_parsed(arbfp::text::parse(source));
}

}  // namespace lt::budget
