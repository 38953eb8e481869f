// The rasteriser's values in vector lanes (src/gx/raster_run.h) against the scalar
// functions they replace in the pixel stage (rasteriser.h raster_pixel, which
// tests/dolphin_raster_test.cpp holds to Dolphin): over seeded random planes -- ordinary values,
// and the cases the conversions must keep (NaN, infinities, values past 2^31, past 2^23 texture
// units, past a colour's 16 bits, negative, q = 0, w = 0) -- and over triangles set up from
// random vertices, every lane must give the scalar's value bit for bit, on every vector target
// the machine runs, under both colour rules.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "gx/raster_run.h"

namespace lt::gx {
namespace {

// Raw mt19937 output (fully specified by the standard), not a distribution (implementation
// defined), so the cases are the same with every standard library.
struct RunRng {
  std::mt19937 engine;
  int below(int n) { return static_cast<int>(engine() % static_cast<unsigned>(n)); }
  float unit() { return static_cast<float>(engine() >> 8) / 16777216.0f; }  // [0, 1)
  float in(float lo, float hi) { return lo + (hi - lo) * unit(); }
  // A plane coefficient: mostly of the size a draw has, sometimes a hard value.
  float coefficient(float scale) {
    switch (below(12)) {
      case 0:
        return std::numeric_limits<float>::quiet_NaN();
      case 1:
        return below(2) ? std::numeric_limits<float>::infinity()
                        : -std::numeric_limits<float>::infinity();
      case 2:
        return in(-3e9f, 3e9f);  // past the 32-bit conversion
      case 3:
        return 0.0f;
      case 4: {  // any float at all
        const std::uint32_t bits = engine();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
      }
      default:
        return in(-scale, scale);
    }
  }
  Slope slope(float scale) {
    return {coefficient(scale), coefficient(scale / 64), coefficient(scale / 64)};
  }
};

std::string where(std::int64_t target, int tri, const RunPixels& pixels, int lane) {
  return std::string(hwy::TargetName(target)) + " triangle " + std::to_string(tri) + " pixel (" +
         std::to_string(pixels.x[lane]) + ", " + std::to_string(pixels.y[lane]) + ")";
}

// Every lane of the run against raster_pixel at its pixel, under both colour rules.
void expect_run_is_scalar(const Triangle& t, const RunPixels& pixels, std::int64_t target,
                          int tri) {
  for (bool round_colors : {false, true}) {
    RunValues run;
    run_depths(t, pixels, run);
    run_attributes(t, pixels, round_colors, run);
    for (int lane = 0; lane < kPixelLanes; ++lane) {
      RasterPixel want;
      raster_pixel(t, pixels.x[lane], pixels.y[lane], round_colors, want);
      ASSERT_EQ(run.z[lane], want.z) << where(target, tri, pixels, lane);
      for (int c = 0; c < t.channels; ++c)
        for (int i = 0; i < 4; ++i)
          ASSERT_EQ(run.color[c][i][lane], want.color[static_cast<size_t>(c)][i])
              << where(target, tri, pixels, lane) << " channel " << c << " component " << i
              << (round_colors ? " (rounded)" : "");
      for (int g = 0; g < t.texgens; ++g)
        for (int k = 0; k < 2; ++k)
          ASSERT_EQ(run.uv[g][k][lane], want.uv[static_cast<size_t>(g)][static_cast<size_t>(k)])
              << where(target, tri, pixels, lane) << " texcoord " << g << "." << k;
    }
  }
}

void expect_run_is_scalar_on_every_target(const Triangle& t, RunPixels pixels,
                                          const std::vector<std::int64_t>& targets, int tri) {
  pixels.pad();
  for (std::int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    expect_run_is_scalar(t, pixels, target, tri);
  }
}

TEST(GxRasterRun, LanesAreTheScalarOnRandomPlanes) {
  RunRng rng{std::mt19937(20261206)};
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  // Every target the machine runs (the emulated one always is).
  ASSERT_GE(targets.size(), 2u);
  for (int tri = 0; tri < 400; ++tri) {
    Triangle t;
    t.origin = {rng.below(640), rng.below(528), rng.in(-0.6f, 1.5f), rng.in(-0.6f, 1.5f)};
    t.channels = rng.below(kMaxChannels + 1);
    t.texgens = rng.below(kMaxTexGens + 1);
    t.z = rng.slope(2e7f);
    t.w = rng.slope(2.0f);
    for (auto& channel : t.color)
      for (Slope& s : channel) s = rng.slope(300.0f);
    for (auto& gen : t.tex)
      for (Slope& s : gen) s = rng.slope(600.0f);
    if (rng.below(8) == 0) t.tex[0][2] = {0, 0, 0};  // q = 0: the projection is 1/w
    if (rng.below(8) == 0) t.w = {0, 0, 0};          // 1/w infinite
    // Pixels anywhere in the EFB, some repeated: a run holds any pixels.
    RunPixels pixels;
    const int count = 1 + rng.below(kPixelLanes);
    while (pixels.count < count) pixels.add(rng.below(640), rng.below(528));
    expect_run_is_scalar_on_every_target(t, pixels, targets, tri);
  }
  hwy::SetSupportedTargetsForTest(0);
}

TEST(GxRasterRun, LanesAreTheScalarOverSetUpTriangles) {
  RunRng rng{std::mt19937(7)};
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  Scissor scissor;
  scissor.right = 640;
  scissor.bottom = 528;
  int drawn = 0;
  for (int tri = 0; tri < 300; ++tri) {
    RasterVertex v[3];
    for (RasterVertex& vertex : v) {
      vertex.screen = {342.0f + rng.in(-20, 660), 342.0f + rng.in(-20, 548), rng.in(0, 16777215)};
      vertex.clip = {0, 0, 0, rng.in(0.05f, 50.0f)};
      for (auto& colour : vertex.color)
        for (int i = 0; i < 4; ++i) colour[i] = static_cast<u8>(rng.below(256));
      for (auto& tex : vertex.tex) tex = {rng.in(-8, 8), rng.in(-8, 8), rng.in(0.5f, 2.0f)};
    }
    Triangle t;
    if (!setup_triangle(v[0], v[1], v[2], rng.below(3), rng.below(kMaxTexGens + 1), scissor, t) &&
        !setup_triangle(v[0], v[2], v[1], rng.below(3), rng.below(kMaxTexGens + 1), scissor, t))
      continue;
    ++drawn;
    // The pixel stage's runs: the triangle's covered pixels of its first rows (a band and
    // more), kPixelLanes a run across the rows.
    RunPixels pixels;
    for (s32 y = t.min_y; y < std::min(t.max_y, t.min_y + 8); ++y) {
      s32 xb, xe;
      covered_span(t, y, xb, xe);
      for (s32 x = xb; x < xe; ++x) {
        pixels.add(x, y);
        if (pixels.full()) {
          expect_run_is_scalar_on_every_target(t, pixels, targets, tri);
          pixels.count = 0;
        }
      }
    }
    if (pixels.count > 0) expect_run_is_scalar_on_every_target(t, pixels, targets, tri);
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GT(drawn, 200);
}

}  // namespace
}  // namespace lt::gx
