// The gx path's CPU pixel stage (issue 39), whole and stage by stage. Whole: TEV stage-pixels per
// second through lt::gx::draw_triangles -- rasterised attributes, early z, texture fetch, TEV,
// alpha test, blend -- for a grid of triangles covering an EFB, with the t=vertex variant's kind
// of program (a fetch from an I8 LUT modulated by the lit channels, three stages); the
// "stage_pixels" counter is the rate, and `ltrender bench` prints the same work as "TEV ...
// stage-pixels". By stage: one run of pixels through each of its steps (BM_GxRasterRun,
// BM_GxTevPlanRun, BM_GxSampleTextureRun), in pixels per second.
//
//   build/bench_gx_pixel_stage --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <vector>

#include "core/parallel_rows.h"
#include "gx/gx_state.h"
#include "gx/pixel_stage.h"
#include "gx/raster_run.h"
#include "gx/tev_plan.h"
#include "gx/texture_unit.h"

namespace {

using namespace lt::gx;  // NOLINT: a benchmark's own translation unit, not part of a unity batch

constexpr int kEfbWidth = 640, kEfbHeight = 528;  // the Wii's EFB

// A stage reading rasterised channel `channel` whose combiners take these operands (a, b, c, d),
// the other fields GX_Init's.
TevStage stage(u8 channel, std::array<TevColorArg, 4> color, std::array<TevAlphaArg, 4> alpha) {
  TevStage s;
  s.channel = channel;
  u8* cs[4] = {&s.color.a, &s.color.b, &s.color.c, &s.color.d};
  u8* as[4] = {&s.alpha.a, &s.alpha.b, &s.alpha.c, &s.alpha.d};
  for (size_t i = 0; i < 4; ++i) {
    *cs[i] = static_cast<u8>(color[i]);
    *as[i] = static_cast<u8>(alpha[i]);
  }
  return s;
}

// A 256x4 I8 ramp, as the path's power LUT is laid out.
TextureObject lut() {
  TextureObject t;
  t.width = 256;
  t.height = 4;
  t.format = kTexFormatI8;
  std::vector<u8> texels(256 * 4);
  for (size_t i = 0; i < texels.size(); ++i)
    texels[i] = static_cast<u8>((i % 256) * (i % 256) / 255);
  t.data = to_tiles(t.format, t.width, t.height, texels);
  return t;
}

// Stage 0 TEXC x RASC (COLOR0A0), stage 1 adds RASC (COLOR1A1) x KONST, stage 2 scales PREV by
// 2 with a half bias; alpha passes RASA through.
GxState program() {
  using C = TevColorArg;
  using A = TevAlphaArg;
  GxState st;
  st.lighting.num_channels = 2;
  st.texgen.num_texgens = 1;
  st.tev.num_stages = 3;
  st.tev.stages[0] =
      stage(4, {C::Zero, C::TexC, C::RasC, C::Zero}, {A::Zero, A::Zero, A::Zero, A::RasA});
  st.tev.stages[0].texmap = 0;
  st.tev.stages[0].texcoord = 0;
  st.tev.stages[1] =
      stage(5, {C::Zero, C::RasC, C::Konst, C::CPrev}, {A::Zero, A::Zero, A::Zero, A::APrev});
  st.tev.stages[1].konst_color_sel = 12;  // K0
  st.tev.stages[2] =
      stage(6, {C::Zero, C::Zero, C::Zero, C::CPrev}, {A::Zero, A::Zero, A::Zero, A::APrev});
  st.tev.stages[2].color.bias = 2;   // -half
  st.tev.stages[2].color.scale = 1;  // x2
  st.tev.konst[0] = {200, 150, 100, 255};
  return st;
}

RasterVertex vertex(float x, float y) {
  RasterVertex v;
  v.clip = {0, 0, 0, 1};
  v.screen = {342.0f + x, 342.0f + y, 1000.0f + 10 * x + y};
  v.color[0] = {static_cast<u8>(x * 255 / kEfbWidth), static_cast<u8>(y * 255 / kEfbHeight), 80,
                255};
  v.color[1] = {40, static_cast<u8>(x * 200 / kEfbWidth), 120, 200};
  v.tex[0] = {x * 256 / kEfbWidth, y * 4 / kEfbHeight, 1};
  return v;
}

// Cells of `cell` pixels, two triangles each, wound whichever way the rasteriser takes.
std::vector<Triangle> grid(int cell) {
  Scissor scissor;
  scissor.right = kEfbWidth;
  scissor.bottom = kEfbHeight;
  std::vector<Triangle> out;
  const auto add = [&](const RasterVertex& a, const RasterVertex& b, const RasterVertex& c) {
    Triangle t;
    for (int order = 0; order < 2; ++order) {
      const bool ok = order == 0 ? setup_triangle(a, b, c, 2, 1, scissor, t)
                                 : setup_triangle(a, c, b, 2, 1, scissor, t);
      s32 xb = 0, xe = 0;
      if (ok) covered_span(t, (t.min_y + t.max_y) / 2, xb, xe);
      if (ok && xe > xb) {
        out.push_back(t);
        return;
      }
    }
  };
  for (int y = 0; y < kEfbHeight; y += cell) {
    for (int x = 0; x < kEfbWidth; x += cell) {
      const float x0 = static_cast<float>(x), y0 = static_cast<float>(y);
      const float x1 = x0 + static_cast<float>(cell), y1 = y0 + static_cast<float>(cell);
      add(vertex(x0, y0), vertex(x1, y0), vertex(x1, y1));
      add(vertex(x0, y0), vertex(x1, y1), vertex(x0, y1));
    }
  }
  return out;
}

// Args: cell size in pixels, threads (0: all cores).
void BM_GxPixelStage(benchmark::State& state) {
  const std::vector<Triangle> triangles = grid(static_cast<int>(state.range(0)));
  const GxState st = program();
  const TextureObject texture = lut();
  PixelProgram pp;
  pp.state = &st;
  pp.textures[0] = &texture;
  const unsigned threads = static_cast<unsigned>(state.range(1));
  const unsigned saved = lt::worker_threads_setting().load();
  lt::worker_threads_setting() = threads;
  Efb efb;
  size_t stage_pixels = 0;
  for (auto _ : state) {
    efb.clear(kEfbWidth, kEfbHeight, {0, 0, 0, 0}, 0xffffff);
    const PixelCounts c = draw_triangles(triangles, pp, false, efb);
    stage_pixels += c.stage_pixels;
    benchmark::DoNotOptimize(efb.color.data());
  }
  lt::worker_threads_setting() = saved;
  if (stage_pixels == 0) state.SkipWithError("the grid covered no pixel");
  state.counters["stage_pixels"] =
      benchmark::Counter(static_cast<double>(stage_pixels), benchmark::Counter::kIsRate);
}

// Wall time: the pixel stage shares its rows out over the worker threads.
BENCHMARK(BM_GxPixelStage)
    ->ArgNames({"cell", "threads"})
    ->Args({32, 1})  // large triangles, one thread: the per-pixel cost
    ->Args({4, 1})   // small triangles: the per-triangle and per-span cost shows
    ->Args({32, 0})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// The stages of a run one at a time, kPixelLanes pixels of one triangle: the rasterised values
// (depth, two channels, one texture coordinate) in lanes, the three-stage TEV plan in lanes, and
// the LUT's bilinear fetch for the run; "pixels" is the rate.
void pixels_per_second(benchmark::State& state) {
  state.counters["pixels"] = benchmark::Counter(
      static_cast<double>(state.iterations() * kPixelLanes), benchmark::Counter::kIsRate);
}

const Triangle& one_triangle() {
  static const Triangle t = grid(32).front();
  return t;
}

RunPixels run_of(const Triangle& t) {
  RunPixels pixels;
  for (s32 y = t.min_y; y < t.max_y && !pixels.full(); ++y) {
    s32 xb, xe;
    covered_span(t, y, xb, xe);
    for (s32 x = xb; x < xe && !pixels.full(); ++x) pixels.add(x, y);
  }
  pixels.pad();
  return pixels;
}

void BM_GxRasterRun(benchmark::State& state) {
  const Triangle& t = one_triangle();
  const RunPixels pixels = run_of(t);
  RunValues values;
  for (auto _ : state) {
    run_depths(t, pixels, values);
    run_attributes(t, pixels, false, values);
    benchmark::DoNotOptimize(values.uv[0][0][0]);
  }
  pixels_per_second(state);
}
BENCHMARK(BM_GxRasterRun);

void BM_GxTevPlanRun(benchmark::State& state) {
  const GxState st = program();
  const TevPlan plan(st.tev);
  TevPlan::Values values;
  plan.start(values);
  for (int c = 0; c < kMaxChannels; ++c)
    for (int i = 0; i < 4; ++i)
      for (int lane = 0; lane < kPixelLanes; ++lane) values.channel(c, i)[lane] = 40 * c + lane;
  TevPlan::Output out;
  for (auto _ : state) {
    plan.run(values, out);
    benchmark::DoNotOptimize(out.c[0][0]);
  }
  pixels_per_second(state);
  state.counters["stage_pixels"] =
      benchmark::Counter(static_cast<double>(state.iterations() * kPixelLanes * plan.num_stages()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GxTevPlanRun);

void BM_GxSampleTextureRun(benchmark::State& state) {
  const TextureObject texture = lut();
  s32 u[kPixelLanes], v[kPixelLanes];
  for (int i = 0; i < kPixelLanes; ++i) {
    u[i] = 100 * i + 37;
    v[i] = 64 + 3 * i;
  }
  Color8 texels[kPixelLanes];
  for (auto _ : state) {
    sample_texture_at(texture, u, v, kPixelLanes, texels);
    benchmark::DoNotOptimize(texels[0]);
  }
  pixels_per_second(state);
}
BENCHMARK(BM_GxSampleTextureRun);

}  // namespace

BENCHMARK_MAIN();
