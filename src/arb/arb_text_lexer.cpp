#include "arb/arb_text_lexer.h"

#include <cctype>

namespace lt::arbfp::text {

namespace {

bool name_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$';
}

bool name_char(char c) {
  return name_start(c) || std::isdigit(static_cast<unsigned char>(c));
}

bool digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// Outside a comment, Mesa's lexer reads a NUL or a byte >= 0x80 as the end of the input
// (glProgramStringARB accepts "END\xdd" and "END\0junk", and refuses "MOV\xdd..." as
// "unexpected end of file"); inside one, every byte but the newline is the comment's. This lexer
// does the same, so both accept and refuse the same texts (checked by arb_text_fuzz_test.cpp).
bool ends_text(char c) {
  return c == '\0' || static_cast<unsigned char>(c) >= 0x80;
}

class Lexer {
 public:
  explicit Lexer(const std::string& s) : s_(s) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    skip_space();
    if (s_.compare(i_, 2, "!!") == 0) {
      const Position at = pos_;
      // The header is its ten characters whatever follows ("!!ARBfp1.0MAD" is the header and
      // MAD, as Mesa reads it); anything else is shown up to the next white space.
      size_t n = 2;
      if (s_.compare(i_, 10, "!!ARBfp1.0") == 0 || s_.compare(i_, 10, "!!ARBvp1.0") == 0) {
        n = 10;
      } else {
        while (i_ + n < s_.size() && (name_char(s_[i_ + n]) || s_[i_ + n] == '.')) ++n;
      }
      out.push_back({TokenKind::Name, s_.substr(i_, n), at});
      advance(n);
    }
    while (true) {
      skip_space();
      if (i_ >= s_.size() || ends_text(s_[i_])) break;
      out.push_back(next());
    }
    out.push_back({TokenKind::End, "", pos_});
    return out;
  }

 private:
  char at(size_t k) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }

  void advance(size_t n) {
    for (size_t k = 0; k < n && i_ < s_.size(); ++k, ++i_) {
      if (s_[i_] == '\n') {
        ++pos_.line;
        pos_.column = 1;
      } else {
        ++pos_.column;
      }
    }
  }

  void skip_space() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '#') {
        while (i_ < s_.size() && s_[i_] != '\n') advance(1);
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        // Mesa's white space; \v and \f are no token there, so they are none here.
        advance(1);
      } else {
        break;
      }
    }
  }

  // Digits of an exponent after 'e': "e5", "e-5", "E+5"; 0 when there is none.
  size_t exponent_length(size_t k) const {
    if (at(k) != 'e' && at(k) != 'E') return 0;
    size_t n = 1;
    if (at(k + n) == '+' || at(k + n) == '-') ++n;
    if (!digit(at(k + n))) return 0;
    while (digit(at(k + n))) ++n;
    return n;
  }

  // The next n characters as one token.
  Token take(TokenKind kind, size_t n) {
    Token t{kind, s_.substr(i_, n), pos_};
    advance(n);
    return t;
  }

  Token number() {
    size_t n = 0;
    while (digit(at(n))) ++n;
    bool is_float = false;
    // "0..2" is an integer and the range operator, not "0." and ".2".
    if (at(n) == '.' && at(n + 1) != '.') {
      is_float = true;
      ++n;
      while (digit(at(n))) ++n;
    }
    if (const size_t e = exponent_length(n)) {
      is_float = true;
      n += e;
    }
    // The texture targets 1D, 2D and 3D start with a digit: one name token.
    if (!is_float && name_start(at(n))) {
      while (name_char(at(n))) ++n;
      return take(TokenKind::Name, n);
    }
    return take(is_float ? TokenKind::Float : TokenKind::Integer, n);
  }

  Token next() {
    const Position start = pos_;
    const char c = at(0);
    if (name_start(c)) {
      size_t n = 1;
      while (name_char(at(n))) ++n;
      return take(TokenKind::Name, n);
    }
    if (digit(c) || (c == '.' && digit(at(1)))) return number();
    if (c == '.' && at(1) == '.') return take(TokenKind::Punct, 2);
    if (std::string(";,.[]{}=+-").find(c) != std::string::npos) return take(TokenKind::Punct, 1);
    const unsigned char u = static_cast<unsigned char>(c);
    const std::string shown = std::isprint(u) ? std::string("'").append(1, c).append("'")
                                              : "byte " + std::to_string(static_cast<int>(u));
    throw SyntaxError(start, "expected a name, number or punctuation, not " + shown);
  }

  const std::string& s_;
  size_t i_ = 0;
  Position pos_;
};

}  // namespace

std::vector<Token> tokenize(const std::string& source) {
  return Lexer(source).run();
}

}  // namespace lt::arbfp::text
