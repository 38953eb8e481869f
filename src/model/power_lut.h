// The precomputed power lookup table ("can precompute powers in order to get rid of the pow()",
// GDC 2011): lobe(t, p) = t^p sampled on [0, 1], built on the CPU in double and stored as the
// texels a GPU path uploads. Shared by the arbfp path (1D/2D texture lookup in the fragment
// program) and the combiners path (texture unit fed by a per-vertex or texgen coordinate).
//
// Texel-centre addressing: texel i (of N) holds t_i = i / (N - 1), so t = 0 and t = 1 are exact
// texels. GL samples texel centres at u = (i + 0.5) / N, so a program must look up
//   u = t * (N - 1) / N + 0.5 / N
// (one MAD) to make linear filtering interpolate between t_i and t_{i+1}. Without that remap the
// ends are off by half a texel, which for large p is most of the lobe.
#pragma once

#include <string>
#include <vector>

namespace lt::model {

enum class LutFormat { U8, F16, F32 };
const char* to_string(LutFormat f);

struct PowerLut {
  int size = 0;  // N texels per row, N >= 2
  LutFormat format = LutFormat::U8;
  std::vector<double> powers;  // one row per power (a 1D LUT has one row; 2D over (t, power))
  std::vector<float> texels;   // rows * size values, already quantised to `format`

  // Builds in double, quantises once (u8: round to nearest of 255 steps; f16: round to nearest
  // half, denormals kept; f32: float). 0^0 := 1 as in model::lobe.
  static PowerLut build(int size, LutFormat format, std::vector<double> powers);

  int rows() const { return static_cast<int>(powers.size()); }
  float texel(int row, int i) const { return texels[static_cast<size_t>(row) * size + i]; }
  // The texture coordinate that samples t under texel-centre addressing (see above).
  double coordinate(double t) const { return t * (size - 1) / size + 0.5 / size; }
  // What GL_LINEAR filtering returns for t in row `row`, computed in double (for error bounds).
  double sample_linear(int row, double t) const;
};

}  // namespace lt::model
