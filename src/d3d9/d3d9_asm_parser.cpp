#include "d3d9/d3d9_asm_parser.h"

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <set>

namespace lt::d3d9 {

using arbfp::text::SyntaxError;

namespace {

// What a register type is called in messages.
std::string register_name(const std::string& type) {
  static const std::map<std::string, std::string> names = {
      {"r", "temporary"},
      {"c", "constant"},
      {"i", "integer constant"},
      {"b", "boolean constant"},
      {"s", "sampler"},
      {"t", "texture coordinate"},
      {"v", "input"},
      {"o", "output"},
      {"oc", "colour output"},
      {"od", "colour output"},
      {"ot", "texture output"},
      {"a", "address"},
      {"al", "loop counter"},
      {"l", "label"},
      {"p", "predicate"},
      {"opos", "position output"},
      {"ofog", "fog output"},
      {"opts", "point size output"},
      {"odepth", "depth output"},
      {"vpos", "position input"},
      {"vface", "face input"},
  };
  const auto it = names.find(type);
  return it == names.end() ? "" : it->second;
}

// One line of code, comments removed (`//` and `;` run to the end of the line), read left to
// right with its column for messages.
class Line {
 public:
  Line(std::string text, int number) : text_(std::move(text)), number_(number) {}

  void skip_space() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }
  bool at_end() {
    skip_space();
    return pos_ >= text_.size();
  }
  char peek() {
    skip_space();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }
  Position here() {
    skip_space();
    return {number_, static_cast<int>(pos_) + 1};
  }
  bool accept(char c) {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }
  void expect(char c, const std::string& what) {
    if (!accept(c)) expected(what);
  }
  // Letters, digits and '_' (an instruction with its modifiers, a register, a keyword).
  std::string word() {
    skip_space();
    const size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
      ++pos_;
    }
    return text_.substr(start, pos_ - start);
  }
  // The letters and digits only: "r0_abs" stops before "_abs".
  std::string alnum() {
    skip_space();
    const size_t start = pos_;
    while (pos_ < text_.size() && std::isalnum(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  // A number as def writes it: "-0.5", "1.00000000", "1e+010", "7".
  std::string number() {
    skip_space();
    const size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.' ||
            text_[pos_] == '-' || text_[pos_] == '+' || text_[pos_] == '#')) {
      ++pos_;
    }
    return text_.substr(start, pos_ - start);
  }
  [[noreturn]] void fail_at(Position at, const std::string& message) {
    throw SyntaxError(at, message);
  }
  [[noreturn]] void fail(const std::string& message) { fail_at(here(), message); }
  [[noreturn]] void expected(const std::string& what) {
    fail("expected " + what + ", found " + shown());
  }

 private:
  std::string shown() {
    if (at_end()) return "the end of the line";
    size_t end = pos_ + 1;
    while (end < text_.size() && std::isalnum(static_cast<unsigned char>(text_[end])) &&
           std::isalnum(static_cast<unsigned char>(text_[pos_]))) {
      ++end;
    }
    return "'" + text_.substr(pos_, end - pos_) + "'";
  }

  std::string text_;
  int number_;
  size_t pos_ = 0;
};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The registers written without an index: the named outputs and inputs, the loop counter.
bool single_register(const std::string& type) {
  return type == "opos" || type == "ofog" || type == "opts" || type == "odepth" || type == "vpos" ||
         type == "vface" || type == "al";
}

bool is_comparison(const std::string& s) {
  return s == "gt" || s == "lt" || s == "ge" || s == "le" || s == "eq" || s == "ne";
}

// The lines of the text with comments cut, numbered from 1.
std::vector<Line> code_lines(const std::string& source) {
  std::vector<Line> lines;
  size_t start = 0;
  int number = 1;
  while (start <= source.size()) {
    size_t end = source.find('\n', start);
    if (end == std::string::npos) end = source.size();
    std::string text = source.substr(start, end - start);
    const size_t slashes = text.find("//"), semicolon = text.find(';');
    text = text.substr(0, std::min(slashes, semicolon));
    lines.emplace_back(text, number++);
    start = end + 1;
  }
  return lines;
}

// Binary shader code is refused by name: a D3D9 token stream starts with its version token
// (0xFFFE0000 | version for vertex shaders, 0xFFFF0000 | version for pixel shaders, little
// endian: "D3D9 shader token format"), a D3D10+ blob with "DXBC".
void refuse_binary(const std::string& source) {
  const auto byte = [&source](size_t i) { return static_cast<std::uint8_t>(source[i]); };
  if (source.size() >= 4 && byte(3) == 0xFF && (byte(2) == 0xFE || byte(2) == 0xFF)) {
    throw SyntaxError({1, 1}, std::string("D3D9 shader bytecode (") +
                                  (byte(2) == 0xFE ? "vs_" : "ps_") + std::to_string(byte(1)) +
                                  "_" + std::to_string(byte(0)) +
                                  "), not assembly text: read its listing (fxc /dumpbin /Fc)");
  }
  if (source.compare(0, 4, "DXBC") == 0) {
    throw SyntaxError({1, 1}, "Direct3D 10+ bytecode (DXBC), not D3D9 assembly text");
  }
  const size_t nul = source.find('\0');
  if (nul != std::string::npos) {
    int line = 1;
    for (size_t i = 0; i < nul; ++i) line += source[i] == '\n';
    throw SyntaxError({line, 1}, "a NUL byte: binary data, not D3D9 assembly text");
  }
}

class Parser {
 public:
  Parser(Version version) : version_(version) {}

  Instruction instruction(Line& line) {
    Instruction ins;
    if (line.accept('(')) predicate(line);
    ins.at = line.here();
    const std::string opcode = lower(line.word());
    if (opcode.empty()) line.expected("an instruction");
    const std::string base = opcode.substr(0, opcode.find('_'));
    if (base == "dcl") return declaration(line, ins, opcode);
    ins.info = find_instruction(base);
    if (!ins.info) line.fail_at(ins.at, "unknown instruction '" + base + "'");
    if (slots(*ins.info, version_) < 0) {
      line.fail_at(ins.at, "'" + base + "' is not a " + to_string(version_) +
                               " instruction (it is in " + versions_with(*ins.info) + ")");
    }
    modifiers(line, ins, opcode.substr(base.size()));
    if (ins.info->kind == Kind::Setup) return definition(line, ins);
    if (ins.info->has_destination) ins.destinations.push_back(operand(line, true));
    const int sources = source_count(*ins.info, version_, ins.compared);
    for (int k = 0; k < sources; ++k) {
      if (k > 0 || ins.info->has_destination) line.expect(',', "',' and a source operand");
      ins.sources.push_back(operand(line, false));
    }
    if (!line.at_end()) line.expected("the end of the instruction");
    return ins;
  }

 private:
  // "(p0.x)" or "(!p0)" before an instruction: predication needs p0 (vs_2_x, ps_2_x up).
  void predicate(Line& line) {
    line.accept('!');
    const Operand p = operand(line, false);
    if (p.reg.type != "p") line.fail("expected the predicate register p0 in '(...)'");
    line.expect(')', "')' after the predicate");
  }

  // "_sat", "_pp", "_centroid" and, for if/break/setp, a comparison; each as the version has it
  // ("Instruction modifiers", "Dest Register Modifiers"): _sat on vertex shaders from vs_3_0,
  // _pp and _centroid on pixel shaders only; ps_1_x's result shifts are gone in 2_0.
  void modifiers(Line& line, Instruction& ins, std::string rest) {
    bool first = true;
    while (!rest.empty()) {
      const size_t next = rest.find('_', 1);
      const std::string m =
          rest.substr(1, next == std::string::npos ? std::string::npos : next - 1);
      rest = next == std::string::npos ? "" : rest.substr(next);
      if (first && ins.info->compares && is_comparison(m)) {
        ins.compared = true;
      } else if (m == "sat") {
        if (!is_pixel(version_) && !is_model3(version_)) {
          line.fail_at(ins.at, "_sat is not in " + to_string(version_) +
                                   " (vertex shaders have it from vs_3_0)");
        }
      } else if (m == "pp" || m == "centroid") {
        if (!is_pixel(version_)) {
          line.fail_at(ins.at,
                       "_" + m + " is a pixel shader modifier, not in " + to_string(version_));
        }
      } else if (m == "x2" || m == "x4" || m == "x8" || m == "d2" || m == "d4" || m == "d8") {
        line.fail_at(ins.at,
                     "the result shift _" + m + " is ps_1_x's, not in " + to_string(version_));
      } else {
        line.fail_at(ins.at, "unknown modifier '_" + m + "' on '" + ins.info->name + "'");
      }
      first = false;
    }
    if (ins.info->compares && ins.info->name == "setp" && !ins.compared) {
      line.fail_at(ins.at, "setp needs a comparison (setp_gt, setp_lt, ...)");
    }
  }

  // dcl, dcl_2d, dcl_texcoord0, dcl_position o0, dcl_texcoord1_centroid v1.xy: a sampler type
  // (2d, cube, volume), a usage with its index, _pp, _centroid; then the register declared.
  Instruction declaration(Line& line, Instruction& ins, const std::string& opcode) {
    static const std::set<std::string> usages = {
        "position", "blendweight", "blendindices", "normal", "psize", "texcoord", "tangent",
        "binormal", "tessfactor",  "positiont",    "color",  "fog",   "depth",    "sample"};
    ins.info = find_instruction("dcl");
    size_t at = 3;
    while (at < opcode.size()) {
      const size_t next = opcode.find('_', at + 1);
      const std::string part =
          opcode.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
      at = next == std::string::npos ? opcode.size() : next;
      std::string usage = part;
      while (!usage.empty() && std::isdigit(static_cast<unsigned char>(usage.back())))
        usage.pop_back();
      const bool known = part == "2d" || part == "cube" || part == "volume" ||
                         usages.count(usage) || part == "pp" || part == "centroid";
      if (!known) line.fail_at(ins.at, "unknown declaration '_" + part + "' in '" + opcode + "'");
      if ((part == "pp" || part == "centroid") && !is_pixel(version_)) {
        line.fail_at(ins.at,
                     "_" + part + " is a pixel shader modifier, not in " + to_string(version_));
      }
    }
    ins.destinations.push_back(operand(line, true));
    if (!line.at_end()) line.expected("the end of the declaration");
    return ins;
  }

  // def c#, 4 floats; defi i#, 4 integers; defb b#, true|false.
  Instruction definition(Line& line, Instruction& ins) {
    const std::string& name = ins.info->name;
    const std::string type = name == "def" ? "c" : name == "defi" ? "i" : "b";
    const Position at = line.here();
    const Operand reg = operand(line, true);
    if (reg.reg.type != type || reg.reg.relative) {
      line.fail_at(at, name + " defines a " + type + "# register");
    }
    ins.destinations.push_back(reg);
    for (int k = 0; k < (name == "defb" ? 1 : 4); ++k) {
      line.expect(',', "',' and a value");
      const Position value_at = line.here();
      const std::string v = lower(line.number());
      char* end = nullptr;
      if (name == "defb") {
        if (v != "true" && v != "false")
          line.fail_at(value_at, "expected true or false, found '" + v + "'");
      } else if (v.empty()) {
        line.expected("a number");
      } else if (v.find("#") == std::string::npos) {  // 1.#INF and 1.#QNAN, as fxc prints them
        (name == "def" ? (void)std::strtod(v.c_str(), &end)
                       : (void)std::strtol(v.c_str(), &end, 10));
        if (*end != '\0') line.fail_at(value_at, "expected a number, found '" + v + "'");
      }
    }
    if (!line.at_end()) line.expected("the end of the definition");
    return ins;
  }

  // [-]register[index][[relative]][_abs][.swizzle|.mask]
  Operand operand(Line& line, bool destination) {
    Operand op;
    const Position at = line.here();
    if (!destination) op.negate = line.accept('-');
    if (!destination && line.peek() == '1') {
      line.fail("the complement modifier 1-x is ps_1_x's, not in " + to_string(version_));
    }
    const std::string text = line.alnum();
    if (text.empty()) line.expected("a register");
    size_t digits = text.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(text[digits - 1]))) --digits;
    op.reg.type = lower(text.substr(0, digits));
    if (register_name(op.reg.type).empty()) {
      line.fail_at(at, "expected a register, found '" + text + "'");
    }
    const int count = register_count(version_, op.reg.type);
    if (count == 0) {
      line.fail_at(at, "register type '" + text.substr(0, digits) + "' (" +
                           register_name(op.reg.type) + ") is not in " + to_string(version_));
    }
    if (digits < text.size()) {
      if (text.size() - digits > 5) line.fail_at(at, "register index of '" + text + "' too large");
      op.reg.index = std::stoi(text.substr(digits));
    }
    const bool indexed = digits < text.size();
    if (line.accept('[')) {
      relative(line, op);
    } else if (!indexed && !single_register(op.reg.type)) {
      // "c" alone is no register: a cut line ("mad r0, r1, c") must not read as c0.
      line.fail_at(at, "expected an index after '" + text + "' (" + text + "0 to " + text +
                           std::to_string(count - 1) + ")");
    }
    if (op.reg.index >= count) {
      line.fail_at(at, text + " is past " + to_string(version_) + "'s " + std::to_string(count) +
                           " " + register_name(op.reg.type) + " registers (" +
                           text.substr(0, digits) + "0-" + text.substr(0, digits) +
                           std::to_string(count - 1) + ")");
    }
    while (line.accept('_')) {
      const std::string m = lower(line.alnum());
      if (m != "abs" || destination) {
        line.fail_at(at, "source modifier '_" + m + "' is not in " + to_string(version_) +
                             (m == "bias" || m == "bx2" || m == "x2" || m == "dz" || m == "dw"
                                  ? " (ps_1_x's)"
                                  : ""));
      }
      if (!is_model3(version_)) {
        line.fail_at(at, "the source modifier _abs is shader model 3's (vs_3_0, ps_3_0), not in " +
                             to_string(version_) + " (use the abs instruction)");
      }
    }
    if (line.accept('.')) {
      const std::string s = lower(line.alnum());
      if (s.empty() || s.size() > 4 || s.find_first_not_of("xyzwrgba") != std::string::npos) {
        line.fail_at(
            at,
            "expected a swizzle or write mask of x, y, z, w (or r, g, b, a), found '." + s + "'");
      }
    }
    return op;
  }

  // c[a0.x + 4], c4[a0.x], v[aL]: the address register must be one the version has.
  void relative(Line& line, Operand& op) {
    op.reg.relative = true;
    if (std::isdigit(static_cast<unsigned char>(line.peek()))) {
      const Position base_at = line.here();
      const std::string base = line.alnum();
      if (base.size() > 5 || base.find_first_not_of("0123456789") != std::string::npos) {
        line.fail_at(base_at, "expected a register offset, found '" + base + "'");
      }
      op.reg.index += std::stoi(base);
      line.expect('+', "'+' and an address register");
    }
    const Position at = line.here();
    const std::string address = lower(line.alnum());
    if (address != "a0" && address != "al") line.fail_at(at, "expected a0 or aL as the address");
    if (register_count(version_, address == "a0" ? "a" : "al") == 0) {
      line.fail_at(at, "relative addressing by " + address + " is not in " + to_string(version_));
    }
    if (line.accept('.')) line.alnum();
    if (line.accept('+')) {
      const Position offset_at = line.here();
      const std::string offset = line.alnum();
      if (offset.empty() || offset.find_first_not_of("0123456789") != std::string::npos ||
          offset.size() > 5) {
        line.fail_at(offset_at, "expected a register offset");
      }
      op.reg.index += std::stoi(offset);
    }
    line.expect(']', "']'");
  }

  Version version_;
};

// The version token of the first line with code, where it is; fails on anything else.
Version read_version(Line& line) {
  const Position at = line.here();
  const std::string token = lower(line.word());
  const std::optional<Version> v = parse_version(token);
  if (!v) {
    if (is_ps1x(token)) {
      line.fail_at(
          at, "pixel shader " + token + " is not read (ltrender reads " + version_list() + ")");
    }
    const bool looks = token.rfind("vs_", 0) == 0 || token.rfind("ps_", 0) == 0;
    line.fail_at(at, (looks ? "unknown version '" + token + "'"
                            : "expected a version token, found '" + token + "'") +
                         " (ltrender reads " + version_list() + ")");
  }
  if (!line.at_end()) line.expected("the end of the version line");
  return *v;
}

}  // namespace

Program parse(const std::string& source) {
  refuse_binary(source);
  std::vector<Line> lines = code_lines(source);
  Program program;
  size_t k = 0;
  while (k < lines.size() && lines[k].at_end()) ++k;
  if (k == lines.size()) {
    throw SyntaxError(
        {static_cast<int>(lines.size()), 1},
        "expected a version token (" + version_list() + "), found the end of the file");
  }
  program.version_at = lines[k].here();
  program.version = read_version(lines[k]);
  Parser parser(program.version);
  for (++k; k < lines.size(); ++k) {
    if (lines[k].at_end()) continue;
    program.instructions.push_back(parser.instruction(lines[k]));
  }
  return program;
}

bool starts_with_version(const std::string& source) {
  if (source.find('\0') != std::string::npos) return false;
  for (Line& line : code_lines(source)) {
    if (line.at_end()) continue;
    const std::string token = lower(line.word());
    return parse_version(token).has_value() || is_ps1x(token);
  }
  return false;
}

}  // namespace lt::d3d9
