#include "arb/arb_text_operands.h"

#include <algorithm>
#include <cstdlib>

namespace lt::arbfp::text {

namespace {

bool valid_components(const std::string& s, const std::string& set) {
  return std::all_of(s.begin(), s.end(),
                     [&](char ch) { return set.find(ch) != std::string::npos; });
}

}  // namespace

float signed_number(Cursor& c) {
  const bool negative = c.peek().is("-");
  if (negative || c.peek().is("+")) c.take();
  const Token& t = c.peek();
  if (t.kind != TokenKind::Integer && t.kind != TokenKind::Float) c.expected("a number");
  c.take();
  const float v = std::strtof(t.text.c_str(), nullptr);
  return negative ? -v : v;
}

ir::ParamSlot vector_constant(Cursor& c) {
  c.expect("{");
  ir::ParamSlot s;
  s.constant = true;
  s.values = {0, 0, 0, 1};
  int n = 0;
  do {
    if (n == 4) c.expected("'}' (a vector has four components at most)");
    s.values[static_cast<size_t>(n++)] = signed_number(c);
  } while (c.accept(","));
  c.expect("}", "',' or '}'");
  return s;
}

bool starts_number(const Cursor& c, size_t ahead) {
  const Token& t = c.peek(ahead);
  return t.kind == TokenKind::Integer || t.kind == TokenKind::Float;
}

std::string write_mask(Cursor& c, bool vertex) {
  if (!c.peek().is(".")) return "";
  const Token& dot = c.take();
  const Token& t = c.expect_attached_name(dot, "a write mask (.x, .xy, .xyzw, ...)");
  const std::string sets[] = {"xyzw", "rgba"};
  for (const std::string& set : sets) {
    if (set == "rgba" && vertex) continue;
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
                            std::string(vertex ? "xyzw" : "xyzw or rgba") +
                            " in that order, each once; found '" + t.text + "'");
}

std::string swizzle(Cursor& c, bool vertex, bool scalar) {
  if (!c.peek().is(".")) {
    if (scalar) c.expected("a scalar suffix (.x, .y, .z or .w)");
    return "";
  }
  const Token& dot = c.take();
  const Token& t =
      c.expect_attached_name(dot, scalar ? "a scalar suffix (.x, .y, .z or .w)" : "a swizzle");
  const bool xyzw = valid_components(t.text, "xyzw");
  const bool rgba = !vertex && valid_components(t.text, "rgba");
  const size_t n = t.text.size();
  if (!(xyzw || rgba) || (scalar ? n != 1 : (n != 1 && n != 4))) {
    Cursor::fail_at(t.at, std::string("expected ") +
                              (scalar ? "one component" : "one or four components") + " of " +
                              (vertex ? "xyzw" : "xyzw or rgba (not mixed)") + ", found '" +
                              t.text + "'");
  }
  return t.text;
}

std::string extended_swizzle(Cursor& c, bool vertex) {
  std::string out;
  bool xyzw = false, rgba = false;
  for (int k = 0; k < 4; ++k) {
    if (k) c.expect(",", "',' and the next extended swizzle component");
    if (c.peek().is("-") || c.peek().is("+")) out += c.take().text;
    const Token& t = c.peek();
    // An integer of value 0 or 1 ("01" too: Mesa's extSwizSel reads an INTEGER's value).
    std::string value;
    if (t.kind == TokenKind::Integer) {
      const size_t nonzero = t.text.find_first_not_of('0');
      value = nonzero == std::string::npos ? "0" : t.text.substr(nonzero);
    }
    const bool constant = value == "0" || value == "1";
    const bool comp = t.kind == TokenKind::Name && t.text.size() == 1 &&
                      valid_components(t.text, vertex ? "xyzw" : "xyzwrgba");
    if (!constant && !comp) c.expected("an extended swizzle component (0, 1, x, y, z, w)");
    if (comp) (valid_components(t.text, "xyzw") ? xyzw : rgba) = true;
    if (xyzw && rgba) c.fail("expected components of xyzw or of rgba, not both");
    out += constant ? value : t.text;
    c.take();
  }
  return out;
}

}  // namespace lt::arbfp::text
