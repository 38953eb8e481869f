// A combiner program: the GL 1.3 texture-environment state (ARB_texture_env_combine, crossbar,
// dot3) of one rendering pass, written as a small text file in combiners/ (format in
// combiners/README.md). Parsed here, applied to GL here; the combiners path only decides which
// program a material needs and what the named textures and constants hold.
//
// GL 1.3 numbering, kept on purpose: stage N is texture unit N's environment. GL skips the
// environment of a unit whose texturing is disabled, so a stage that samples nothing still binds
// a texture (`white`) to run at all, and every stage costs a texture unit.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "gl/gl.h"

namespace lt::combiners {

// GL_MAX_TEXTURE_UNITS on the widest profile we target (Mesa, and the Wii's 8 texture maps).
inline constexpr int kMaxStages = 8;

enum class Function { Replace, Modulate, Add, AddSigned, Interpolate, Subtract, Dot3Rgb, Dot3Rgba };
enum class Source { Texture, TextureUnit, Constant, Primary, Previous };
enum class Operand { Color, OneMinusColor, Alpha, OneMinusAlpha };
enum class TexCoord { None, Array, NormalMap };

struct Argument {
  Source source = Source::Previous;
  int unit = -1;  // Source::TextureUnit only (crossbar: texture<unit>)
  Operand operand = Operand::Color;
};

struct Combine {
  Function function = Function::Replace;
  std::vector<Argument> args;
  int scale = 1;  // 1, 2 or 4; 0 = "fit" (rgb only): picked from the stage constant when applied
};

struct Stage {
  int line = 0;                  // where `stage N` is, for errors about the stage as a whole
  std::string texture = "none";  // none | white | power_lut | lobe_cube
  TexCoord texcoord = TexCoord::None;
  Combine rgb, alpha;
  bool has_alpha = false;           // absent: alpha REPLACE previous (primary alpha at stage 0)
  std::string constant_name;        // a constant the path supplies, or empty
  glm::dvec4 constant{0, 0, 0, 0};  // a literal constant (when constant_name is empty)
};

struct CombinerProgram {
  std::string name;        // `program NAME`, or the file name
  std::string file;        // for errors
  bool color_sum = false;  // add the secondary colour after the last stage (GL 1.4 colour sum)
  std::vector<Stage> stages;

  // Distinct named constants plus literal constants that are not zero.
  int constant_colors() const;
};

// Parses program text. Throws InputError(file, line, what) for every mistake.
CombinerProgram parse_combiner_program(const std::string& text, const std::string& file);
// A program shipped in combiners/ (embedded at build time), e.g. "lobe_vertex.comb".
CombinerProgram load_combiner_program(const std::string& name);

// What the path binds to a program's names when applying it.
struct TextureBinding {
  GLenum target = GL_TEXTURE_2D;
  GLuint id = 0;
};
struct ProgramInputs {
  std::map<std::string, TextureBinding> textures;  // by the names a program's `texture` uses
  std::map<std::string, glm::dvec4> constants;     // true magnitude; `fit` divides by the scale
};

// What applying set, per stage: the scale and constant GL got, and whether the constant had to
// be clamped (a magnitude over 4 cannot be shown by any scale; the caller avoids that).
struct AppliedStage {
  float rgb_scale = 1, alpha_scale = 1;
  glm::vec4 constant{0};
  bool constant_clamped = false;
};

// Sets texture env, bindings, texgen and colour sum for every stage, disables the units above
// them. Throws InputError(program file, stage line) for a name `inputs` does not provide.
std::vector<AppliedStage> apply(const CombinerProgram& program, const ProgramInputs& inputs);
// Back to GL defaults: every unit MODULATE with texturing and texgen off, colour sum off.
void reset_texture_state(int units);

// The smallest of 1, 2, 4 that brings `max_channel` into [0, 1] (4 when nothing does).
int fit_scale(double max_channel);

}  // namespace lt::combiners
