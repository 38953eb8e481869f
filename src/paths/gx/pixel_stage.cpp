#include "paths/gx/pixel_stage.h"

#include <algorithm>
#include <cmath>

#include "core/parallel_rows.h"

namespace lt::gx {

namespace {

// The 8-bit value of an interpolated channel colour (0..255 as a float). Real hardware
// interpolates in fixed point of unpublished precision (Dolphin PR#2075: "GC/Wii does
// fixed-point interpolation"); Dolphin's software rasteriser truncates a float [DSW Rasterizer
// Draw]. Truncating the float alone would turn float noise (a flat 200 interpolated as
// 199.99998) into a lost LSB, so the interpolant is first rounded to 8 fractional bits, as a
// fixed-point interpolator with 8 fractional bits would hold it, then truncated. `round`: the
// shader backends' iround(col) instead [DHW tev_ras_table], the other side of gx-hardware.md §2.5.
u8 interpolated_color(float v, bool round) {
  if (!(v > 0)) return 0;  // also NaN
  if (round) return static_cast<u8>(std::min(255.0, std::floor(static_cast<double>(v) + 0.5)));
  const double fixed = std::floor(static_cast<double>(v) * 256.0 + 0.5);
  return static_cast<u8>(std::min(255.0, std::floor(fixed / 256.0)));
}

// The texel stage `s` fetches at this pixel.
Color8 stage_texel(const PixelProgram& p, const TevStage& stage, const AttributeRasteriser& raster,
                   size_t g) {
  const TextureObject* tex = p.textures[stage.texmap];
  const int texgens = p.state->texgen.num_texgens;
  // Zero texgens read a black texel, and a texcoord beyond them reads texcoord 0 (Dolphin's
  // model, "further hardware testing is needed" [DSW Tev::Draw]); GX_TEXCOORDNULL with a map
  // programs texcoord 0 [OGC gx.c GX_SetTevOrder].
  if (!tex || texgens == 0) return {};
  int tc = stage.texcoord == kTexCoordNull ? 0 : stage.texcoord;
  if (tc >= texgens) tc = 0;
  const float* stq = raster.texcoord(tc, g);
  float s = stq[0], t = stq[1];
  // A 3x4 texgen's q divides after interpolation; q = 0 is special-cased on hardware
  // [DSW TransformTexCoordRegular] and is read as 1 here.
  if (p.state->texgen.texgens[static_cast<size_t>(tc)].type == 0 && stq[2] != 0.0f) {
    s /= stq[2];
    t /= stq[2];
  }
  return sample_texture(*tex, to_fixed_texcoord(s, tex->width), to_fixed_texcoord(t, tex->height));
}

}  // namespace

size_t shade_pass(const AttributeRasteriser& raster, const std::vector<PixelProgram>& by_material,
                  std::vector<Color8>& efb, bool round_colors) {
  const int width = raster.width(), height = raster.height();
  std::vector<size_t> stage_pixels(worker_threads(), 0);
  for_each_row_in_parallel(height, [&](int gy, unsigned worker) {
    TevPixelInputs in;
    for (int x = 0; x < width; ++x) {
      const size_t g = raster.index(x, gy);
      if (!raster.covered(g)) continue;
      const int m = raster.material(g);
      if (m < 0 || static_cast<size_t>(m) >= by_material.size()) continue;
      const PixelProgram& p = by_material[static_cast<size_t>(m)];
      if (!p.state) continue;
      const GxState& st = *p.state;
      for (int ch = 0; ch < kMaxChannels; ++ch) {
        const float* c = raster.color(ch, g);
        for (int k = 0; k < 4; ++k)
          in.channels[static_cast<size_t>(ch)][k] = interpolated_color(c[k], round_colors);
      }
      for (int s = 0; s < st.tev.num_stages; ++s) {
        const TevStage& stage = st.tev.stages[static_cast<size_t>(s)];
        in.texels[static_cast<size_t>(s)] =
            stage.texmap == kTexMapNull ? Color8{} : stage_texel(p, stage, raster, g);
      }
      stage_pixels[worker] += static_cast<size_t>(st.tev.num_stages);
      const Color8 src = tev_to_efb(run_tev(st.tev, in));
      if (!alpha_test(st.alpha_compare, src.a)) continue;
      Color8& dst = efb[static_cast<size_t>(gy) * width + x];
      dst = blend(st.blend, src, dst);
    }
  });
  size_t total = 0;
  for (size_t n : stage_pixels) total += n;
  return total;
}

}  // namespace lt::gx
