#include "gx/pixel_stage.h"

#include <algorithm>
#include <iterator>
#include <memory>
#include <vector>

#include "core/parallel_rows.h"
#include "gx/raster_run.h"
#include "gx/tev_plan.h"

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
    // The texture's LOD can change its texels (mipmaps, or min and mag filters that differ):
    // the LOD of each pixel's 2x2 block is computed. Otherwise level 0 with the mag filter, as
    // every LOD would give, and nothing more is computed (TextureObject::needs_lod).
    bool lod = false;
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
      f.lod = f.texture != nullptr && f.texture->needs_lod();
    }
  }
};

// What a band reuses from one run of pixels to the next: the rasterised values and the TEV's
// inputs and output, each a lane a pixel. Made zero once per band and never written beyond the
// draw's channel and texgen counts (every triangle of a draw has the state's), so a stage that
// reads a channel the draw does not light reads zero.
struct Lanes {
  RunPixels pixels;
  RunValues raster;
  TevPlan::Values tev;
  TevPlan::Output out;
};

// The pixels of lanes.pixels (covered pixels of triangle t), as [DSW Draw] then [DSW Tev::Draw]
// take each: the depths of all of them first (the pixels are distinct, so no pixel's test sees
// another's write), then the colours, texels and TEV of those that passed, in lanes, then each
// one's alpha test and blend. Empties lanes.pixels.
void shade_run(const PixelProgram& p, const DrawPlan& plan, const Triangle& t, bool round_colors,
               Efb& efb, Lanes& lanes, PixelCounts& counts) {
  const GxState& st = *p.state;
  RunPixels& pixels = lanes.pixels;
  const int n = pixels.count;
  if (n == 0) return;
  pixels.pad();
  pixels.count = 0;
  const auto efb_index = [&](int i) {
    return static_cast<size_t>(pixels.y[i]) * static_cast<size_t>(efb.width) +
           static_cast<size_t>(pixels.x[i]);
  };
  counts.covered += static_cast<size_t>(n);
  run_depths(t, pixels, lanes.raster);
  int passed[kPixelLanes];
  int num_passed = 0;
  for (int i = 0; i < n; ++i) {
    const size_t index = efb_index(i);
    efb.covered[index] = 1;
    // GX_Init's GX_SetZCompLoc(GX_TRUE) puts the depth test before texturing [DSW Draw, "early
    // z"; BPMemory.h GetEmulatedZ], so a pixel the alpha test then discards has written its
    // depth. With the test off nothing is compared or written.
    if (st.z.enable) {
      u32& depth = efb.depth[index];
      const u32 z = lanes.raster.z[i];
      if (!z_compare(st.z.func, z, depth)) {
        ++counts.z_failed;
        continue;
      }
      if (st.z.update) depth = z & 0xffffff;  // [DSW SetPixelDepth]: 24 bits kept
    }
    passed[num_passed++] = i;
  }
  // A pixel that failed the depth test needs no colour, texel or TEV.
  if (num_passed == 0) return;
  run_attributes(t, pixels, round_colors, lanes.raster);
  // The channels beyond the draw's count stay the zeros the band's Lanes began with.
  for (int c = 0; c < t.channels; ++c)
    for (int i = 0; i < 4; ++i)
      std::copy(std::begin(lanes.raster.color[c][i]), std::end(lanes.raster.color[c][i]),
                lanes.tev.channel(c, i));
  for (int k = 0; k < plan.num_fetches; ++k) {
    const DrawPlan::Fetch& f = plan.fetches[static_cast<size_t>(k)];
    const auto& uv = lanes.raster.uv[f.texcoord];
    Color8 texels[kPixelLanes] = {};
    if (f.texture) {
      s32 u[kPixelLanes], v[kPixelLanes];
      for (int j = 0; j < num_passed; ++j) {
        u[j] = uv[0][passed[j]];
        v[j] = uv[1][passed[j]];
      }
      if (f.lod) {
        // [DSW Rasterizer.cpp BuildBlock, CalculateLOD]: one LOD per 2x2 block, from the
        // texture coordinates of its pixels, the texture's LOD fields deciding the rest.
        LodChoice lods[kPixelLanes];
        const TextureObject& tex = *f.texture;
        for (int j = 0; j < num_passed; ++j) {
          const int i = passed[j];
          lods[j] =
              quad_lod(*tex.lod, tex.linear,
                       quad_texcoords(t, static_cast<int>(f.texcoord), pixels.x[i], pixels.y[i]));
        }
        sample_texture_lod_at(tex, u, v, lods, num_passed, texels);
      } else {
        sample_texture_at(*f.texture, u, v, num_passed, texels);
      }
    }
    for (int j = 0; j < num_passed; ++j) lanes.tev.set_texel(f.stage, passed[j], texels[j]);
  }
  counts.stage_pixels += static_cast<size_t>(num_passed) * static_cast<size_t>(st.tev.num_stages);
  plan.tev.run(lanes.tev, lanes.out);
  for (int j = 0; j < num_passed; ++j) {
    const int i = passed[j];
    const Color8 src = tev_to_efb(lanes.out.at(i));
    if (!alpha_test(st.alpha_compare, src.a)) {
      ++counts.alpha_failed;
      continue;
    }
    // [DSW BlendTev]: the EFB's colour as it reads back, blended, dithered and stored in the
    // frame's pixel format (GX_Init's colour and alpha updates on, destination alpha off).
    Color8& dst = efb.color[efb_index(i)];
    dst = efb_written(efb.pixel_format, st.dither, pixels.x[i], pixels.y[i],
                      blend(st.blend, src, dst));
    ++counts.written;
  }
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
    // Per band, not per worker: 10 KB a band is nothing beside its pixels, and a fresh one holds
    // the zeros the draw's unused channels must read.
    auto lanes = std::make_unique<Lanes>();
    plan.tev.start(lanes->tev);
    const size_t band_index = static_cast<size_t>(band);
    for (u32 k = lists.first[band_index]; k < lists.first[band_index + 1]; ++k) {
      const Triangle& t = triangles[lists.items[k]];
      // The triangle's covered pixels of the band, kPixelLanes a run across its rows (a small
      // triangle covers a few a row); each triangle's runs end with it, so a pixel sees the
      // triangles in draw order.
      for (s32 y = std::max(y0, t.min_y); y < std::min(y1, t.max_y); ++y) {
        s32 xb, xe;
        covered_span(t, y, xb, xe);
        for (s32 x = xb; x < xe; ++x) {
          lanes->pixels.add(x, y);
          if (lanes->pixels.full()) shade_run(program, plan, t, round_colors, efb, *lanes, counts);
        }
      }
      shade_run(program, plan, t, round_colors, efb, *lanes, counts);
    }
  });
  PixelCounts total;
  for (const PixelCounts& c : per_worker) total.add(c);
  return total;
}

}  // namespace lt::gx
