// A GX program file (gx.md §1): libogc calls, one statement per line, exactly as a porter writes
// them in C, optionally grouped into pass functions and preceded by the data they use (light
// and texture objects, matrices, the LUT as a u8 array). This is the one representation of a
// GX program: the generator builds it, the printer writes it as C, the parser reads it back,
// and the interpreter turns it into GX state for the emulator and the budget.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace lt::gx {

// Where a token stood, for `file:line:column` errors.
struct SourcePos {
  int line = 0, column = 0;
};

// One argument of a call.
struct Arg {
  enum class Kind {
    Integer,    // an integer expression: GX_* names and literals joined by `|` (names holds the
                // parts, value the result)
    Number,     // a float literal (f32 parameters; integers are accepted there too)
    Color,      // (GXColor){r, g, b, a}
    ColorS10,   // (GXColorS10){r, g, b, a}
    AddressOf,  // &name (a GXLightObj, GXTexObj, GXTlutObj or TPLFile)
    String,     // "text" (TPL_OpenTPLFromFile's file name), without escapes: text is the
                // characters between the quotes
    Identifier  // name (an Mtx or a u8 array)
  };
  Kind kind = Kind::Integer;
  std::string text;                  // as written (for messages and printing)
  long long value = 0;               // Integer
  double number = 0;                 // Number (and Integer as a number)
  std::array<long long, 4> color{};  // Color, ColorS10
  std::string name;                  // AddressOf, Identifier
  SourcePos pos;

  static Arg integer(const std::string& gx_name, long long v);
  static Arg literal(long long v);
  static Arg f32(float v);
  static Arg rgba(std::array<long long, 4> c, bool s10 = false);
  static Arg address_of(const std::string& n);
  static Arg identifier(const std::string& n);
  static Arg string(const std::string& s);
};

struct Call {
  std::string function;
  std::vector<Arg> args;
  SourcePos pos;

  Call() = default;
  Call(std::string f, std::vector<Arg> a) : function(std::move(f)), args(std::move(a)) {}
};

// `GXLightObj name;`, `GXTexObj name;`, `GXTlutObj name;`, `TPLFile name;` (libogc's open TPL
// file, tpl.h), `Mtx name = {{..},{..},{..}};` and `u8 name[N] ATTRIBUTE_ALIGN(32) = {..};`
// (static/const allowed).
struct Declaration {
  enum class Type { LightObj, TexObj, Mtx, ByteArray, TlutObj, TplFile };
  Type type = Type::LightObj;
  std::string name;
  std::vector<double> values;  // Mtx: 12 floats row by row; ByteArray: the bytes
  SourcePos pos;
};

struct Statement {
  enum class Kind { Call, Declaration };
  Kind kind = Kind::Call;
  Call call;
  Declaration declaration;
  std::string comment;  // printed as // lines before it (the parser skips comments)

  static Statement of(Call c, std::string comment = "");
  static Statement of(Declaration d, std::string comment = "");
};

// `void name(void) { ... }`: a pass function.
struct Function {
  std::string comment;
  std::string name;
  // Printed between the parentheses; empty is `void`. Only the module export (paths/gx/module/)
  // gives its pass functions a parameter; a program file's functions take none.
  std::string parameters;
  std::vector<Statement> body;
  SourcePos pos;
};

struct ProgramFile {
  std::string file;                  // for errors
  std::string comment;               // printed at the top of the file
  std::vector<Statement> top_level;  // statements outside any function, in order
  std::vector<Function> functions;
};

}  // namespace lt::gx
