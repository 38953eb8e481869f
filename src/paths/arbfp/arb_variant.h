// The arbfp path's variants: how the fragment program evaluates the lobe t^p, by --variant name.
#pragma once

#include <string>

#include "model/power_lut.h"

namespace lt::arbfp {

// How the fragment program evaluates the lobe t^p (model.md "Where the paths lose accuracy").
enum class PowMethod {
  Exact,         // POW, with t = 0 selected to 0 by CMP (POW is EX2(p * LG2(t)): LG2(0) = -inf)
  Lut,           // 1D texture of t^p per material (model::PowerLut), one MAD + one TEX
  Sg,            // exp2(n' * (t - 1)), n' = 1.4427 p + 1.4427 (the spherical-Gaussian form)
  SgSimplified,  // exp2(p * (t - 1)): a different curve, ~35-40 LSB off (model.md)
  SgFitted,      // exp2(n' * (t - 1)) with n' fitted per material to the max error against t^p
  Mul,           // t^p by repeated squaring for integer p; non-integer p falls back to Exact
};

struct PowVariant {
  PowMethod method = PowMethod::Exact;
  int lut_size = 256;                                  // Lut only
  model::LutFormat lut_format = model::LutFormat::U8;  // Lut only
  // Mul only ("pow=mul:vertex"): t, the lobe and (lobe * s + a) in the vertex program, which
  // passes them four lights to a texcoord; the fragment program keeps diffuse and attenuation
  // per pixel. The cheapest fragment program, at the price of Gouraud-interpolating the lobe.
  bool per_vertex = false;
  // ":guards=all": every hard-case guard in the fragment program, also those the scene cannot
  // trigger (arb_guards.h drops those by default); the same image, a longer program.
  bool all_guards = false;

  std::string name() const;  // as given to --variant, e.g. "pow=lut:256:u8"
};

// Parses a --variant name ("pow=exact", "pow=lut:N:u8|f16|f32", "pow=sg", "pow=sg-simplified",
// "pow=sg-fitted", "pow=mul", "pow=mul:vertex"), each with an optional ":guards=all". Throws
// InputError("--variant", name, ...) when malformed.
PowVariant parse_variant(const std::string& name);

}  // namespace lt::arbfp
