#include "arb/arb_ir.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/error.h"

namespace lt::arbfp::ir {

Reg Reg::swz(const std::string& components) const {
  Reg r = *this;
  r.swizzle = components;
  return r;
}

Reg Reg::masked(const std::string& components) const {
  Reg r = *this;
  r.write_mask = components;
  return r;
}

Reg Reg::operator-() const {
  Reg r = *this;
  r.negate = !r.negate;
  return r;
}

Reg Reg::as_destination() const {
  Reg r = *this;
  r.write_mask = r.swizzle;
  r.swizzle.clear();
  r.negate = false;
  return r;
}

bool Reg::same_register(const Reg& o) const {
  if (file != o.file) return false;
  if (file == File::Literal) return false;  // each literal is its own (the counter merges)
  return file == File::Attrib || file == File::Output ? binding == o.binding : index == o.index;
}

Reg attrib(const std::string& binding) {
  Reg r;
  r.file = File::Attrib;
  r.binding = binding;
  return r;
}

Reg output(const std::string& binding) {
  Reg r;
  r.file = File::Output;
  r.binding = binding;
  return r;
}

const OpInfo& info(Op op) {
  // In enum order. Sources and the program kinds from the two specs' instruction tables.
  static const OpInfo kOps[] = {
      {"ABS", 1, false, true, true},  {"ADD", 2, false, true, true},
      {"ARL", 1, false, true, false}, {"CMP", 3, false, false, true},
      {"COS", 1, false, false, true}, {"DP3", 2, false, true, true},
      {"DP4", 2, false, true, true},  {"DPH", 2, false, true, true},
      {"DST", 2, false, true, true},  {"EX2", 1, false, true, true},
      {"EXP", 1, false, true, false}, {"FLR", 1, false, true, true},
      {"FRC", 1, false, true, true},  {"KIL", 1, true, false, true},
      {"LG2", 1, false, true, true},  {"LIT", 1, false, true, true},
      {"LOG", 1, false, true, false}, {"LRP", 3, false, false, true},
      {"MAD", 3, false, true, true},  {"MAX", 2, false, true, true},
      {"MIN", 2, false, true, true},  {"MOV", 1, false, true, true},
      {"MUL", 2, false, true, true},  {"POW", 2, false, true, true},
      {"RCP", 1, false, true, true},  {"RSQ", 1, false, true, true},
      {"SCS", 1, false, false, true}, {"SGE", 2, false, true, true},
      {"SIN", 1, false, false, true}, {"SLT", 2, false, true, true},
      {"SUB", 2, false, true, true},  {"SWZ", 1, false, true, true},
      {"TEX", 1, true, false, true},  {"TXB", 1, true, false, true},
      {"TXP", 1, true, false, true},  {"XPD", 2, false, true, true},
  };
  static_assert(sizeof kOps / sizeof kOps[0] == static_cast<size_t>(Op::XPD) + 1);
  return kOps[static_cast<size_t>(op)];
}

const char* header(ProgramKind kind) {
  return kind == ProgramKind::Vertex ? "!!ARBvp1.0" : "!!ARBfp1.0";
}

bool Program::has_option(const std::string& name) const {
  return std::find(options_.begin(), options_.end(), name) != options_.end();
}

std::vector<Instr> Program::instructions() const {
  std::vector<Instr> out;
  for (const auto& block : blocks_) {
    for (const Line& l : block) {
      if (l.kind == Line::Kind::Instr) out.push_back(instrs_[l.index]);
    }
  }
  return out;
}

const std::string& Program::name(const Reg& r) const {
  LT_CHECK(r.valid() && (r.file == File::Temp || r.file == File::Param || r.file == File::Address),
           "ARB IR: not a declared register");
  if (r.file == File::Temp) {
    LT_CHECK(static_cast<size_t>(r.index) < temps_.size(), "ARB IR: no such temporary");
    return temps_[static_cast<size_t>(r.index)];
  }
  if (r.file == File::Address) {
    LT_CHECK(static_cast<size_t>(r.index) < addresses_.size(), "ARB IR: no such address register");
    return addresses_[static_cast<size_t>(r.index)];
  }
  LT_CHECK(static_cast<size_t>(r.index) < params_.size(), "ARB IR: no such parameter");
  return params_[static_cast<size_t>(r.index)].name;
}

void Program::check_new_name(const std::string& name) const {
  LT_CHECK(!name.empty(), "ARB IR: a register needs a name");
  for (const std::string& t : temps_) LT_CHECK(t != name, "ARB IR: " + name + " declared twice");
  for (const Param& p : params_) LT_CHECK(p.name != name, "ARB IR: " + name + " declared twice");
  for (const std::string& a : addresses_) {
    LT_CHECK(a != name, "ARB IR: " + name + " declared twice");
  }
}

Reg Program::temp(const std::string& name) {
  check_new_name(name);
  temps_.push_back(name);
  Reg r;
  r.file = File::Temp;
  r.index = static_cast<int>(temps_.size() - 1);
  return r;
}

Reg Program::address(const std::string& name) {
  LT_CHECK(kind_ == ProgramKind::Vertex, "ARB IR: address registers are vertex programs'");
  check_new_name(name);
  addresses_.push_back(name);
  Reg r;
  r.file = File::Address;
  r.index = static_cast<int>(addresses_.size() - 1);
  return r;
}

Block Program::block() {
  blocks_.emplace_back();
  return Block(*this, blocks_.size() - 1);
}

// What the specs would reject, caught where the generator (or the parser) wrote it: an opcode the
// program kind lacks (CMP, _SAT and TEX in a vertex program), a wrong operand count, a
// destination that is swizzled or an input (ARL's: an address register), a source that is masked,
// an output or an address register, a register of no declaration.
void Program::check(const Instr& in) const {
  const OpInfo& oi = info(in.op);
  const bool vertex = kind_ == ProgramKind::Vertex;
  const std::string what = std::string("ARB IR: ") + oi.name;
  LT_CHECK(vertex ? oi.in_vertex : oi.in_fragment,
           what + " is not an instruction of " + budget::to_string(kind_) + " programs");
  LT_CHECK(!(vertex && in.saturate), what + "_SAT: vertex programs have no saturation");
  LT_CHECK(in.srcs.size() == static_cast<size_t>(oi.sources), what + ": wrong operand count");
  if (in.op != Op::KIL) {
    const bool arl = in.op == Op::ARL;
    LT_CHECK(in.dst.valid() && (arl ? in.dst.file == File::Address
                                    : in.dst.file == File::Temp || in.dst.file == File::Output),
             what + (arl ? ": the destination is an address register"
                         : ": the destination is a temporary or an output"));
    LT_CHECK(in.dst.swizzle.empty() && !in.dst.negate, what + ": a destination has a mask only");
    if (in.dst.file != File::Output) name(in.dst);
  }
  for (const Reg& s : in.srcs) {
    LT_CHECK(
        s.valid() && s.file != File::Output && s.file != File::Address && s.write_mask.empty(),
        what + ": a source is a declared register, an input or a literal, with a swizzle only");
    if (s.file == File::Temp || s.file == File::Param) name(s);
  }
  LT_CHECK(oi.texture == !in.texture_target.empty() || in.op == Op::KIL,
           what + ": texture instructions, and only they, name a texture target");
}

void Block::add(Program::Line line) {
  program_->blocks_[index_].push_back(std::move(line));
}

void Block::text(const std::string& lines) {
  // Only comments and blank lines: the counters skip text, so no code may hide in it.
  std::istringstream in(lines);
  for (std::string l; std::getline(in, l);) {
    LT_CHECK(l.empty() || l[0] == '#', "ARB IR: text line is not a comment: " + l);
  }
  LT_CHECK(!lines.empty() && lines.back() == '\n', "ARB IR: text must end with a newline");
  add({Program::Line::Kind::Text, lines, 0});
}

void Block::option(const std::string& name) {
  program_->options_.push_back(name);
  add({Program::Line::Kind::Option, "", program_->options_.size() - 1});
}

Reg Block::param(const std::string& name, const std::string& value, const std::string& comment) {
  Param d;
  d.name = name;
  d.value = value;
  d.comment = comment;
  return param(std::move(d));
}

Reg Block::param(Param declaration) {
  program_->check_new_name(declaration.name);
  declaration.after_instructions = program_->instrs_.size();
  program_->params_.push_back(std::move(declaration));
  add({Program::Line::Kind::Param, "", program_->params_.size() - 1});
  Reg r;
  r.file = File::Param;
  r.index = static_cast<int>(program_->params_.size() - 1);
  return r;
}

void Block::temps() {
  add({Program::Line::Kind::Temps, "", 0});
}

void Block::emit(Instr in) {
  program_->check(in);
  program_->instrs_.push_back(std::move(in));
  add({Program::Line::Kind::Instr, "", program_->instrs_.size() - 1});
}

void Block::op(Op op, const Reg& dst, std::vector<Reg> srcs, const std::string& comment) {
  Instr in;
  in.op = op;
  in.dst = dst;
  in.srcs = std::move(srcs);
  in.comment = comment;
  emit(std::move(in));
}

void Block::op_sat(Op op, const Reg& dst, std::vector<Reg> srcs) {
  Instr in;
  in.op = op;
  in.saturate = true;
  in.dst = dst;
  in.srcs = std::move(srcs);
  emit(std::move(in));
}

void Block::tex(const Reg& dst, const Reg& coord, int unit, const std::string& target) {
  Instr in;
  in.op = Op::TEX;
  in.dst = dst;
  in.srcs = {coord};
  in.texture_unit = unit;
  in.texture_target = target;
  emit(std::move(in));
}

namespace {

std::string operand(const Program& p, const Reg& r) {
  LT_CHECK(r.file != File::Literal && r.file != File::Address && r.element == 0,
           "ARB IR: print writes generated programs (a parsed one's text is its source)");
  std::string s = r.negate ? "-" : "";
  s += r.file == File::Attrib || r.file == File::Output ? r.binding : p.name(r);
  const std::string& c = r.write_mask.empty() ? r.swizzle : r.write_mask;
  if (!c.empty()) s.append(".").append(c);
  return s;
}

std::string instruction(const Program& p, const Instr& in) {
  std::string s = info(in.op).name;
  if (in.saturate) s += "_SAT";
  s += " ";
  std::vector<std::string> ops;
  if (in.op != Op::KIL) ops.push_back(operand(p, in.dst));
  for (const Reg& r : in.srcs) ops.push_back(operand(p, r));
  if (!in.texture_target.empty()) {
    ops.push_back("texture[" + std::to_string(in.texture_unit) + "]");
    ops.push_back(in.texture_target);
  }
  for (size_t i = 0; i < ops.size(); ++i) s.append(i ? ", " : "").append(ops[i]);
  s += ";";
  if (!in.comment.empty()) s.append("  # ").append(in.comment);
  return s + "\n";
}

}  // namespace

std::string print(const Program& p) {
  LT_CHECK(p.addresses_.empty(),
           "ARB IR: print writes generated programs (a parsed one's text is its source)");
  std::string s = header(p.kind());
  s += "\n";  // appended: GCC 12 warns (-Wrestrict) on the inlined operator+
  for (const auto& block : p.blocks_) {
    for (const Program::Line& l : block) {
      switch (l.kind) {
        case Program::Line::Kind::Text:
          s += l.text;
          break;
        case Program::Line::Kind::Option:
          s.append("OPTION ").append(p.options_[l.index]).append(";\n");
          break;
        case Program::Line::Kind::Param: {
          const Param& d = p.params_[l.index];
          LT_CHECK(d.slots.empty(),
                   "ARB IR: print writes generated programs (a parsed one's text is its source)");
          s.append("PARAM ").append(d.name).append(" = ").append(d.value).append(";");
          if (!d.comment.empty()) s.append("  # ").append(d.comment);
          s += "\n";
          break;
        }
        case Program::Line::Kind::Temps:
          if (p.temps_.empty()) break;
          s += "TEMP ";
          for (size_t i = 0; i < p.temps_.size(); ++i) s.append(i ? ", " : "").append(p.temps_[i]);
          s += ";\n";
          break;
        case Program::Line::Kind::Instr:
          s += instruction(p, p.instrs_[l.index]);
          break;
      }
    }
  }
  return s + "END\n";
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(static_cast<float>(v)));
  return buf;
}

std::string vec4(double x, double y, double z, double w) {
  // Appended, not "{" + ...: GCC 12 warns (-Wrestrict) on the inlined operator+ chain.
  std::string s = "{";
  s.append(num(x)).append(", ").append(num(y)).append(", ").append(num(z)).append(", ");
  return s.append(num(w)).append("}");
}

}  // namespace lt::arbfp::ir
