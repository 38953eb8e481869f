#include "combiner/combiner_program.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/fs.h"
#include "gl/context.h"
#include "gl/program.h"

namespace lt::combiners {

namespace {

struct FunctionInfo {
  const char* name;
  Function function;
  int args;
  GLenum gl;
};

constexpr FunctionInfo kFunctions[] = {
    {"REPLACE", Function::Replace, 1, GL_REPLACE},
    {"MODULATE", Function::Modulate, 2, GL_MODULATE},
    {"ADD", Function::Add, 2, GL_ADD},
    {"ADD_SIGNED", Function::AddSigned, 2, GL_ADD_SIGNED},
    {"INTERPOLATE", Function::Interpolate, 3, GL_INTERPOLATE},
    {"SUBTRACT", Function::Subtract, 2, GL_SUBTRACT},
    {"DOT3_RGB", Function::Dot3Rgb, 2, GL_DOT3_RGB},
    {"DOT3_RGBA", Function::Dot3Rgba, 2, GL_DOT3_RGBA},
};

const FunctionInfo& info(Function f) {
  for (const FunctionInfo& i : kFunctions) {
    if (i.function == f) return i;
  }
  LT_CHECK(false, "unknown combiner function");
  return kFunctions[0];
}

// One file being parsed: every error names the file and the current line.
class Parser {
 public:
  Parser(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  CombinerProgram run() {
    CombinerProgram prog;
    prog.file = file_;
    prog.name = file_;
    // A UTF-8 byte-order mark (a Windows editor's) is no part of the program.
    std::istringstream in(starts_with_utf8_bom(text_) ? text_.substr(kUtf8Bom.size()) : text_);
    std::string raw;
    Stage* stage = nullptr;
    std::set<std::string> seen;  // directives already given in the current stage
    bool seen_program = false, seen_color_sum = false;
    while (std::getline(in, raw)) {
      ++line_;
      const auto hash = raw.find('#');
      std::istringstream words(hash == std::string::npos ? raw : raw.substr(0, hash));
      std::vector<std::string> w;
      for (std::string s; words >> s;) w.push_back(s);
      if (w.empty()) continue;
      const std::string& key = w[0];
      if (key == "program") {
        expect_count(w, 2, "program NAME");
        if (seen_program) fail("program given twice");
        if (!prog.stages.empty()) fail("`program` must come before the first stage");
        seen_program = true;
        prog.name = w[1];
      } else if (key == "color_sum") {
        expect_count(w, 2, "color_sum on|off");
        if (seen_color_sum) fail("color_sum given twice");
        seen_color_sum = true;
        if (w[1] != "on" && w[1] != "off") fail("color_sum must be on or off, not '" + w[1] + "'");
        prog.color_sum = w[1] == "on";
      } else if (key == "stage") {
        expect_count(w, 2, "stage N");
        const int n = parse_int(w[1], "stage number");
        if (n != static_cast<int>(prog.stages.size())) {
          fail("stage " + w[1] + " out of order: expected stage " +
               std::to_string(prog.stages.size()) + " (stage N runs on texture unit N)");
        }
        if (n >= kMaxStages) fail("stage " + w[1] + ": at most " + std::to_string(kMaxStages));
        if (stage) finish(*stage);
        prog.stages.emplace_back();
        stage = &prog.stages.back();
        stage->line = line_;
        seen.clear();
      } else {
        if (!stage) fail("'" + key + "' outside a stage (start one with `stage 0`)");
        if (!seen.insert(key).second) fail("'" + key + "' given twice in this stage");
        stage_directive(*stage, w);
      }
    }
    if (stage) finish(*stage);
    if (prog.stages.empty()) {
      line_ = std::max(line_, 1);
      fail("no stages");
    }
    // Crossbar sources must name a unit that has a texture (GL reads black otherwise, silently).
    for (const Stage& s : prog.stages) {
      for (const Combine* c : {&s.rgb, &s.alpha}) {
        for (const Argument& a : c->args) {
          if (a.source != Source::TextureUnit) continue;
          line_ = s.line;
          if (a.unit >= static_cast<int>(prog.stages.size())) {
            fail("texture" + std::to_string(a.unit) + ": the program has no unit " +
                 std::to_string(a.unit));
          }
          if (prog.stages[a.unit].texture == "none") {
            fail("texture" + std::to_string(a.unit) + ": unit " + std::to_string(a.unit) +
                 " binds no texture");
          }
        }
      }
    }
    return prog;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_, std::to_string(line_), what);
  }

  void expect_count(const std::vector<std::string>& w, size_t n, const std::string& usage) const {
    if (w.size() != n) fail("expected `" + usage + "`");
  }

  int parse_int(const std::string& s, const std::string& what) const {
    try {
      size_t used = 0;
      const int v = std::stoi(s, &used);
      if (used == s.size()) return v;
    } catch (const std::exception&) {
    }
    fail(what + " must be an integer, not '" + s + "'");
  }

  // Finite numbers only: stod reads "nan" and "inf", and a NaN passes every range check after it
  // (NaN < 0 and NaN > 1 are both false).
  double parse_double(const std::string& s) const {
    try {
      size_t used = 0;
      const double v = std::stod(s, &used);
      if (used == s.size() && std::isfinite(v)) return v;
      if (used == s.size()) fail("'" + s + "' is not a finite number");
    } catch (const std::logic_error&) {  // invalid_argument, out_of_range
    }
    fail("'" + s + "' is not a number");
  }

  void stage_directive(Stage& stage, const std::vector<std::string>& w) {
    const std::string& key = w[0];
    if (key == "texture") {
      // Any name: the path that applies the program provides its textures by name, and apply()
      // names the line of one it does not provide. So a new texture needs no parser change.
      expect_count(w, 2, "texture none|NAME");
      const bool identifier = std::all_of(w[1].begin(), w[1].end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
      });
      if (!identifier) fail("texture '" + w[1] + "' is not a name (letters, digits, _)");
      stage.texture = w[1];
    } else if (key == "texcoord") {
      expect_count(w, 2, "texcoord none|array|normal_map");
      if (w[1] == "none") {
        stage.texcoord = TexCoord::None;
      } else if (w[1] == "array") {
        stage.texcoord = TexCoord::Array;
      } else if (w[1] == "normal_map") {
        stage.texcoord = TexCoord::NormalMap;
      } else {
        fail("unknown texcoord '" + w[1] + "' (valid: none, array, normal_map)");
      }
    } else if (key == "rgb" || key == "alpha") {
      const bool rgb = key == "rgb";
      if (w.size() < 2) fail("expected `" + key + " FUNCTION ARG...`");
      Combine& c = rgb ? stage.rgb : stage.alpha;
      const int old_scale = c.scale;
      c = parse_combine(w, rgb);
      c.scale = old_scale;
      if (!rgb) stage.has_alpha = true;
    } else if (key == "rgb_scale" || key == "alpha_scale") {
      expect_count(w, 2, key + " 1|2|4");
      const bool rgb = key == "rgb_scale";
      if (rgb && w[1] == "fit") {
        stage.rgb.scale = 0;
        return;
      }
      const int s = parse_int(w[1], key);
      // The only factors GL_RGB_SCALE / GL_ALPHA_SCALE accept (and the TEV's "scale" field).
      if (s != 1 && s != 2 && s != 4) {
        fail(key + " must be 1, 2 or 4" + std::string(rgb ? " or fit" : "") + ", not " + w[1]);
      }
      (rgb ? stage.rgb : stage.alpha).scale = s;
    } else if (key == "constant") {
      if (w.size() == 2) {
        stage.constant_name = w[1];
      } else if (w.size() == 5) {
        for (int i = 0; i < 4; ++i) {
          const double v = parse_double(w[1 + i]);
          // GL clamps TEXTURE_ENV_COLOR to [0, 1]; a literal outside would silently change.
          if (v < 0 || v > 1) fail("constant component " + w[1 + i] + " outside [0, 1]");
          stage.constant[i] = v;
        }
      } else {
        fail("expected `constant NAME` or `constant R G B A`");
      }
    } else {
      fail("unknown directive '" + key +
           "' (valid: texture, texcoord, rgb, alpha, rgb_scale, alpha_scale, constant)");
    }
  }

  Combine parse_combine(const std::vector<std::string>& w, bool rgb) const {
    Combine c;
    const FunctionInfo* fi = nullptr;
    for (const FunctionInfo& i : kFunctions) {
      if (w[1] == i.name) fi = &i;
    }
    if (!fi) {
      fail("unknown function '" + w[1] +
           "' (valid: REPLACE, MODULATE, ADD, ADD_SIGNED, INTERPOLATE, SUBTRACT, DOT3_RGB, "
           "DOT3_RGBA)");
    }
    if (!rgb && (fi->function == Function::Dot3Rgb || fi->function == Function::Dot3Rgba)) {
      fail(std::string(fi->name) + " is an rgb function (DOT3_RGBA writes alpha itself)");
    }
    const int given = static_cast<int>(w.size()) - 2;
    if (given != fi->args) {
      fail(std::string(fi->name) + " takes " + std::to_string(fi->args) + " argument" +
           (fi->args == 1 ? "" : "s") + ", got " + std::to_string(given));
    }
    c.function = fi->function;
    for (int i = 0; i < given; ++i) c.args.push_back(parse_argument(w[2 + i], rgb));
    return c;
  }

  // [1-]SOURCE[.alpha]: SOURCE is texture, texture0..7, constant, primary or previous.
  Argument parse_argument(std::string s, bool rgb) const {
    const std::string original = s;
    Argument a;
    bool invert = false, alpha = !rgb;
    if (s.rfind("1-", 0) == 0) {
      invert = true;
      s = s.substr(2);
    }
    const auto dot = s.find('.');
    if (dot != std::string::npos) {
      const std::string op = s.substr(dot + 1);
      s = s.substr(0, dot);
      if (op == "alpha") {
        alpha = true;
      } else if (op == "color" && rgb) {
        alpha = false;
      } else {
        fail("'" + original + "': operand must be ." + (rgb ? "color or .alpha" : "alpha") +
             " in an " + (rgb ? "rgb" : "alpha") + " function");
      }
    }
    if (s == "texture") {
      a.source = Source::Texture;
    } else if (s == "constant") {
      a.source = Source::Constant;
    } else if (s == "primary") {
      a.source = Source::Primary;
    } else if (s == "previous") {
      a.source = Source::Previous;
    } else if (s.size() == 8 && s.rfind("texture", 0) == 0 && s[7] >= '0' && s[7] <= '7') {
      a.source = Source::TextureUnit;
      a.unit = s[7] - '0';
    } else {
      fail("unknown source '" + original +
           "' (valid: texture, texture0..texture7, constant, primary, previous, with 1- and "
           ".alpha)");
    }
    a.operand = alpha ? (invert ? Operand::OneMinusAlpha : Operand::Alpha)
                      : (invert ? Operand::OneMinusColor : Operand::Color);
    return a;
  }

  void finish(Stage& stage) {
    const int saved = line_;
    line_ = stage.line;
    if (stage.rgb.args.empty()) fail("stage has no `rgb` function");
    auto reads_texture = [](const Combine& c) {
      return std::any_of(c.args.begin(), c.args.end(),
                         [](const Argument& a) { return a.source == Source::Texture; });
    };
    if (stage.texture == "none" && (reads_texture(stage.rgb) || reads_texture(stage.alpha))) {
      fail("stage reads `texture` but binds none (add `texture NAME`)");
    }
    if (stage.texture == "none" && stage.texcoord != TexCoord::None) {
      fail("texcoord without a texture");
    }
    if (stage.rgb.scale == 0 && stage.constant_name.empty()) {
      fail("rgb_scale fit needs a named constant to fit");
    }
    if (!stage.has_alpha) {
      stage.alpha.function = Function::Replace;
      stage.alpha.args = {Argument{Source::Previous, -1, Operand::Alpha}};
    }
    line_ = saved;
  }

  const std::string& text_;
  std::string file_;
  int line_ = 0;
};

GLenum gl_source(const Argument& a) {
  switch (a.source) {
    case Source::Texture:
      return GL_TEXTURE;
    case Source::TextureUnit:
      return static_cast<GLenum>(GL_TEXTURE0 + a.unit);
    case Source::Constant:
      return GL_CONSTANT;
    case Source::Primary:
      return GL_PRIMARY_COLOR;
    case Source::Previous:
      return GL_PREVIOUS;
  }
  return GL_PREVIOUS;
}

GLenum gl_operand(Operand o) {
  switch (o) {
    case Operand::Color:
      return GL_SRC_COLOR;
    case Operand::OneMinusColor:
      return GL_ONE_MINUS_SRC_COLOR;
    case Operand::Alpha:
      return GL_SRC_ALPHA;
    case Operand::OneMinusAlpha:
      return GL_ONE_MINUS_SRC_ALPHA;
  }
  return GL_SRC_COLOR;
}

void set_combine(const Combine& c, bool rgb) {
  const GLenum sources[] = {GL_SRC0_RGB, GL_SRC1_RGB, GL_SRC2_RGB};
  const GLenum operands[] = {GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB};
  const GLenum asources[] = {GL_SRC0_ALPHA, GL_SRC1_ALPHA, GL_SRC2_ALPHA};
  const GLenum aoperands[] = {GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA};
  glTexEnvi(GL_TEXTURE_ENV, rgb ? GL_COMBINE_RGB : GL_COMBINE_ALPHA,
            static_cast<GLint>(info(c.function).gl));
  for (size_t i = 0; i < c.args.size(); ++i) {
    glTexEnvi(GL_TEXTURE_ENV, rgb ? sources[i] : asources[i],
              static_cast<GLint>(gl_source(c.args[i])));
    glTexEnvi(GL_TEXTURE_ENV, rgb ? operands[i] : aoperands[i],
              static_cast<GLint>(gl_operand(c.args[i].operand)));
  }
}

const GLenum kTexTargets[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP};

void disable_unit(int unit) {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  for (GLenum t : kTexTargets) glDisable(t);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

}  // namespace

int CombinerProgram::constant_colors() const {
  std::set<std::string> names;
  int literals = 0;
  for (const Stage& s : stages) {
    if (!s.constant_name.empty()) {
      names.insert(s.constant_name);
    } else if (s.constant != glm::dvec4(0)) {
      ++literals;
    }
  }
  return static_cast<int>(names.size()) + literals;
}

CombinerProgram parse_combiner_program(const std::string& text, const std::string& file) {
  return Parser(text, file).run();
}

CombinerProgram load_combiner_program(const std::string& name) {
  const std::string path = "combiners/" + name;
  return parse_combiner_program(gl::read_shader_source(path), path);
}

int fit_scale(double max_channel) {
  for (int s : {1, 2, 4}) {
    if (max_channel <= s) return s;
  }
  return 4;
}

std::vector<AppliedStage> apply(const CombinerProgram& program, const ProgramInputs& inputs) {
  std::vector<AppliedStage> out;
  for (size_t i = 0; i < program.stages.size(); ++i) {
    const Stage& s = program.stages[i];
    const int unit = static_cast<int>(i);
    disable_unit(unit);
    if (s.texture != "none") {
      const auto it = inputs.textures.find(s.texture);
      if (it == inputs.textures.end()) {
        throw InputError(program.file, std::to_string(s.line),
                         "texture '" + s.texture + "' is not provided by this path");
      }
      glBindTexture(it->second.target, it->second.id);
      glEnable(it->second.target);
    }
    if (s.texcoord == TexCoord::NormalMap) {
      // Eye-space normal as (s, t, r): the texture matrix of this unit maps it further.
      for (GLenum c : {GL_S, GL_T, GL_R}) glTexGeni(c, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
      glEnable(GL_TEXTURE_GEN_S);
      glEnable(GL_TEXTURE_GEN_T);
      glEnable(GL_TEXTURE_GEN_R);
    }
    AppliedStage a;
    glm::dvec4 constant = s.constant;
    if (!s.constant_name.empty()) {
      const auto it = inputs.constants.find(s.constant_name);
      if (it == inputs.constants.end()) {
        throw InputError(program.file, std::to_string(s.line),
                         "constant '" + s.constant_name + "' is not provided by this path");
      }
      constant = it->second;
    }
    int rgb_scale = s.rgb.scale;
    if (rgb_scale == 0) {
      // `fit`: the constant arrives in true magnitude and is shown as constant/scale * scale, so
      // magnitudes up to 4 survive GL's clamp of TEXTURE_ENV_COLOR to [0, 1].
      rgb_scale = fit_scale(std::max({constant.r, constant.g, constant.b}));
      constant = glm::dvec4(glm::dvec3(constant) / static_cast<double>(rgb_scale), constant.a);
    }
    for (int c = 0; c < 4; ++c) {
      a.constant_clamped = a.constant_clamped || constant[c] < 0 || constant[c] > 1;
      a.constant[c] = static_cast<float>(std::clamp(constant[c], 0.0, 1.0));
    }
    a.rgb_scale = static_cast<float>(rgb_scale);
    a.alpha_scale = static_cast<float>(s.alpha.scale);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    set_combine(s.rgb, true);
    set_combine(s.alpha, false);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, a.rgb_scale);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, a.alpha_scale);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &a.constant[0]);
    out.push_back(a);
  }
  for (int unit = static_cast<int>(program.stages.size()); unit < kMaxStages; ++unit) {
    disable_unit(unit);
  }
  glActiveTexture(GL_TEXTURE0);
  if (program.color_sum) {
    glEnable(GL_COLOR_SUM);
  } else {
    glDisable(GL_COLOR_SUM);
  }
  gl::check_error("applying a combiner program");
  return out;
}

void reset_texture_state(int units) {
  for (int unit = 0; unit < units; ++unit) {
    disable_unit(unit);
    glBindTexture(GL_TEXTURE_1D, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_COLOR_SUM);
}

}  // namespace lt::combiners
