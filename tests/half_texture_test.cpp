// The half path's bilinear sampling (fp16::sample_half): half texels, half weights, every product
// and sum of the blend rounded to half, against values computed by hand.
#include <gtest/gtest.h>

#include "model/texture_sampling.h"
#include "paths/half/half_shading.h"

namespace lt::fp16 {
namespace {

TextureH texture_row(std::initializer_list<float> values) {
  TextureH t;
  t.width = static_cast<int>(values.size());
  t.height = 1;
  for (float v : values) t.texels.push_back({half(v), half(v), half(v)});
  return t;
}

TEST(HalfTexture, WeightsAreRoundedToHalf) {
  // Texels 0 and 1: the result is the weight of texel 1 itself. u = (0.5 + 1/3) / 2 puts the
  // position a third of the way: fx = 1/3 in double, 0.333251953125 in half.
  const TextureH t = texture_row({0.0f, 1.0f});
  const Vec3h s = sample_half(t, {(0.5 + 1.0 / 3) / 2, 0.5});
  EXPECT_EQ(float(s.x), 0.333251953125f);
  EXPECT_NE(float(s.x), static_cast<float>(1.0 / 3));
  // The reference sampler keeps the double weight.
  model::Texture d;
  d.width = 2;
  d.height = 1;
  d.texels = {0, 0, 0, 1, 1, 1};
  EXPECT_DOUBLE_EQ(model::sample_bilinear(d, {(0.5 + 1.0 / 3) / 2, 0.5}).x, 1.0 / 3);
}

TEST(HalfTexture, TexelsAreHalvesAndTheBlendRoundsEachStep) {
  // 0.1 is 0.0999755859375 in half; at a texel centre the blend is 1 * texel + 0 * neighbour.
  const TextureH t = texture_row({0.1f, 0.7f});
  EXPECT_EQ(float(sample_half(t, {0.25, 0.5}).x), 0.0999755859375f);
  // Halfway: 0.5 * 0.0999755859375 = 0.04998779296875 (exact), 0.5 * half(0.7) = 0.5 *
  // 0.7001953125 = 0.35009765625 (exact); their sum 0.40008544921875 rounds to half's
  // 0.400146484375 (spacing 2^-12 in [0.25, 0.5)).
  EXPECT_EQ(float(sample_half(t, {0.5, 0.5}).x), 0.400146484375f);
}

TEST(HalfTexture, ClampsLikeTheReference) {
  const TextureH t = texture_row({0.25f, 0.75f});
  EXPECT_EQ(float(sample_half(t, {-2.0, 0.5}).x), 0.25f);
  EXPECT_EQ(float(sample_half(t, {3.0, 7.0}).x), 0.75f);
}

}  // namespace
}  // namespace lt::fp16
