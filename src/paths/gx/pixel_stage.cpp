#include "paths/gx/pixel_stage.h"

#include <algorithm>
#include <vector>

#include "core/parallel_rows.h"
#include "paths/gx/tev_plan.h"

namespace lt::gx {

namespace {

// Rows a worker takes at a time: small enough that two workers share a small object's rows,
// large enough that a triangle's bounds are tested once for several rows.
constexpr int kBandRows = 4;

// What one draw's pixels do that does not depend on the pixel, decoded once: the TEV plan and
// the texture fetches (which stages fetch, from which texture, at which texture coordinate), so
// the per-pixel loop looks nothing up in the state.
struct DrawPlan {
  // One stage's fetch [DSW Tev::Draw, TextureSampler::Sample]; texture null: a black texel.
  struct Fetch {
    int stage = 0;
    const TextureObject* texture = nullptr;
    size_t texcoord = 0;
  };
  TevPlan tev;
  std::array<Fetch, kMaxTevStages> fetches{};
  int num_fetches = 0;

  explicit DrawPlan(const PixelProgram& p) : tev(p.state->tev) {
    const GxState& st = *p.state;
    const int texgens = st.texgen.num_texgens;
    for (int s = 0; s < std::min(st.tev.num_stages, kMaxTevStages); ++s) {
      const TevStage& stage = st.tev.stages[static_cast<size_t>(s)];
      if (stage.texmap == kTexMapNull) continue;
      Fetch& f = fetches[static_cast<size_t>(num_fetches++)];
      f.stage = s;
      // Zero texgens read a black texel here (Dolphin reads whatever texture coordinate its TEV
      // last held); a texcoord beyond them reads texcoord 0 ("Quirk: when the tex coord is not
      // less than the number of tex gens ... tex coord 0 is used" [DSW Tev::Draw]);
      // GX_TEXCOORDNULL with a map programs texcoord 0 [OGC gx.c GX_SetTevOrder].
      const TextureObject* tex = p.textures[stage.texmap & 7];
      f.texture = texgens == 0 ? nullptr : tex;
      int tc = stage.texcoord == kTexCoordNull ? 0 : stage.texcoord;
      if (tc >= texgens) tc = 0;
      f.texcoord = static_cast<size_t>(tc);
    }
  }
};

// The TEV inputs of one pixel that passed early z: its channel colours and its stages' texels.
void load_tev_inputs(const DrawPlan& plan, const RasterPixel& px, TevPlan::Values& values) {
  for (int c = 0; c < kMaxChannels; ++c) values.set_channel(c, px.color[static_cast<size_t>(c)]);
  for (int k = 0; k < plan.num_fetches; ++k) {
    const DrawPlan::Fetch& f = plan.fetches[static_cast<size_t>(k)];
    const auto& uv = px.uv[f.texcoord];
    values.set_texel(f.stage, f.texture ? sample_texture(*f.texture, uv[0], uv[1]) : Color8{});
  }
}

// One covered pixel, as [DSW Draw] then [DSW Tev::Draw] take it.
void shade_pixel(const PixelProgram& p, const DrawPlan& plan, const Triangle& t, s32 x, s32 y,
                 bool round_colors, size_t index, Efb& efb, RasterPixel& px,
                 TevPlan::Values& values, PixelCounts& counts) {
  const GxState& st = *p.state;
  ++counts.covered;
  px.z = raster_pixel_depth(t, x, y);
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
  // A pixel that failed the depth test needs no colour or texture coordinate. Every triangle of
  // a draw has the state's channel and texgen counts, so the entries raster_pixel leaves alone
  // (beyond those counts) stay what they were whichever pixels skip this.
  raster_pixel_attributes(t, x, y, round_colors, px);
  load_tev_inputs(plan, px, values);
  counts.stage_pixels += static_cast<size_t>(st.tev.num_stages);
  const Color8 src = tev_to_efb(plan.tev.run(values));
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

// The triangles that reach each band of rows, in draw order, as one list per band (offsets into
// one array): a band then visits only those, where it otherwise tested every triangle's rows
// against its own -- for a draw of many small triangles most of the band's time. A band gets a
// triangle when their rows overlap; one whose rows then hold none of the triangle's (the last,
// short band) draws nothing of it, as before.
struct BandLists {
  std::vector<u32> first;  // band b's triangles are items[first[b] .. first[b + 1])
  std::vector<u32> items;

  BandLists(const std::vector<Triangle>& triangles, int bands)
      : first(static_cast<size_t>(bands) + 1, 0) {
    const auto range = [&](const Triangle& t, int& b0, int& b1) {
      b0 = std::max(t.min_y, 0) / kBandRows;
      b1 = t.max_y <= t.min_y ? b0 : std::min(bands, (t.max_y + kBandRows - 1) / kBandRows);
    };
    int b0, b1;
    for (const Triangle& t : triangles) {
      range(t, b0, b1);
      for (int b = b0; b < b1; ++b) ++first[static_cast<size_t>(b) + 1];
    }
    for (size_t b = 0; b < static_cast<size_t>(bands); ++b) first[b + 1] += first[b];
    items.resize(first.back());
    std::vector<u32> next(first.begin(), first.end() - 1);
    for (size_t i = 0; i < triangles.size(); ++i) {
      range(triangles[i], b0, b1);
      for (int b = b0; b < b1; ++b) items[next[static_cast<size_t>(b)]++] = static_cast<u32>(i);
    }
  }
};

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
  const DrawPlan plan(program);
  const BandLists lists(triangles, bands);
  for_each_row_in_parallel(bands, [&](int band, unsigned worker) {
    PixelCounts& counts = per_worker[worker];
    const s32 y0 = band * kBandRows, y1 = std::min(efb.height, y0 + kBandRows);
    RasterPixel px;
    TevPlan::Values values;
    plan.tev.start(values);
    const size_t band_index = static_cast<size_t>(band);
    for (u32 k = lists.first[band_index]; k < lists.first[band_index + 1]; ++k) {
      const Triangle& t = triangles[lists.items[k]];
      for (s32 y = std::max(y0, t.min_y); y < std::min(y1, t.max_y); ++y) {
        s32 xb, xe;
        covered_span(t, y, xb, xe);
        for (s32 x = xb; x < xe; ++x) {
          const size_t index =
              static_cast<size_t>(y) * static_cast<size_t>(efb.width) + static_cast<size_t>(x);
          efb.covered[index] = 1;
          shade_pixel(program, plan, t, x, y, round_colors, index, efb, px, values, counts);
        }
      }
    }
  });
  PixelCounts total;
  for (const PixelCounts& c : per_worker) total.add(c);
  return total;
}

}  // namespace lt::gx
