#include "arb/arb_text_parser.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include "arb/arb_text_bindings.h"
#include "arb/arb_text_cursor.h"
#include "arb/arb_text_grammar.h"
#include "arb/arb_text_operands.h"
#include "core/fs.h"

namespace lt::arbfp::text {

namespace {

using ir::File;
using ir::Reg;

class Parser {
 public:
  Parser(const std::string& source, const Limits& limits) : c_(tokenize(source)), limits_(limits) {}

  ir::Program run() {
    p_ = ir::Program(header());
    b_.emplace(p_.block());
    while (c_.peek().is("OPTION")) option();
    while (!c_.peek().is("END")) {
      if (c_.peek().kind == TokenKind::End) c_.expected("an instruction, a declaration or END");
      statement();
      c_.expect(";");
    }
    c_.take();
    if (c_.peek().kind != TokenKind::End) c_.expected("nothing after END");
    return std::move(p_);
  }

 private:
  struct Symbol {
    File file;
    int index = -1;
    std::string binding;
    Position at;
  };

  bool vertex() const { return p_.kind() == ProgramKind::Vertex; }

  ProgramKind header() {
    const Token& t = c_.peek();
    for (ProgramKind k : {ProgramKind::Fragment, ProgramKind::Vertex}) {
      if (t.is(ir::header(k))) {
        c_.take();
        return k;
      }
    }
    c_.expected("the header !!ARBvp1.0 or !!ARBfp1.0 at the start of the program");
  }

  void option() {
    c_.take();
    const Token& t = c_.expect_name("an option name");
    const bool known = known_option(t.text, vertex());
    if (!known) {
      Cursor::fail_at(t.at, std::string("expected an option of ") +
                                (vertex() ? "ARB_vertex_program (ARB_position_invariant)"
                                          : "ARB_fragment_program (ARB_precision_hint_fastest/"
                                            "nicest, ARB_fog_exp/exp2/linear, "
                                            "ARB_fragment_program_shadow, ARB_draw_buffers)") +
                                ", found '" + t.text + "'");
    }
    // ARB_fragment_program 3.11.4.1-2: the two precision hints exclude each other, and so do the
    // three fog options.
    auto family = [](const std::string& o) {
      if (o.rfind("ARB_precision_hint_", 0) == 0) return std::string("ARB_precision_hint_*");
      if (o.rfind("ARB_fog_", 0) == 0) return std::string("ARB_fog_*");
      return o;
    };
    for (const std::string& o : p_.options()) {
      // The same option twice is harmless (Mesa accepts it).
      if (o == t.text) {
        c_.expect(";");
        return;
      }
      if (family(o) == family(t.text)) {
        Cursor::fail_at(t.at, "expected at most one " + family(t.text) + " option (" + o +
                                  " was given before)");
      }
    }
    b_->option(t.text);
    c_.expect(";");
  }

  // ---- declarations ------------------------------------------------------------------------

  const Token& new_name() {
    const Token& t = c_.peek();
    if (t.kind != TokenKind::Name || reserved(t.text)) c_.expected("a new name");
    const auto it = names_.find(t.text);
    if (it != names_.end()) {
      c_.fail("expected a new name: '" + t.text + "' is already declared at line " +
              std::to_string(it->second.at.line) + ", column " +
              std::to_string(it->second.at.column));
    }
    return c_.take();
  }

  void declare(const Token& name, File file, int index, const std::string& binding) {
    names_[name.text] = Symbol{file, index, binding, name.at};
  }
  void declare(const Token& name, const Symbol& alias_of) {
    declare(name, alias_of.file, alias_of.index, alias_of.binding);
  }

  void statement() {
    const Token& t = c_.peek();
    if (t.is("OPTION")) c_.fail("expected an instruction or a declaration: OPTION must come first");
    if (t.is("TEMP") || t.is("ADDRESS")) return register_list();
    if (t.is("ATTRIB") || t.is("OUTPUT")) {
      // The binding parsers check the binding's root (fragment.* / vertex.*, result.*).
      const bool input = c_.take().is("ATTRIB");
      const Token& n = new_name();
      c_.expect("=");
      if (input) {
        declare(n, File::Attrib, -1, attrib_binding());
      } else {
        declare(n, File::Output, -1, result_binding());
      }
      return;
    }
    if (t.is("ALIAS")) {
      c_.take();
      const Token& n = new_name();
      c_.expect("=");
      const Token& target = c_.expect_name("a declared name");
      const auto it = names_.find(target.text);
      if (it == names_.end()) {
        Cursor::fail_at(target.at, "expected a declared name, found '" + target.text + "'");
      }
      declare(n, it->second);
      return;
    }
    if (t.is("PARAM")) return param();
    instruction();
  }

  void register_list() {
    const Token& kw = c_.take();
    const bool address = kw.is("ADDRESS");
    if (address && !vertex()) {
      Cursor::fail_at(kw.at,
                      "expected an instruction or a declaration of fragment programs "
                      "(ADDRESS is ARB_vertex_program's)");
    }
    do {
      const Token& n = new_name();
      const Reg r = address ? p_.address(n.text) : p_.temp(n.text);
      declare(n, r.file, r.index, "");
    } while (c_.accept(","));
  }

  // A PARAM's initialiser item: a constant, or a binding (`ranges`: may cover several slots).
  std::vector<ParamSlot> param_item(bool ranges) {
    const Token& t = c_.peek();
    if (t.is("{")) return {vector_constant(c_)};
    if (starts_number(c_) || ((t.is("-") || t.is("+")) && starts_number(c_, 1))) {
      // A declared scalar is replicated: PARAM k = 0.5 is (0.5, 0.5, 0.5, 0.5).
      ParamSlot s;
      s.constant = true;
      const float v = signed_number(c_);
      s.values = {v, v, v, v};
      return {s};
    }
    if (starts_param_binding(t)) return parse_param_binding(c_, p_.kind(), limits_, ranges);
    c_.expected("a constant, a state.* or a program.* binding");
  }

  void param() {
    c_.take();
    const Token& n = new_name();
    ir::Param d;
    d.name = n.text;
    if (c_.accept("[")) {
      d.array = true;
      int size = -1;
      Position size_at = c_.peek().at;
      if (!c_.peek().is("]")) size = c_.expect_index(1 << 20, "an array size");
      if (size == 0) Cursor::fail_at(size_at, "expected an array size of at least 1");
      c_.expect("]");
      c_.expect("=");
      c_.expect("{", "'{' and the array's items");
      do {
        for (ParamSlot& s : param_item(true)) d.slots.push_back(std::move(s));
      } while (c_.accept(","));
      c_.expect("}", "',' or '}'");
      if (size >= 0 && static_cast<int>(d.slots.size()) != size) {
        Cursor::fail_at(size_at, "expected " + std::to_string(d.slots.size()) +
                                     " as the array size: the initialiser has that many slots");
      }
    } else {
      c_.expect("=", "'=' or '['");
      d.slots = param_item(false);
    }
    declare(n, File::Param, b_->param(std::move(d)).index, "");
  }

  std::string attrib_binding() {
    const Position at = c_.peek().at;
    std::string b = parse_attrib_binding(c_, p_.kind(), limits_);
    const std::string named = named_alias_of_generic(b);
    const std::string other = named.empty() ? generic_of_named(b) : named;
    if (!other.empty() && attribs_seen_.count(other)) {
      Cursor::fail_at(at, "expected one name per vertex attribute: " + b + " and " + other +
                              " are the same attribute (ARB_vertex_program table X.2.1)");
    }
    attribs_seen_.insert(b);
    return b;
  }

  std::string result_binding() {
    return parse_result_binding(c_, p_.kind(), limits_, p_.has_option("ARB_draw_buffers"));
  }

  // ---- operands ----------------------------------------------------------------------------

  // c[n], c[A0.x], c[A0.x + n], c[A0.x - n]: the element, or -1 for relative addressing.
  int array_element(const ir::Param& d) {
    c_.expect("[", "'[' and an index: '" + d.name + "' is an array");
    int element = -1;
    if (c_.peek().kind == TokenKind::Name) {
      const Token& a = c_.take();
      const auto it = names_.find(a.text);
      if (!vertex() || it == names_.end() || it->second.file != File::Address) {
        Cursor::fail_at(
            a.at, vertex() ? "expected an index or an ADDRESS register, found '" + a.text + "'"
                           : "expected an index (relative addressing is "
                             "ARB_vertex_program's)");
      }
      const Token& dot = c_.expect(".", "'.x' after the address register");
      if (!c_.expect_attached_name(dot, "x, the address register's only component").is("x")) {
        Cursor::fail_at(dot.at, "expected .x, the address register's only component");
      }
      if (c_.peek().is("+") || c_.peek().is("-")) {
        c_.take();
        c_.expect_index(limits_.address_offset + 1, "an address offset");
      }
    } else {
      const Position at = c_.peek().at;
      element = c_.expect_index(1 << 20, "an array index");
      if (element >= static_cast<int>(d.slots.size())) {
        Cursor::fail_at(at, "expected an index below " + std::to_string(d.slots.size()) +
                                ", the size of '" + d.name + "'");
      }
    }
    c_.expect("]");
    return element;
  }

  // A source operand without its swizzle.
  Reg source_register() {
    Reg o;
    const Token& t = c_.peek();
    if (starts_number(c_)) {
      o.file = File::Literal;
      o.literal.constant = true;
      const float v = std::strtof(c_.take().text.c_str(), nullptr);
      o.literal.values = {v, v, v, v};
      o.literal.size = 1;
      return o;
    }
    if (t.is("{")) {
      o.file = File::Literal;
      o.literal = vector_constant(c_);
      return o;
    }
    if (starts_attrib_binding(t)) return ir::attrib(attrib_binding());
    if (starts_param_binding(t)) {
      o.file = File::Literal;
      o.literal = parse_param_binding(c_, p_.kind(), limits_, false).front();
      return o;
    }
    if (t.is("result")) c_.fail("expected a source register: outputs cannot be read");
    if (t.kind != TokenKind::Name) c_.expected("a source register");
    const auto it = names_.find(t.text);
    if (it == names_.end()) c_.fail("expected a declared name, found '" + t.text + "'");
    const Symbol s = it->second;
    c_.take();
    switch (s.file) {
      case File::Output:
        Cursor::fail_at(t.at, "expected a source register: '" + t.text +
                                  "' is an output, which cannot be read");
      case File::Address:
        Cursor::fail_at(t.at, "expected a source register: '" + t.text +
                                  "' is an address register (used only inside a[...])");
      case File::Attrib:
        // An ATTRIB name is a read of its binding: the alias check applies as for inline uses.
        attribs_seen_.insert(s.binding);
        return ir::attrib(s.binding);
      case File::Param: {
        o.file = File::Param;
        o.index = s.index;
        const ir::Param& d = p_.params()[static_cast<size_t>(s.index)];
        if (d.array) {
          o.element = array_element(d);
        } else if (c_.peek().is("[")) {
          c_.fail("expected no index: '" + t.text + "' is not an array");
        }
        return o;
      }
      default:
        o.file = s.file;
        o.index = s.index;
        return o;
    }
  }

  Reg source(bool scalar) {
    bool negate = false;
    if (c_.peek().is("-") || c_.peek().is("+")) negate = c_.take().is("-");
    Reg o = source_register();
    o.negate = negate;
    o.swizzle = swizzle(c_, vertex(), scalar);
    return o;
  }

  Reg destination() {
    const Token& t = c_.peek();
    Reg o;
    if (t.is("result")) {
      o = ir::output(result_binding());
    } else {
      const auto it = t.kind == TokenKind::Name ? names_.find(t.text) : names_.end();
      if (it == names_.end() ||
          (it->second.file != File::Temp && it->second.file != File::Output)) {
        c_.expected("a temporary or an output as the destination");
      }
      c_.take();
      o.file = it->second.file;
      o.index = it->second.index;
      o.binding = it->second.binding;
    }
    o.write_mask = write_mask(c_, vertex());
    return o;
  }

  void texture_operands(ir::Instr& in) {
    c_.expect(",");
    c_.expect("texture", "texture[n]");
    in.texture_unit = 0;
    if (c_.accept("[")) {
      in.texture_unit = c_.expect_index(limits_.texture_image_units, "a texture image unit");
      c_.expect("]");
    }
    c_.expect(",");
    const Token& t = c_.peek();
    std::vector<std::string> targets = {"1D", "2D", "3D", "CUBE", "RECT"};
    if (p_.has_option("ARB_fragment_program_shadow")) {
      for (const char* s : {"SHADOW1D", "SHADOW2D", "SHADOWRECT"}) targets.push_back(s);
    }
    if (t.kind != TokenKind::Name ||
        std::find(targets.begin(), targets.end(), t.text) == targets.end()) {
      c_.expected("a texture target (1D, 2D, 3D, CUBE, RECT" +
                  std::string(p_.has_option("ARB_fragment_program_shadow")
                                  ? ", SHADOW1D, SHADOW2D, SHADOWRECT)"
                                  : "; SHADOW* with OPTION ARB_fragment_program_shadow)"));
    }
    // ARB_fragment_program 3.11.6: one texture image unit is sampled with one target.
    const auto it = unit_targets_.find(in.texture_unit);
    if (it != unit_targets_.end() && it->second != t.text) {
      c_.fail("expected target " + it->second + " for texture[" + std::to_string(in.texture_unit) +
              "], as it is used before: one unit, one target");
    }
    unit_targets_[in.texture_unit] = t.text;
    in.texture_target = c_.take().text;
  }

  void instruction() {
    const Token& t = c_.peek();
    if (t.kind != TokenKind::Name) c_.expected("an instruction or a declaration");
    ir::Instr in;
    std::string name = t.text;
    if (name.size() > 4 && name.compare(name.size() - 4, 4, "_SAT") == 0) {
      name = name.substr(0, name.size() - 4);
      in.saturate = true;
    }
    const OpcodeInfo* op = find_opcode(name);
    const ir::OpInfo* oi = op ? &ir::info(op->op) : nullptr;
    if (!op || (in.saturate && vertex()) || !(vertex() ? oi->in_vertex : oi->in_fragment)) {
      const bool other_kind = op && !(in.saturate && vertex());
      c_.expected(
          std::string("an instruction or a declaration of ") + (vertex() ? "vertex" : "fragment") +
          " programs" +
          (other_kind
               ? " (" + name + " is ARB_" + (vertex() ? "fragment" : "vertex") + "_program's)"
               : (in.saturate && vertex() && op ? " (no _SAT in vertex programs)" : "")));
    }
    c_.take();
    in.op = op->op;
    switch (op->form) {
      case Form::Kill:
        in.srcs.push_back(source(false));
        break;
      case Form::Address: {
        const Token& a = c_.peek();
        const auto it = names_.find(a.text);
        if (a.kind != TokenKind::Name || it == names_.end() || it->second.file != File::Address) {
          c_.expected("an ADDRESS register as ARL's destination");
        }
        c_.take();
        in.dst.file = File::Address;
        in.dst.index = it->second.index;
        const Token& dot = c_.expect(".", "'.x': ARL writes the address register's x");
        if (!c_.expect_attached_name(dot, "x, the address register's only component").is("x")) {
          Cursor::fail_at(dot.at, "expected .x, the address register's only component");
        }
        in.dst.write_mask = "x";
        c_.expect(",");
        in.srcs.push_back(source(true));
        break;
      }
      case Form::Swizzle: {
        in.dst = destination();
        c_.expect(",");
        bool negate = false;
        if (c_.peek().is("-") || c_.peek().is("+")) negate = c_.take().is("-");
        Reg s = source_register();
        s.negate = negate;
        c_.expect(",", "',' and the extended swizzle");
        s.swizzle = extended_swizzle(c_, vertex());
        in.srcs.push_back(s);
        break;
      }
      case Form::Texture:
        in.dst = destination();
        c_.expect(",");
        in.srcs.push_back(source(false));
        texture_operands(in);
        break;
      case Form::Vector:
      case Form::Scalar:
        in.dst = destination();
        for (int k = 0; k < oi->sources; ++k) {
          c_.expect(",", k == 0 ? "','" : "',' and source " + std::to_string(k + 1));
          in.srcs.push_back(source(op->form == Form::Scalar));
        }
        break;
    }
    b_->emit(std::move(in));
  }

  Cursor c_;
  Limits limits_;
  ir::Program p_;
  std::optional<ir::Block> b_;  // the program's one block, from the header on
  std::map<std::string, Symbol> names_;
  std::set<std::string> attribs_seen_;
  std::map<int, std::string> unit_targets_;
};

}  // namespace

ir::Program parse(const std::string& source, const Limits& limits) {
  // Refused as Mesa refuses it (a byte >= 0x80 ends its text, so it finds no header), but named:
  // a Windows editor's mark is invisible, and "found the end of the program" would not say why.
  if (starts_with_utf8_bom(source)) {
    throw SyntaxError({1, 1},
                      "a UTF-8 byte-order mark stands before the header: Mesa reads it as the end "
                      "of the text and refuses the program (save the file without it)");
  }
  return Parser(source, limits).run();
}

}  // namespace lt::arbfp::text
