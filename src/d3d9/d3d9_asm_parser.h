// Direct3D 9 shader assembly text (fxc /Fc listings, the d3d9 subprograms of compiled Unity
// shaders) read into a Program. The syntax is the documentation's ("Asm Shader Reference",
// learn.microsoft.com direct3dhlsl/dx9-graphics-reference-asm): one instruction a line, `//` and
// `;` comments, the version token first; instruction modifiers _sat _pp _centroid and comparison
// suffixes after the name; a predicate "(p0.x)" or "(!p0)" before it; source negate, _abs,
// swizzles, destination masks, relative addressing c[a0.x + n] / c3[aL]. What the version lacks
// is refused where it is written: an instruction, a modifier, a register type or an index past
// the version's register file.
#pragma once

#include <string>

#include "d3d9/d3d9_asm_program.h"

namespace lt::d3d9 {

// Throws arbfp::text::SyntaxError at the first line and column that is not a valid program of
// its version.
Program parse(const std::string& source);

// True when the first line with code (after blank lines and comments) is a version token the
// reader takes or refuses by name (ps_1_x): how `ltrender budget` knows the text by its content.
bool starts_with_version(const std::string& source);

}  // namespace lt::d3d9
