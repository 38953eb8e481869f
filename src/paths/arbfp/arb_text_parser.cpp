#include "paths/arbfp/arb_text_parser.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

#include "paths/arbfp/arb_text_bindings.h"
#include "paths/arbfp/arb_text_cursor.h"
#include "paths/arbfp/arb_text_grammar.h"

namespace lt::arbfp::text {

bool Program::has_option(const std::string& name) const {
  return std::find(options.begin(), options.end(), name) != options.end();
}

namespace {

bool valid_components(const std::string& s, const std::string& set) {
  return std::all_of(s.begin(), s.end(),
                     [&](char ch) { return set.find(ch) != std::string::npos; });
}

class Parser {
 public:
  Parser(const std::string& source, const Limits& limits) : c_(tokenize(source)), limits_(limits) {}

  Program run() {
    header();
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
    RegFile file;
    int index = -1;
    std::string binding;
    Position at;
  };

  bool vertex() const { return p_.kind == ProgramKind::Vertex; }

  void header() {
    const Token& t = c_.peek();
    if (t.is("!!ARBfp1.0")) {
      p_.kind = ProgramKind::Fragment;
    } else if (t.is("!!ARBvp1.0")) {
      p_.kind = ProgramKind::Vertex;
    } else {
      c_.expected("the header !!ARBvp1.0 or !!ARBfp1.0 at the start of the program");
    }
    p_.header = c_.take().text;
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
    for (const std::string& o : p_.options) {
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
    p_.options.push_back(t.text);
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

  void declare(const Token& name, RegFile file, int index, const std::string& binding) {
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
        declare(n, RegFile::Attrib, -1, attrib_binding());
      } else {
        declare(n, RegFile::Output, -1, result_binding());
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
      auto& list = address ? p_.addresses : p_.temps;
      declare(n, address ? RegFile::Address : RegFile::Temp, static_cast<int>(list.size()), "");
      list.push_back(n.text);
    } while (c_.accept(","));
  }

  float signed_number() {
    const bool negative = c_.peek().is("-");
    if (negative || c_.peek().is("+")) c_.take();
    const Token& t = c_.peek();
    if (t.kind != TokenKind::Integer && t.kind != TokenKind::Float) c_.expected("a number");
    c_.take();
    const float v = std::strtof(t.text.c_str(), nullptr);
    return negative ? -v : v;
  }

  // '{' a [, b [, c [, d]]] '}': missing components are (0, 0, 1) as in ARB_vertex_program
  // 2.14.3.4 ({x} is (x, 0, 0, 1)).
  ParamSlot vector_constant() {
    c_.expect("{");
    ParamSlot s;
    s.constant = true;
    s.values = {0, 0, 0, 1};
    int n = 0;
    do {
      if (n == 4) c_.expected("'}' (a vector has four components at most)");
      s.values[static_cast<size_t>(n++)] = signed_number();
    } while (c_.accept(","));
    c_.expect("}", "',' or '}'");
    return s;
  }

  bool starts_number(size_t ahead = 0) const {
    const Token& t = c_.peek(ahead);
    return t.kind == TokenKind::Integer || t.kind == TokenKind::Float;
  }

  // A PARAM's initialiser item: a constant, or a binding (`ranges`: may cover several slots).
  std::vector<ParamSlot> param_item(bool ranges) {
    const Token& t = c_.peek();
    if (t.is("{")) return {vector_constant()};
    if (starts_number() || ((t.is("-") || t.is("+")) && starts_number(1))) {
      // A declared scalar is replicated: PARAM k = 0.5 is (0.5, 0.5, 0.5, 0.5).
      ParamSlot s;
      s.constant = true;
      const float v = signed_number();
      s.values = {v, v, v, v};
      return {s};
    }
    if (starts_param_binding(t)) return parse_param_binding(c_, p_.kind, limits_, ranges);
    c_.expected("a constant, a state.* or a program.* binding");
  }

  void param() {
    c_.take();
    const Token& n = new_name();
    ParamDecl d;
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
    d.after_instructions = p_.code.size();
    declare(n, RegFile::Param, static_cast<int>(p_.params.size()), "");
    p_.params.push_back(std::move(d));
  }

  std::string attrib_binding() {
    const Position at = c_.peek().at;
    std::string b = parse_attrib_binding(c_, p_.kind, limits_);
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
    return parse_result_binding(c_, p_.kind, limits_, p_.has_option("ARB_draw_buffers"));
  }

  // ---- operands ----------------------------------------------------------------------------

  // ".mask" of a destination: components in xyzw order, each once (rgba too in fragment
  // programs).
  std::string write_mask() {
    if (!c_.peek().is(".")) return "";
    const Token& dot = c_.take();
    const Token& t = c_.expect_attached_name(dot, "a write mask (.x, .xy, .xyzw, ...)");
    const std::string sets[] = {"xyzw", "rgba"};
    for (const std::string& set : sets) {
      if (set == "rgba" && vertex()) continue;
      size_t last = 0;
      bool ok = !t.text.empty() && t.text.size() <= 4;
      for (size_t k = 0; ok && k < t.text.size(); ++k) {
        const size_t at = set.find(t.text[k]);
        ok = at != std::string::npos && (k == 0 || at > last);
        last = at;
      }
      if (ok) return t.text;
    }
    Cursor::fail_at(t.at, "expected a write mask: components of " +
                              std::string(vertex() ? "xyzw" : "xyzw or rgba") +
                              " in that order, each once; found '" + t.text + "'");
  }

  // ".x" or ".xyzw" of a source (one or four components, ARB_vertex_program 2.14.2.2).
  std::string swizzle(bool scalar) {
    if (!c_.peek().is(".")) {
      if (scalar) c_.expected("a scalar suffix (.x, .y, .z or .w)");
      return "";
    }
    const Token& dot = c_.take();
    const Token& t =
        c_.expect_attached_name(dot, scalar ? "a scalar suffix (.x, .y, .z or .w)" : "a swizzle");
    const bool xyzw = valid_components(t.text, "xyzw");
    const bool rgba = !vertex() && valid_components(t.text, "rgba");
    const size_t n = t.text.size();
    if (!(xyzw || rgba) || (scalar ? n != 1 : (n != 1 && n != 4))) {
      Cursor::fail_at(t.at, std::string("expected ") +
                                (scalar ? "one component" : "one or four components") + " of " +
                                (vertex() ? "xyzw" : "xyzw or rgba (not mixed)") + ", found '" +
                                t.text + "'");
    }
    return t.text;
  }

  // c[n], c[A0.x], c[A0.x + n], c[A0.x - n]: the element, or -1 for relative addressing.
  int array_element(const ParamDecl& d) {
    c_.expect("[", "'[' and an index: '" + d.name + "' is an array");
    int element = -1;
    if (c_.peek().kind == TokenKind::Name) {
      const Token& a = c_.take();
      const auto it = names_.find(a.text);
      if (!vertex() || it == names_.end() || it->second.file != RegFile::Address) {
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
  Operand source_register() {
    Operand o;
    const Token& t = c_.peek();
    if (starts_number()) {
      o.file = RegFile::InlineParam;
      o.slot.constant = true;
      const float v = std::strtof(c_.take().text.c_str(), nullptr);
      o.slot.values = {v, v, v, v};
      o.slot.size = 1;
      return o;
    }
    if (t.is("{")) {
      o.file = RegFile::InlineParam;
      o.slot = vector_constant();
      return o;
    }
    if (starts_attrib_binding(t)) {
      o.file = RegFile::Attrib;
      o.binding = attrib_binding();
      return o;
    }
    if (starts_param_binding(t)) {
      o.file = RegFile::InlineParam;
      o.slot = parse_param_binding(c_, p_.kind, limits_, false).front();
      return o;
    }
    if (t.is("result")) c_.fail("expected a source register: outputs cannot be read");
    if (t.kind != TokenKind::Name) c_.expected("a source register");
    const auto it = names_.find(t.text);
    if (it == names_.end()) c_.fail("expected a declared name, found '" + t.text + "'");
    const Symbol s = it->second;
    c_.take();
    switch (s.file) {
      case RegFile::Output:
        Cursor::fail_at(t.at, "expected a source register: '" + t.text +
                                  "' is an output, which cannot be read");
      case RegFile::Address:
        Cursor::fail_at(t.at, "expected a source register: '" + t.text +
                                  "' is an address register (used only inside a[...])");
      case RegFile::Attrib:
        o.file = RegFile::Attrib;
        o.binding = s.binding;
        // An ATTRIB name is a read of its binding: the alias check applies as for inline uses.
        attribs_seen_.insert(s.binding);
        return o;
      case RegFile::Param: {
        o.file = RegFile::Param;
        o.index = s.index;
        const ParamDecl& d = p_.params[static_cast<size_t>(s.index)];
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

  Operand source(bool scalar) {
    bool negate = false;
    if (c_.peek().is("-") || c_.peek().is("+")) negate = c_.take().is("-");
    Operand o = source_register();
    o.negate = negate;
    o.swizzle = swizzle(scalar);
    return o;
  }

  Operand destination() {
    const Token& t = c_.peek();
    Operand o;
    if (t.is("result")) {
      o.file = RegFile::Output;
      o.binding = result_binding();
    } else {
      const auto it = t.kind == TokenKind::Name ? names_.find(t.text) : names_.end();
      if (it == names_.end() ||
          (it->second.file != RegFile::Temp && it->second.file != RegFile::Output)) {
        c_.expected("a temporary or an output as the destination");
      }
      c_.take();
      o.file = it->second.file;
      o.index = it->second.index;
      o.binding = it->second.binding;
    }
    o.swizzle = write_mask();
    return o;
  }

  // SWZ's four components: 0, 1, or a component, each with an optional sign.
  std::string extended_swizzle() {
    std::string out;
    bool xyzw = false, rgba = false;
    for (int k = 0; k < 4; ++k) {
      if (k) c_.expect(",", "',' and the next extended swizzle component");
      if (c_.peek().is("-") || c_.peek().is("+")) out += c_.take().text;
      const Token& t = c_.peek();
      // An integer of value 0 or 1 ("01" too: Mesa's extSwizSel reads an INTEGER's value).
      std::string value;
      if (t.kind == TokenKind::Integer) {
        const size_t nonzero = t.text.find_first_not_of('0');
        value = nonzero == std::string::npos ? "0" : t.text.substr(nonzero);
      }
      const bool constant = value == "0" || value == "1";
      const bool comp = t.kind == TokenKind::Name && t.text.size() == 1 &&
                        valid_components(t.text, vertex() ? "xyzw" : "xyzwrgba");
      if (!constant && !comp) c_.expected("an extended swizzle component (0, 1, x, y, z, w)");
      if (comp) (valid_components(t.text, "xyzw") ? xyzw : rgba) = true;
      if (xyzw && rgba) c_.fail("expected components of xyzw or of rgba, not both");
      out += constant ? value : t.text;
      c_.take();
    }
    return out;
  }

  void texture_operands(Instruction& in) {
    c_.expect(",");
    c_.expect("texture", "texture[n]");
    in.unit = 0;
    if (c_.accept("[")) {
      in.unit = c_.expect_index(limits_.texture_image_units, "a texture image unit");
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
    const auto it = unit_targets_.find(in.unit);
    if (it != unit_targets_.end() && it->second != t.text) {
      c_.fail("expected target " + it->second + " for texture[" + std::to_string(in.unit) +
              "], as it is used before: one unit, one target");
    }
    unit_targets_[in.unit] = t.text;
    in.target = c_.take().text;
  }

  void instruction() {
    const Token& t = c_.peek();
    if (t.kind != TokenKind::Name) c_.expected("an instruction or a declaration");
    Instruction in;
    in.at = t.at;
    std::string name = t.text;
    if (name.size() > 4 && name.compare(name.size() - 4, 4, "_SAT") == 0) {
      name = name.substr(0, name.size() - 4);
      in.saturate = true;
    }
    const OpcodeInfo* op = find_opcode(name);
    if (!op || (in.saturate && vertex()) || !(vertex() ? op->vertex : op->fragment)) {
      const bool other_kind = op && !(in.saturate && vertex());
      c_.expected(
          std::string("an instruction or a declaration of ") + (vertex() ? "vertex" : "fragment") +
          " programs" +
          (other_kind
               ? " (" + name + " is ARB_" + (vertex() ? "fragment" : "vertex") + "_program's)"
               : (in.saturate && vertex() && op ? " (no _SAT in vertex programs)" : "")));
    }
    c_.take();
    in.opcode = op->name;
    in.texture = op->form == Form::Texture || op->form == Form::Kill;
    switch (op->form) {
      case Form::Kill:
        in.has_dst = false;
        in.srcs.push_back(source(false));
        break;
      case Form::Address: {
        const Token& a = c_.peek();
        const auto it = names_.find(a.text);
        if (a.kind != TokenKind::Name || it == names_.end() ||
            it->second.file != RegFile::Address) {
          c_.expected("an ADDRESS register as ARL's destination");
        }
        c_.take();
        in.dst.file = RegFile::Address;
        in.dst.index = it->second.index;
        const Token& dot = c_.expect(".", "'.x': ARL writes the address register's x");
        if (!c_.expect_attached_name(dot, "x, the address register's only component").is("x")) {
          Cursor::fail_at(dot.at, "expected .x, the address register's only component");
        }
        in.dst.swizzle = "x";
        c_.expect(",");
        in.srcs.push_back(source(true));
        break;
      }
      case Form::Swizzle: {
        in.dst = destination();
        c_.expect(",");
        bool negate = false;
        if (c_.peek().is("-") || c_.peek().is("+")) negate = c_.take().is("-");
        Operand s = source_register();
        s.negate = negate;
        c_.expect(",", "',' and the extended swizzle");
        s.swizzle = extended_swizzle();
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
        for (int k = 0; k < op->sources; ++k) {
          c_.expect(",", k == 0 ? "','" : "',' and source " + std::to_string(k + 1));
          in.srcs.push_back(source(op->form == Form::Scalar));
        }
        break;
    }
    p_.code.push_back(std::move(in));
  }

  Cursor c_;
  Limits limits_;
  Program p_;
  std::map<std::string, Symbol> names_;
  std::set<std::string> attribs_seen_;
  std::map<int, std::string> unit_targets_;
};

}  // namespace

Program parse(const std::string& source, const Limits& limits) {
  return Parser(source, limits).run();
}

}  // namespace lt::arbfp::text
