#include "gx/program/printer.h"

#include <charconv>
#include <cstdio>
#include <sstream>

namespace lt::gx {

namespace {

// %.9g is enough digits for any float to read back as the same float (FLT_DECIMAL_DIG = 9); a
// C float literal needs a '.' or an exponent before its f suffix.
// A byte array's values, 16 to a row, each row begun by `row_start`: written with to_chars into
// one string: a texture is up to 10^5 values, and a stream insertion apiece made printing a
// large part of exporting a program with an albedo map (perf of GxPlan's sweep: the stream's
// insertions ~15% of its CPU).
std::string byte_rows(const std::vector<double>& values, const std::string& row_start) {
  std::string text;
  text.reserve(values.size() * 5 + values.size() / 16 * row_start.size());
  char digits[8];
  for (size_t i = 0; i < values.size(); ++i) {
    text += i % 16 ? " " : row_start;
    text.append(digits,
                std::to_chars(digits, digits + sizeof digits, static_cast<int>(values[i])).ptr);
    if (i + 1 < values.size()) text += ',';
  }
  return text;
}

std::string print_float(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(static_cast<float>(v)));
  std::string s = buf;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s + "f";
}

void print_comment(std::ostream& out, const std::string& comment, const std::string& indent) {
  if (comment.empty()) return;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) {
    out << indent << "//" << (line.empty() ? "" : " ") << line << "\n";
  }
}

void print_declaration(std::ostream& out, const Declaration& d, const std::string& indent) {
  switch (d.type) {
    case Declaration::Type::LightObj:
      out << indent << "GXLightObj " << d.name << ";\n";
      return;
    case Declaration::Type::TexObj:
      out << indent << "GXTexObj " << d.name << ";\n";
      return;
    case Declaration::Type::TlutObj:
      out << indent << "GXTlutObj " << d.name << ";\n";
      return;
    case Declaration::Type::TplFile:
      out << indent << "TPLFile " << d.name << ";\n";
      return;
    case Declaration::Type::Mtx:
      out << indent << "Mtx " << d.name << " = {";
      for (size_t r = 0; r < 3; ++r) {
        out << (r ? ", {" : "{");
        for (size_t c = 0; c < 4; ++c) out << (c ? ", " : "") << print_float(d.values[r * 4 + c]);
        out << "}";
      }
      out << "};\n";
      return;
    case Declaration::Type::ByteArray:
      // 32-byte aligned: GX texture images must be [OGC gx.h L4262]. ATTRIBUTE_ALIGN is
      // libogc's macro (gcutil.h since the 2025 rework, gctypes.h before it); there is no
      // ATTRIBUTE_ALIGNED in libogc, though the parser still reads it from older files.
      out << indent << "static u8 " << d.name << "[" << d.values.size()
          << "] ATTRIBUTE_ALIGN(32) = {";
      out << byte_rows(d.values, "\n" + indent + "    ") << "\n" << indent << "};\n";
      return;
  }
}

void print_statements(std::ostream& out, const std::vector<Statement>& body,
                      const std::string& indent) {
  for (const Statement& s : body) {
    print_comment(out, s.comment, indent);
    if (s.kind == Statement::Kind::Declaration) {
      print_declaration(out, s.declaration, indent);
      continue;
    }
    out << indent << s.call.function << "(";
    for (size_t i = 0; i < s.call.args.size(); ++i)
      out << (i ? ", " : "") << print_arg(s.call.args[i]);
    out << ");\n";
  }
}

}  // namespace

std::string print_arg(const Arg& a) {
  switch (a.kind) {
    case Arg::Kind::Integer:
      return a.text.empty() ? std::to_string(a.value) : a.text;
    case Arg::Kind::Number:
      return print_float(a.number);
    case Arg::Kind::Color:
    case Arg::Kind::ColorS10: {
      std::string s = a.kind == Arg::Kind::Color ? "(GXColor){" : "(GXColorS10){";
      for (size_t i = 0; i < 4; ++i) s += (i ? ", " : "") + std::to_string(a.color[i]);
      return s + "}";
    }
    case Arg::Kind::AddressOf:
      return "&" + a.name;
    case Arg::Kind::Identifier:
      return a.name;
    case Arg::Kind::String:
      return "\"" + a.text + "\"";
  }
  return "";
}

std::string print_program(const ProgramFile& program) {
  std::ostringstream out;
  print_comment(out, program.comment, "");
  if (!program.comment.empty()) out << "\n";
  print_statements(out, program.top_level, "");
  for (const Function& f : program.functions) {
    out << "\n";
    print_comment(out, f.comment, "");
    out << "void " << f.name << "(" << (f.parameters.empty() ? "void" : f.parameters) << ") {\n";
    print_statements(out, f.body, "  ");
    out << "}\n";
  }
  return out.str();
}

}  // namespace lt::gx
