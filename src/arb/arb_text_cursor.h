// A read position in the token list of an ARB program (arb_text_lexer.h), shared by the parser
// and the binding parser: look at the next token, take it, or fail there with what was expected.
#pragma once

#include <string>
#include <vector>

#include "arb/arb_text_lexer.h"

namespace lt::arbfp::text {

// What a token shows in a message: "'MOV'", or "the end of the program".
inline std::string shown(const Token& t) {
  return t.kind == TokenKind::End ? "the end of the program" : "'" + t.text + "'";
}

class Cursor {
 public:
  explicit Cursor(std::vector<Token> tokens) : t_(std::move(tokens)) {}

  const Token& peek(size_t ahead = 0) const {
    const size_t k = i_ + ahead;
    return k < t_.size() ? t_[k] : t_.back();
  }
  const Token& take() {
    const Token& t = peek();
    if (i_ < t_.size() - 1) ++i_;
    return t;
  }
  // Takes the token if it is `text`.
  bool accept(const char* text) {
    if (!peek().is(text)) return false;
    take();
    return true;
  }
  const Token& expect(const char* text, const std::string& what = "") {
    if (!peek().is(text)) expected(what.empty() ? std::string("'").append(text).append("'") : what);
    return take();
  }
  const Token& expect_name(const std::string& what) {
    if (peek().kind != TokenKind::Name) expected(what);
    return take();
  }
  // The name right after the '.' just taken, with nothing between: Mesa's lexer reads ".xyzw"
  // as one token, so "r. x" or "r.\nx" is not a swizzle.
  const Token& expect_attached_name(const Token& dot, const std::string& what) {
    const Token& t = peek();
    if (t.kind != TokenKind::Name || t.at.line != dot.at.line || t.at.column != dot.at.column + 1) {
      expected(what + " right after '.'");
    }
    return take();
  }
  // A non-negative integer in brackets' place: "[3]" reads 3; bounded by `limit` (exclusive).
  int expect_index(int limit, const std::string& what) {
    const Token& t = peek();
    if (t.kind != TokenKind::Integer) expected(what);
    // Bounded before conversion: an integer literal can have any number of digits.
    if (t.text.size() > 9 || std::stol(t.text) >= limit) {
      fail("expected " + what + " below " + std::to_string(limit) + ", not " + t.text);
    }
    take();
    return std::stoi(t.text);
  }
  // "expected <what>, found 'x'" at the next token.
  [[noreturn]] void expected(const std::string& what) const;
  [[noreturn]] void fail(const std::string& message) const { fail_at(peek().at, message); }
  [[noreturn]] static void fail_at(Position at, const std::string& message) {
    throw SyntaxError(at, message);
  }

 private:
  std::vector<Token> t_;
  size_t i_ = 0;
};

inline void Cursor::expected(const std::string& what) const {
  fail("expected " + what + ", found " + shown(peek()));
}

}  // namespace lt::arbfp::text
