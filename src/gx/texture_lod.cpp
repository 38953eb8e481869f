// The texture unit's level of detail (texture_lod.h).
#include "gx/texture_lod.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lt::gx {

TextureLod libogc_texture_lod(int minfilt, float minlod, float maxlod, float lodbias,
                              bool biasclamp, bool edgelod, int maxaniso) {
  static constexpr u8 kHwFilter[8] = {0x00, 0x04, 0x01, 0x05, 0x02, 0x06, 0x00, 0x00};
  TextureLod out;
  out.min_filter = kHwFilter[minfilt & 7];
  if (lodbias < -4.0f)
    lodbias = -4.0f;
  else if (lodbias == 4.0f)
    lodbias = 3.99f;
  // A bias far above 4 wraps in the 8-bit field; the min keeps the conversion defined in C++.
  const s32 scaled = static_cast<s32>(std::min(32.0f * lodbias, 2147483520.0f));
  out.bias = static_cast<std::int8_t>(static_cast<u8>(scaled & 0xff));
  out.diagonal = !edgelod;
  out.bias_clamp = biasclamp;
  out.max_aniso = static_cast<u8>(maxaniso & 3);
  const auto lod_field = [](float lod) {
    lod = std::clamp(lod, 0.0f, 10.0f);
    return static_cast<u8>(static_cast<u32>(16.0f * lod) & 0xff);
  };
  out.min_lod = lod_field(minlod);
  out.max_lod = lod_field(maxlod);
  return out;
}

TextureLod mipmapped_texture_lod(bool indexed) {
  TextureLod out;
  out.min_filter = indexed ? 5 : 6;
  return out;
}

s32 fixed_log2(float f) {
  u32 x;
  std::memcpy(&x, &f, sizeof x);
  // [DSW FixedLog2]: "((x & 0x7F800000) >> 19) - 2032" (exponent * 16 - 127 * 16) and
  // "(x & 0x007fffff) >> 19" (the mantissa's top four bits).
  const s32 integer_part = static_cast<s32>((x & 0x7F800000u) >> 19) - 2032;
  const s32 fraction = static_cast<s32>((x & 0x007FFFFFu) >> 19);
  return integer_part + fraction;
}

LodChoice quad_lod(const TextureLod& mode, bool mag_linear, const QuadTexcoords& q) {
  const float dudx = std::fabs(q.u00 - q.u10), dvdx = std::fabs(q.v00 - q.v10);
  const float dudy = std::fabs(q.u00 - q.u01), dvdy = std::fabs(q.v00 - q.v01);
  float s_delta, t_delta;
  if (mode.diagonal) {
    s_delta = dudx + dudy;
    t_delta = dvdx + dvdy;
  } else {
    s_delta = std::max(dudx, dudy);
    t_delta = std::max(dvdx, dvdy);
  }
  s32 lod = fixed_log2(std::max(s_delta, t_delta));
  // "bias is s2.5": the 8-bit field sign-extended, then >> 1 to the LOD's 4 fractional bits.
  lod += static_cast<s32>(mode.bias) >> 1;
  LodChoice out;
  out.linear = (lod > 0 && mode.min_linear()) || (lod <= 0 && mag_linear);
  // "The order of comparisons for this clamp check matters."
  if (lod > static_cast<s32>(mode.max_lod))
    lod = mode.max_lod;
  else if (lod < static_cast<s32>(mode.min_lod))
    lod = mode.min_lod;
  out.lod = lod;
  return out;
}

MipChoice mip_choice(const TextureLod& mode, s32 lod) {
  MipChoice out;
  const int mip = mode.mip_filter();
  if (lod <= 0 || mip == 0) return out;
  out.level = lod >> 4;
  const int fraction = lod & 0xf;
  if (mip == 2) out.fraction = fraction;       // MipMode::Linear
  if (mip == 1 && fraction >= 8) ++out.level;  // MipMode::Point rounds to the nearer level
  return out;
}

int reachable_levels(const TextureLod& mode) {
  if (mode.mip_filter() == 0) return 1;
  const int highest = std::max(mode.min_lod, mode.max_lod);
  return (highest >> 4) + 1 + ((highest & 0xf) != 0 ? 1 : 0);
}

bool lod_matters(const TextureLod& mode, bool mag_linear) {
  if (mode.min_linear() != mag_linear) return true;
  return mode.mip_filter() != 0 && (mode.min_lod > 0 || mode.max_lod > 0);
}

}  // namespace lt::gx
