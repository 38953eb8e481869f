#include "gx/program/parser.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/fs.h"
#include "gx/program/gx_names.h"

namespace lt::gx {

namespace {

struct Token {
  enum class Kind { Identifier, Integer, Float, Punct, String, End };
  Kind kind = Kind::End;
  // Into the program text, which outlives the parse: a texture's bytes are millions of tokens,
  // and a view neither copies them nor makes a token larger than 32 bytes.
  std::string_view text;
  SourcePos pos;
};

// Splits the text into tokens, one at a time as the parser asks: a texture's bytes are millions of
// tokens, and a vector of them all took 16 MB for a 1.3 MB textured program, written and freed at
// every parse (GxPlan's sweep: 18.7 s of CPU with it, 13.7 s without). Comments (// and /* */)
// and preprocessor lines (#include, which an exported file carries for the compiler) are skipped,
// as a C compiler's front end would.
class Lexer {
 public:
  Lexer(const std::string& text, const std::string& file) : s_(text), file_(file) {
    // A UTF-8 byte-order mark (a Windows editor's) is skipped, as GCC skips it; positions count
    // from the character after it.
    if (starts_with_utf8_bom(s_)) i_ = kUtf8Bom.size();
  }

  // The next token; at the end of the text, an End token (again on every later call).
  Token next() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '\n') {
        advance();
        line_start_ = true;
        continue;
      }
      if (std::isspace(static_cast<unsigned char>(c))) {
        advance();
        continue;
      }
      if (c == '#' && line_start_) {
        while (i_ < s_.size() && s_[i_] != '\n') advance();
        continue;
      }
      line_start_ = false;
      if (c == '/' && peek(1) == '/') {
        while (i_ < s_.size() && s_[i_] != '\n') advance();
        continue;
      }
      if (c == '/' && peek(1) == '*') {
        const SourcePos at = pos_;
        advance();
        advance();
        while (i_ < s_.size() && !(s_[i_] == '*' && peek(1) == '/')) advance();
        if (i_ >= s_.size()) fail(at, "unterminated comment");
        advance();
        advance();
        continue;
      }
      Token t;
      t.pos = pos_;
      if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        const size_t start = i_;
        while (i_ < s_.size() &&
               (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_'))
          advance();
        t.text = text_from(start);
        t.kind = Token::Kind::Identifier;
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1))))) {
        t = number();
      } else if (c == '"') {
        t = string_literal();
      } else if (std::string_view("(){}[],;&|=-+").find(c) != std::string_view::npos) {
        const size_t start = i_;
        advance();
        t.text = text_from(start);
        t.kind = Token::Kind::Punct;
      } else {
        // A byte that is no printable ASCII as its code: printed raw it would be half a character.
        char shown[8];
        std::snprintf(shown, sizeof shown,
                      std::isprint(static_cast<unsigned char>(c)) ? "'%c'" : "0x%02X",
                      static_cast<unsigned char>(c));
        fail(pos_, std::string("unexpected character ") + shown);
      }
      return t;
    }
    Token end;
    end.pos = pos_;
    return end;
  }

 private:
  char peek(size_t k) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }
  std::string_view text_from(size_t start) const {
    return std::string_view(s_).substr(start, i_ - start);
  }
  void advance() { take(); }
  char take() {
    const char c = s_[i_++];
    if (c == '\n') {
      ++pos_.line;
      pos_.column = 1;
    } else {
      ++pos_.column;
    }
    return c;
  }
  [[noreturn]] void fail(const SourcePos& p, const std::string& what) const {
    throw InputError(file_, std::to_string(p.line) + ":" + std::to_string(p.column), what);
  }

  // "text" on one line, without escapes (TPL_OpenTPLFromFile's file name): the token is the
  // characters between the quotes.
  Token string_literal() {
    Token t;
    t.pos = pos_;
    advance();
    const size_t start = i_;
    while (i_ < s_.size() && s_[i_] != '"' && s_[i_] != '\n') {
      const unsigned char c = static_cast<unsigned char>(s_[i_]);
      if (c == '\\') fail(pos_, "escape sequences in strings are not read");
      // Printable ASCII only: a message that quotes the string stays one readable line.
      if (c < 0x20 || c > 0x7e) {
        char shown[8];
        std::snprintf(shown, sizeof shown, "0x%02X", c);
        fail(pos_, std::string("unexpected character ") + shown + " in a string");
      }
      advance();
    }
    if (i_ >= s_.size() || s_[i_] != '"') fail(t.pos, "unterminated string");
    t.text = text_from(start);
    advance();
    t.kind = Token::Kind::String;
    return t;
  }

  // C literals: decimal and hex integers (u/U/l/L suffixes), floats with an optional f suffix.
  Token number() {
    Token t;
    t.pos = pos_;
    const size_t start = i_;
    bool is_float = false;
    if (s_[i_] == '0' && (peek(1) == 'x' || peek(1) == 'X')) {
      advance();
      advance();
      while (std::isxdigit(static_cast<unsigned char>(peek(0)))) advance();
    } else {
      while (i_ < s_.size()) {
        const char c = s_[i_];
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
          is_float |= c == '.';
          advance();
        } else if ((c == 'e' || c == 'E') && i_ > start) {
          is_float = true;
          advance();
          if (peek(0) == '-' || peek(0) == '+') advance();
        } else {
          break;
        }
      }
    }
    t.text = text_from(start);  // without the suffixes below
    if (peek(0) == 'f' || peek(0) == 'F') {
      is_float = true;
      advance();
    }
    while (peek(0) == 'u' || peek(0) == 'U' || peek(0) == 'l' || peek(0) == 'L') advance();
    if (std::isalnum(static_cast<unsigned char>(peek(0))) || peek(0) == '_')
      fail(pos_, "malformed number '" + std::string(t.text) + peek(0) + "'");
    t.kind = is_float ? Token::Kind::Float : Token::Kind::Integer;
    return t;
  }

  const std::string& s_;
  const std::string& file_;
  size_t i_ = 0;
  SourcePos pos_{1, 1};
  bool line_start_ = true;
};

class Parser {
 public:
  Parser(const std::string& text, const std::string& file) : lexer_(text, file), file_(file) {}

  ProgramFile run() {
    ProgramFile out;
    out.file = file_;
    while (cur().kind != Token::Kind::End) {
      if (is_function_start()) {
        out.functions.push_back(function());
      } else {
        out.top_level.push_back(statement());
      }
    }
    return out;
  }

 private:
  const Token& cur() const { return ahead(0); }
  // The token n after the current one (n < kLookahead); End past the end of the text. Read from
  // the lexer on demand: filling the window does not change what the parser has taken.
  const Token& ahead(size_t n) const {
    LT_CHECK(n < kLookahead, "the parser looks at most three tokens ahead");
    while (buffered_ <= n) {
      window_[(first_ + buffered_) & (kLookahead - 1)] = lexer_.next();
      ++buffered_;
    }
    return window_[(first_ + n) & (kLookahead - 1)];
  }
  // A view, not a C string: a literal's length is known where it is written (a byte array calls
  // this twice a byte).
  bool is(std::string_view text) const {
    return cur().kind != Token::Kind::End && cur().kind != Token::Kind::String &&
           cur().text == text;
  }
  Token take() {
    Token t = cur();
    if (t.kind != Token::Kind::End) {
      first_ = (first_ + 1) & (kLookahead - 1);
      --buffered_;
    }
    return t;
  }

  [[noreturn]] void fail(const SourcePos& p, const std::string& what) const {
    throw InputError(file_, std::to_string(p.line) + ":" + std::to_string(p.column), what);
  }
  [[noreturn]] void expected(const std::string& what) const {
    const std::string got =
        cur().kind == Token::Kind::End ? "end of file" : "'" + std::string(cur().text) + "'";
    fail(cur().pos, "expected " + what + ", found " + got);
  }
  void expect(std::string_view punct) {
    if (!is(punct)) expected("'" + std::string(punct) + "'");
    take();
  }
  std::string identifier(const std::string& what) {
    if (cur().kind != Token::Kind::Identifier) expected(what);
    return std::string(take().text);
  }

  bool is_function_start() const {
    return is("void") && ahead(1).kind == Token::Kind::Identifier && ahead(2).text == "(";
  }

  Function function() {
    Function f;
    f.pos = cur().pos;
    take();  // void
    f.name = identifier("a function name");
    expect("(");
    if (is("void")) take();
    expect(")");
    expect("{");
    while (!is("}")) {
      if (cur().kind == Token::Kind::End) expected("'}' closing function " + f.name);
      f.body.push_back(statement());
    }
    take();
    return f;
  }

  Statement statement() {
    Statement s;
    std::optional<Token> qualifier;
    while (is("static") || is("const")) {
      const Token q = take();
      if (!qualifier) qualifier = q;
    }
    if (is("GXLightObj") || is("GXTexObj") || is("GXTlutObj") || is("TPLFile") || is("Mtx") ||
        is("u8")) {
      s.kind = Statement::Kind::Declaration;
      s.declaration = declaration();
      return s;
    }
    // A qualifier starts nothing but a declaration here (a call cannot be static or const).
    if (qualifier)
      fail(qualifier->pos, "'" + std::string(qualifier->text) +
                               "' before something that is not a declaration (GXLightObj, "
                               "GXTexObj, GXTlutObj, TPLFile, Mtx or u8)");
    s.kind = Statement::Kind::Call;
    s.call = call();
    expect(";");
    return s;
  }

  Declaration declaration() {
    Declaration d;
    d.pos = cur().pos;
    const std::string type(take().text);
    d.name = identifier("a variable name");
    if (type == "GXLightObj" || type == "GXTexObj" || type == "GXTlutObj" || type == "TPLFile") {
      d.type = type == "GXLightObj"  ? Declaration::Type::LightObj
               : type == "GXTexObj"  ? Declaration::Type::TexObj
               : type == "GXTlutObj" ? Declaration::Type::TlutObj
                                     : Declaration::Type::TplFile;
      expect(";");
      return d;
    }
    if (type == "Mtx") {
      d.type = Declaration::Type::Mtx;
      expect("=");
      expect("{");
      for (int row = 0; row < 3; ++row) {
        expect("{");
        for (int col = 0; col < 4; ++col) {
          d.values.push_back(number_value());
          if (col < 3) expect(",");
        }
        expect("}");
        if (row < 2) expect(",");
      }
      if (is(",")) take();
      expect("}");
      expect(";");
      return d;
    }
    // u8 name[N] ATTRIBUTE_ALIGN(32) = { ... };
    d.type = Declaration::Type::ByteArray;
    expect("[");
    long long declared = -1;
    if (cur().kind == Token::Kind::Integer) declared = integer_literal(take());
    expect("]");
    alignment();
    expect("=");
    expect("{");
    while (!is("}")) {
      const SourcePos p = cur().pos;
      if (cur().kind != Token::Kind::Integer) expected("a byte value (0..255)");
      const long long v = integer_literal(take());
      if (v < 0 || v > 255) fail(p, "byte value out of range: " + std::to_string(v) + " (0..255)");
      d.values.push_back(static_cast<double>(v));
      if (!is("}")) expect(",");
    }
    take();
    alignment();
    expect(";");
    // As in C: fewer initialisers than the declared size leave the rest zero, more are an error.
    if (declared >= 0 && declared < static_cast<long long>(d.values.size()))
      fail(d.pos, "array " + d.name + " declares " + std::to_string(declared) +
                      " bytes but lists " + std::to_string(d.values.size()));
    if (declared >= 0) d.values.resize(static_cast<size_t>(declared), 0.0);
    return d;
  }

  // ATTRIBUTE_ALIGN(32) (libogc's macro), ATTRIBUTE_ALIGNED(32) (what exports before the fix
  // wrote; libogc never defined it) or __attribute__((aligned(32))).
  void alignment() {
    auto parenthesised_integer = [&] {
      expect("(");
      if (cur().kind != Token::Kind::Integer) expected("an alignment");
      take();
      expect(")");
    };
    if (is("ATTRIBUTE_ALIGN") || is("ATTRIBUTE_ALIGNED")) {
      take();
      parenthesised_integer();
    } else if (is("__attribute__")) {
      take();
      expect("(");
      expect("(");
      if (!is("aligned")) expected("'aligned'");
      take();
      parenthesised_integer();
      expect(")");
      expect(")");
    }
  }

  Call call() {
    Call c;
    c.pos = cur().pos;
    c.function = identifier("a libogc call or a declaration");
    expect("(");
    while (!is(")")) {
      c.args.push_back(argument());
      if (!is(")")) expect(",");
    }
    take();
    return c;
  }

  Arg argument() {
    const SourcePos p = cur().pos;
    Arg a;
    if (is("&")) {
      take();
      a = Arg::address_of(identifier("a variable after '&'"));
    } else if (is("(") && (ahead(1).text == "GXColor" || ahead(1).text == "GXColorS10")) {
      take();
      const bool s10 = take().text == "GXColorS10";
      expect(")");
      expect("{");
      std::array<long long, 4> c{};
      for (int i = 0; i < 4; ++i) {
        c[static_cast<size_t>(i)] = signed_integer("a colour component");
        if (i < 3) expect(",");
      }
      expect("}");
      a = Arg::rgba(c, s10);
    } else if (cur().kind == Token::Kind::String) {
      a = Arg::string(std::string(take().text));
    } else {
      a = expression();
    }
    a.pos = p;
    return a;
  }

  // An integer or float expression: literals and GX_* names joined by `|`, with a unary sign.
  Arg expression() {
    Arg a = term();
    while (is("|")) {
      take();
      const Arg b = term();
      if (a.kind != Arg::Kind::Integer || b.kind != Arg::Kind::Integer)
        fail(b.pos, "'|' joins integers and GX_* names only");
      a.value |= b.value;
      a.number = static_cast<double>(a.value);
      a.text += " | " + b.text;
    }
    return a;
  }

  Arg term() {
    const SourcePos p = cur().pos;
    bool negative = false;
    while (is("-") || is("+")) negative ^= take().text == "-";
    Arg a;
    if (cur().kind == Token::Kind::Integer) {
      const long long v = integer_literal(take());
      a = Arg::literal(negative ? -v : v);
    } else if (cur().kind == Token::Kind::Float) {
      const Token t = take();
      const double v = std::strtod(std::string(t.text).c_str(), nullptr);
      if (!std::isfinite(v)) fail(t.pos, "number out of range: " + std::string(t.text));
      a.kind = Arg::Kind::Number;
      a.number = negative ? -v : v;
      a.text = (negative ? "-" : "") + std::string(t.text);
    } else if (cur().kind == Token::Kind::Identifier) {
      const Token t = take();
      if (const GxName* n = find_gx_name(t.text)) {
        a = Arg::integer(n->name, negative ? -n->value : n->value);
      } else if (t.text.rfind("GX_", 0) == 0) {
        fail(t.pos,
             "unknown name " + std::string(t.text) + " (not a GX constant of libogc's gx.h)");
      } else {
        if (negative) fail(p, "a sign before " + std::string(t.text));
        a = Arg::identifier(std::string(t.text));
      }
    } else {
      expected("an argument");
    }
    a.pos = p;
    return a;
  }

  long long signed_integer(const std::string& what) {
    bool negative = false;
    while (is("-") || is("+")) negative ^= take().text == "-";
    if (cur().kind != Token::Kind::Integer) expected(what);
    const long long v = integer_literal(take());
    return negative ? -v : v;
  }

  double number_value() {
    bool negative = false;
    while (is("-") || is("+")) negative ^= take().text == "-";
    if (cur().kind != Token::Kind::Integer && cur().kind != Token::Kind::Float)
      expected("a number");
    const Token t = take();
    const double v = t.kind == Token::Kind::Integer
                         ? static_cast<double>(integer_literal(t))
                         : std::strtod(std::string(t.text).c_str(), nullptr);
    // Mtx entries are f32 in C: a value beyond float's range would be an Inf in XF.
    if (!std::isfinite(static_cast<float>(v)))
      fail(t.pos, "number out of float range: " + std::string(t.text));
    return negative ? -v : v;
  }

  long long integer_literal(const Token& t) const {
    long long v = 0;
    const bool hex = t.text.size() > 2 && (t.text[1] == 'x' || t.text[1] == 'X');
    const char* b = t.text.data() + (hex ? 2 : 0);
    const auto r = std::from_chars(b, t.text.data() + t.text.size(), v, hex ? 16 : 10);
    if (r.ec != std::errc() || v > (1LL << 40))
      fail(t.pos, "integer out of range: " + std::string(t.text));
    return v;
  }

  static constexpr size_t kLookahead = 4;  // a power of two: the window's index is a mask
  mutable Lexer lexer_;
  mutable std::array<Token, kLookahead> window_{};
  mutable size_t first_ = 0, buffered_ = 0;
  const std::string& file_;
  size_t k_ = 0;
};

}  // namespace

ProgramFile parse_program(const std::string& text, const std::string& file_for_errors) {
  return Parser(text, file_for_errors).run();
}

ProgramFile load_program(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  try {
    return parse_program(text, path.string());
  } catch (const std::bad_alloc&) {
    // Within the size cap but too large for this machine: name the file, not std::bad_alloc.
    throw InputError(path.string(), "", "out of memory reading this program file");
  }
}

}  // namespace lt::gx
