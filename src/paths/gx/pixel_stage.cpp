#include "paths/gx/pixel_stage.h"

#include <algorithm>

#include "core/parallel_rows.h"

namespace lt::gx {

namespace {

// Rows a worker takes at a time: small enough that two workers share a small object's rows,
// large enough that a triangle's bounds are tested once for several rows.
constexpr int kBandRows = 4;

// The texel stage `s` fetches at this pixel [DSW Tev::Draw, TextureSampler::Sample].
Color8 stage_texel(const PixelProgram& p, const TevStage& stage, const RasterPixel& px) {
  const TextureObject* tex = p.textures[stage.texmap & 7];
  const int texgens = p.state->texgen.num_texgens;
  // Zero texgens read a black texel here (Dolphin reads whatever texture coordinate its TEV last
  // held); a texcoord beyond them reads texcoord 0 ("Quirk: when the tex coord is not less than
  // the number of tex gens ... tex coord 0 is used" [DSW Tev::Draw]); GX_TEXCOORDNULL with a map
  // programs texcoord 0 [OGC gx.c GX_SetTevOrder].
  if (!tex || texgens == 0) return {};
  int tc = stage.texcoord == kTexCoordNull ? 0 : stage.texcoord;
  if (tc >= texgens) tc = 0;
  const auto& uv = px.uv[static_cast<size_t>(tc)];
  return sample_texture(*tex, uv[0], uv[1]);
}

// One covered pixel, as [DSW Draw] then [DSW Tev::Draw] take it.
void shade_pixel(const PixelProgram& p, const RasterPixel& px, s32 x, s32 y, size_t index, Efb& efb,
                 PixelCounts& counts) {
  const GxState& st = *p.state;
  ++counts.covered;
  // GX_Init's GX_SetZCompLoc(GX_TRUE) puts the depth test before texturing [DSW Draw, "early
  // z"; BPMemory.h GetEmulatedZ], so a pixel the alpha test then discards has written its
  // depth. With the test off nothing is compared or written.
  if (st.z.enable) {
    u32& depth = efb.depth[index];
    if (!z_compare(st.z.func, px.z, depth)) {
      ++counts.z_failed;
      return;
    }
    if (st.z.update) depth = px.z & 0xffffff;  // [DSW SetPixelDepth]: 24 bits kept
  }
  TevPixelInputs in;
  in.channels = px.color;
  for (int s = 0; s < st.tev.num_stages; ++s) {
    const TevStage& stage = st.tev.stages[static_cast<size_t>(s)];
    in.texels[static_cast<size_t>(s)] =
        stage.texmap == kTexMapNull ? Color8{} : stage_texel(p, stage, px);
  }
  counts.stage_pixels += static_cast<size_t>(st.tev.num_stages);
  const Color8 src = tev_to_efb(run_tev(st.tev, in));
  if (!alpha_test(st.alpha_compare, src.a)) {
    ++counts.alpha_failed;
    return;
  }
  // [DSW BlendTev]: the EFB's colour as it reads back, blended, dithered and stored in the
  // frame's pixel format (GX_Init's colour and alpha updates on, destination alpha off).
  Color8& dst = efb.color[index];
  dst = efb_written(efb.pixel_format, st.dither, x, y, blend(st.blend, src, dst));
  ++counts.written;
}

}  // namespace

void PixelCounts::add(const PixelCounts& o) {
  covered += o.covered;
  z_failed += o.z_failed;
  alpha_failed += o.alpha_failed;
  written += o.written;
  stage_pixels += o.stage_pixels;
}

PixelCounts draw_triangles(const std::vector<Triangle>& triangles, const PixelProgram& program,
                           bool round_colors, Efb& efb) {
  std::vector<PixelCounts> per_worker(worker_threads());
  const int bands = (efb.height + kBandRows - 1) / kBandRows;
  for_each_row_in_parallel(bands, [&](int band, unsigned worker) {
    PixelCounts& counts = per_worker[worker];
    const s32 y0 = band * kBandRows, y1 = std::min(efb.height, y0 + kBandRows);
    RasterPixel px;
    for (const Triangle& t : triangles) {
      if (t.max_y <= y0 || t.min_y >= y1) continue;
      for (s32 y = std::max(y0, t.min_y); y < std::min(y1, t.max_y); ++y) {
        s32 xb, xe;
        covered_span(t, y, xb, xe);
        for (s32 x = xb; x < xe; ++x) {
          const size_t index =
              static_cast<size_t>(y) * static_cast<size_t>(efb.width) + static_cast<size_t>(x);
          efb.covered[index] = 1;
          raster_pixel(t, x, y, round_colors, px);
          shade_pixel(program, px, x, y, index, efb, counts);
        }
      }
    }
  });
  PixelCounts total;
  for (const PixelCounts& c : per_worker) total.add(c);
  return total;
}

}  // namespace lt::gx
