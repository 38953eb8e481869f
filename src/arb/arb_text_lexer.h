// Tokens of ARB_vertex_program / ARB_fragment_program text, each with the line and column where it
// starts, so the parser (arb_text_parser.h) can name `file:line:column` as a driver's compiler
// does. The grammar's lexical rules (ARB_vertex_program section 2.14.2, ARB_fragment_program
// 3.11.2): `#` starts a comment to the end of the line; names are letters, digits, `_` and `$`,
// not starting with a digit; numbers are integers or floats (`1.5e2`, `.5`, `5.`).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace lt::arbfp::text {

// Where in the program text: 1-based line and column (columns count bytes).
struct Position {
  int line = 1, column = 1;
};

// A program that is not valid: where, and what was expected there. Derived from
// std::invalid_argument so the counters' callers catch one type for any bad program.
class SyntaxError : public std::invalid_argument {
 public:
  SyntaxError(Position at, const std::string& message)
      : std::invalid_argument(std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
                              message),
        at_(at),
        message_(message) {}
  Position at() const { return at_; }
  const std::string& message() const { return message_; }

 private:
  Position at_;
  std::string message_;
};

enum class TokenKind {
  Name,     // OPTION, MOV, fragment, a_1; also the texture targets 1D, 2D, 3D
  Integer,  // 12
  Float,    // 1.5, .5, 5., 1e3
  Punct,    // ; , . [ ] { } = + - and ".."
  End,      // end of the text
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;
  Position at;
  bool is(const char* t) const { return kind != TokenKind::End && text == t; }
};

// The header ("!!ARBvp1.0" / "!!ARBfp1.0", after optional leading white space as Mesa accepts)
// is returned as the first Name token; an invalid character is a SyntaxError at its position.
std::vector<Token> tokenize(const std::string& source);

}  // namespace lt::arbfp::text
