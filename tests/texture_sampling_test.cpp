// The bilinear sampler of thickness maps and lobe ramps (model/texture_sampling.h) against values
// computed by hand: texel centres, between them, clamp at the edges and beyond, the v
// orientation, and the ramp's lookup.
#include "model/texture_sampling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lt::model {
namespace {

// A 2x2 grey texture (r = g = b) from the rows bottom-up: {bottom-left, bottom-right},
// {top-left, top-right}.
Texture grey_2x2(float bl, float br, float tl, float tr) {
  Texture t;
  t.width = t.height = 2;
  for (float v : {bl, br, tl, tr}) t.texels.insert(t.texels.end(), {v, v, v});
  return t;
}

TEST(TextureSampling, TexelCentresReturnTheirTexels) {
  const Texture t = grey_2x2(0.1f, 0.2f, 0.3f, 0.4f);
  // Texel (i, j) is centred at ((i + 0.5) / 2, (j + 0.5) / 2): 0.25 and 0.75.
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.25, 0.25}).x, 0.1f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.75, 0.25}).x, 0.2f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.25, 0.75}).x, 0.3f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.75, 0.75}).x, 0.4f);
}

TEST(TextureSampling, BetweenCentresIsBilinear) {
  const Texture t = grey_2x2(0.0f, 1.0f, 0.5f, 0.25f);
  // The middle: the average of the four.
  EXPECT_NEAR(sample_bilinear(t, {0.5, 0.5}).x, (0.0 + 1.0 + 0.5 + 0.25) / 4, 1e-15);
  // u = 0.375: x = 0.375 * 2 - 0.5 = 0.25 along the bottom row (v at its centre): 0.25 * 1.
  EXPECT_NEAR(sample_bilinear(t, {0.375, 0.25}).x, 0.25, 1e-15);
  // (u, v) = (0.625, 0.5): fx = 0.75, fy = 0.5:
  //   bottom 0.25 * 0 + 0.75 * 1 = 0.75, top 0.25 * 0.5 + 0.75 * 0.25 = 0.3125, mean 0.53125.
  EXPECT_NEAR(sample_bilinear(t, {0.625, 0.5}).x, 0.53125, 1e-15);
}

TEST(TextureSampling, ClampsToTheEdgeTexelsAtAndBeyondTheBorder) {
  const Texture t = grey_2x2(0.1f, 0.2f, 0.3f, 0.4f);
  // At u = 0 and beyond: the left column only (CLAMP_TO_EDGE), still blended in v.
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.0, 0.25}).x, 0.1f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {-3.0, 0.25}).x, 0.1f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {1.0, 0.25}).x, 0.2f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {7.5, 0.75}).x, 0.4f);
  EXPECT_NEAR(sample_bilinear(t, {-1.0, 0.5}).x, (double{0.1f} + double{0.3f}) / 2, 1e-15);
  // The corners beyond both edges.
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {-1.0, -1.0}).x, 0.1f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {2.0, 2.0}).x, 0.4f);
  // A NaN coordinate is texel (0, 0), never NaN.
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {std::nan(""), std::nan("")}).x, 0.1f);
}

TEST(TextureSampling, VZeroIsTheBottomRow) {
  // Row 0 of the storage is v = 0: sampling near v = 0 gives the first row, near 1 the last.
  const Texture t = grey_2x2(0.0f, 0.0f, 1.0f, 1.0f);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.5, 0.0}).x, 0.0);
  EXPECT_DOUBLE_EQ(sample_bilinear(t, {0.5, 1.0}).x, 1.0);
  // v = 0.6: y = 0.6 * 2 - 0.5 = 0.7 of the way up.
  EXPECT_NEAR(sample_bilinear(t, {0.5, 0.6}).x, 0.7, 1e-15);
}

TEST(TextureSampling, ChannelsAreSampledIndependently) {
  Texture t;
  t.width = 2;
  t.height = 1;
  t.texels = {1, 0, 0.5f, 0, 1, 0.25f};
  const glm::dvec3 mid = sample_bilinear(t, {0.5, 0.5});
  EXPECT_DOUBLE_EQ(mid.x, 0.5);
  EXPECT_DOUBLE_EQ(mid.y, 0.5);
  EXPECT_DOUBLE_EQ(mid.z, 0.375);
}

TEST(TextureSampling, RampIsLinearBetweenTexelCentresAndClamped) {
  // 4 texels: centres at t = 0.125, 0.375, 0.625, 0.875.
  Texture ramp;
  ramp.width = 4;
  ramp.height = 1;
  for (float v : {0.0f, 0.25f, 0.5f, 1.0f}) ramp.texels.insert(ramp.texels.end(), {v, v, v});
  EXPECT_DOUBLE_EQ(sample_ramp(ramp, 0.0).x, 0.0);       // before the first centre: clamped
  EXPECT_DOUBLE_EQ(sample_ramp(ramp, 0.125).x, 0.0);     // the first centre
  EXPECT_DOUBLE_EQ(sample_ramp(ramp, 0.25).x, 0.125);    // halfway between texels 0 and 1
  EXPECT_DOUBLE_EQ(sample_ramp(ramp, 0.625).x, 0.5);     // the third centre
  EXPECT_DOUBLE_EQ(sample_ramp(ramp, 0.8125).x, 0.875);  // x = 2.75: 0.25 * 0.5 + 0.75 * 1
  EXPECT_DOUBLE_EQ(sample_ramp(ramp, 1.0).x, 1.0);       // after the last centre: clamped
  // Taps: the weights the GPU paths reproduce.
  const BilinearTaps k = bilinear_taps(4, 1, {0.25, 0.5});
  EXPECT_EQ(k.x0, 0);
  EXPECT_EQ(k.x1, 1);
  EXPECT_DOUBLE_EQ(k.fx, 0.5);
  EXPECT_EQ(k.y0, 0);
  EXPECT_EQ(k.y1, 0);
}

}  // namespace
}  // namespace lt::model
