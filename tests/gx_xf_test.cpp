// The XF units of the gx path: per-vertex lighting (src/gx/xf_lighting.h, gx-hardware.md
// §2.3-2.4) and texgens (src/gx/xf_texgen.h, §3.1). Every expectation is worked out by
// hand in the test from the documented formulas, never by calling the unit's helpers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gx/xf_lighting.h"
#include "gx/xf_texgen.h"

namespace lt::gx {
namespace {

constexpr u8 kReg = 0, kVtx = 1;                        // GX_SRC_REG / GX_SRC_VTX
constexpr u8 kDfNone = 0, kDfSigned = 1, kDfClamp = 2;  // GX_DF_*
constexpr u8 kAfSpec = 0, kAfSpot = 1, kAfNone = 2;     // GX_AF_*
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

Color8 gray_color(u8 v) {
  return Color8{v, v, v, v};
}

// One channel (COLOR0 and ALPHA0 with the same control), register ambient and material, the
// given lights enabled. Position at the origin, normal +z, in the tests below.
XfLightingState one_channel(u8 ambient, u8 material, u8 mask, u8 diffuse, u8 attn) {
  XfLightingState s;
  s.num_channels = 1;
  ChannelControl c;
  c.lighting = true;
  c.ambient_source = kReg;
  c.material_source = kReg;
  c.light_mask = mask;
  c.diffuse_fn = diffuse;
  c.attenuation_fn = attn;
  s.control[0] = c;
  s.control[2] = c;
  s.ambient[0] = gray_color(ambient);
  s.material[0] = gray_color(material);
  return s;
}

XfLight light_at(glm::vec3 position, Color8 color) {
  XfLight l;
  l.position = position;
  l.color = color;
  l.direction = glm::vec3(0, 0, -1);
  return l;
}

const glm::vec3 kOrigin(0, 0, 0), kUp(0, 0, 1);
const std::array<Color8, kMaxChannels> kNoVertexColors{};

Color8 light0(const XfLightingState& s, glm::vec3 normal = kUp,
              LightRounding rounding = LightRounding::SumThenTruncate) {
  return light_vertex(s, kOrigin, normal, kNoVertexColors, rounding)[0];
}

// ---- lighting ----

TEST(XfLighting, DisabledPassesTheMaterialUnchanged) {
  XfLightingState s;
  s.num_channels = 2;
  // Lights are configured and bright, but lighting is off: they must not matter.
  s.lights[0] = light_at({0, 0, 5}, gray_color(255));
  for (ChannelControl& c : s.control) {
    c.lighting = false;
    c.light_mask = 1;
    c.material_source = kVtx;
  }
  const std::array<Color8, kMaxChannels> vtx{Color8{10, 20, 30, 40}, Color8{50, 60, 70, 80}};
  auto out = light_vertex(s, kOrigin, kUp, vtx);
  EXPECT_EQ(out[0], (Color8{10, 20, 30, 40}));
  EXPECT_EQ(out[1], (Color8{50, 60, 70, 80}));
  // Register material: white is passed as 255, not as (255 * 256) >> 8 of something.
  s.control[1].material_source = kReg;
  s.control[3].material_source = kReg;
  s.material[1] = Color8{1, 2, 3, 255};
  out = light_vertex(s, kOrigin, kUp, vtx);
  EXPECT_EQ(out[1], (Color8{1, 2, 3, 255}));
}

TEST(XfLighting, NoLightsMatchTheHardwareFormulaForAllPairs) {
  // [HWT gxtest/lighting.cpp L86]: out = (mat * (amb + (amb >> 7))) >> 8, verified on a console.
  // Channel 0 takes both colours from registers; channel 1 takes the material from the vertex.
  XfLightingState s = one_channel(0, 0, 0, kDfNone, kAfNone);
  s.num_channels = 2;
  s.control[1] = s.control[0];
  s.control[1].material_source = kVtx;
  s.control[3] = s.control[1];
  int mismatches = 0;
  for (int mat = 0; mat < 256; ++mat) {
    for (int amb = 0; amb < 256; ++amb) {
      s.ambient[0] = s.ambient[1] = gray_color(static_cast<u8>(amb));
      s.material[0] = gray_color(static_cast<u8>(mat));
      const std::array<Color8, kMaxChannels> vtx{Color8{}, gray_color(static_cast<u8>(mat))};
      const auto out = light_vertex(s, kOrigin, kUp, vtx);
      const u8 expected = static_cast<u8>((mat * (amb + (amb >> 7))) >> 8);
      if (out[0] != gray_color(expected) || out[1] != gray_color(expected)) {
        if (++mismatches < 5) ADD_FAILURE() << "mat " << mat << " amb " << amb;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(XfLighting, WhiteMaterialLosesOneLsbBelow128) {
  // (255 * (L + (L >> 7))) >> 8 = L - 1 for 1 <= L <= 127 and L for 128..255 (§2.4 gotcha 1).
  XfLightingState s = one_channel(0, 255, 0, kDfNone, kAfNone);
  for (int L = 0; L < 256; ++L) {
    s.ambient[0] = gray_color(static_cast<u8>(L));
    const int expected = (L >= 1 && L <= 127) ? L - 1 : L;
    EXPECT_EQ(light0(s).r, expected) << L;
    EXPECT_EQ(light0(s).a, expected) << L;
  }
}

TEST(XfLighting, DistanceAttenuationWithSpotOff) {
  // GX_AF_SPOT with a = (1, 0, 0) (GX_SP_OFF) and k = (1, 0, 0.25) (the STEEP form): at
  // distance 2, A = 1 / (1 + 0.25 * 4) = 0.5.
  XfLightingState s = one_channel(0, 255, 1, kDfNone, kAfSpot);
  s.lights[0] = light_at({0, 0, 2}, Color8{200, 100, 50, 255});
  s.lights[0].k = {1, 0, 0.25f};
  // L = 100, 50, 25, 127.5 -> 127; white material: 99, 49, 24, 126.
  EXPECT_EQ(light0(s), (Color8{99, 49, 24, 126}));
  // a = (1, 0, 0): the light direction plays no part.
  s.lights[0].direction = glm::vec3(0.3f, -0.7f, 0.1f);
  EXPECT_EQ(light0(s), (Color8{99, 49, 24, 126}));
  // The same light at distance 4 along x: A = 1 / (1 + 0.25 * 16) = 0.2 -> L = 40, 20, 10, 51.
  s.lights[0].position = glm::vec3(4, 0, 0);
  EXPECT_EQ(light0(s), (Color8{39, 19, 9, 50}));
}

TEST(XfLighting, SpotAngularTermUsesLDotDirection) {
  // a = (0, 1, 0): A = x / (k0 + k1 d + k2 d^2) with x = max(0, l . dir). l = (0, 0, 1),
  // dir = (0.5, 0, 0.5) -> x = 0.5; k = (1, 0, 0.25), d = 2 -> A = 0.25. L = 200 * 0.25 = 50.
  XfLightingState s = one_channel(0, 255, 1, kDfNone, kAfSpot);
  s.lights[0] = light_at({0, 0, 2}, gray_color(200));
  s.lights[0].a = {0, 1, 0};
  s.lights[0].k = {1, 0, 0.25f};
  s.lights[0].direction = glm::vec3(0.5f, 0, 0.5f);
  EXPECT_EQ(light0(s).g, (255 * 50) >> 8);  // 49
  // dir = (0, 0, -0.5): x = max(0, l . dir) = max(0, -0.5) = 0, so A = 0 and only the (zero)
  // ambient remains.
  s.lights[0].direction = glm::vec3(0, 0, -0.5f);
  EXPECT_EQ(light0(s).g, 0);
  // a = (0.5, 0, 1): the square term sees the clamped x. With l . dir = -0.5, x = 0: A = 0.5 / 2,
  // L = 50 -> 49 (an unclamped x = -0.5 would give 0.75 / 2, L = 75 -> 74).
  s.lights[0].a = {0.5f, 0, 1};
  EXPECT_EQ(light0(s).g, 49);
  // dir = (0, 0, 0.5), x = 0.5: A = (0.5 + 0.25) / 2 = 0.375, L = 75 -> (255 * 75) >> 8 = 74.
  s.lights[0].direction = glm::vec3(0, 0, 0.5f);
  EXPECT_EQ(light0(s).g, 74);
}

TEST(XfLighting, DiffuseFunctionsWithALightBehindTheSurface) {
  // Ambient 100, light colour 60 straight behind the surface: l . N = -1.
  XfLightingState s = one_channel(100, 255, 1, kDfClamp, kAfNone);
  s.lights[0] = light_at({0, 0, -5}, gray_color(60));
  EXPECT_EQ(light0(s).r, 99);  // CLAMP: D = 0, L = 100, (255 * 100) >> 8 = 99
  s.control[0].diffuse_fn = kDfSigned;
  EXPECT_EQ(light0(s).r, 39);  // SIGNED: L = 100 - 60 = 40, (255 * 40) >> 8 = 39
  s.control[0].diffuse_fn = kDfNone;
  EXPECT_EQ(light0(s).r, 160);  // NONE: D = 1, L = 160, (255 * 161) >> 8 = 160
  // In front (l . N = 1), CLAMP and SIGNED agree: L = 160.
  s.lights[0].position = glm::vec3(0, 0, 10);
  s.control[0].diffuse_fn = kDfClamp;
  EXPECT_EQ(light0(s).r, 160);
  s.control[0].diffuse_fn = kDfSigned;
  EXPECT_EQ(light0(s).r, 160);
  // The normal is normalised first: a long normal gives the same D = 1.
  EXPECT_EQ(light0(s, glm::vec3(0, 0, 7)).r, 160);
}

TEST(XfLighting, SumIsClampedBeforeTheMaterialMultiply) {
  // 100 + 255 = 355 -> 255, then (128 * (255 + 1)) >> 8 = 128. Clamping after the multiply
  // would give (128 * 357) >> 8 = 178.
  XfLightingState s = one_channel(100, 128, 1, kDfNone, kAfNone);
  s.lights[0] = light_at({0, 0, 1}, gray_color(255));
  EXPECT_EQ(light0(s), gray_color(128));
  // A = 1 / 0.5 = 2 > 1: 200 * 2 = 400 saturates; (100 * 256) >> 8 = 100.
  s = one_channel(0, 100, 1, kDfNone, kAfSpot);
  s.lights[0] = light_at({0, 0, 1}, gray_color(200));
  s.lights[0].k = {0.5f, 0, 0};
  EXPECT_EQ(light0(s), gray_color(100));
}

TEST(XfLighting, SpecularAttenuationCountsOnlyLitSide) {
  // GX_AF_SPEC: x = (N . l >= 0) ? max(0, N . dir) : 0, A = (a0 + a1 x + a2 x^2) / (k0 + k1 x
  // + k2 x^2). a = (0.25, 0, 1), k = (1, 0, 0), dir (half-angle) = (0, 0, 0.5) -> x = 0.5.
  XfLightingState s = one_channel(0, 255, 1, kDfNone, kAfSpec);
  s.lights[0] = light_at({0, 0, 10}, gray_color(200));
  s.lights[0].a = {0.25f, 0, 1};
  s.lights[0].k = {1, 0, 0};
  s.lights[0].direction = glm::vec3(0, 0, 0.5f);
  EXPECT_EQ(light0(s).r, 99);  // A = 0.25 + 0.25 = 0.5, L = 100, (255 * 100) >> 8
  // Light behind the surface (N . l = -1): x = 0, A = 0.25, L = 50, (255 * 50) >> 8 = 49.
  s.lights[0].position = glm::vec3(0, 0, -10);
  EXPECT_EQ(light0(s).r, 49);
  // Grazing (N . l = 0 counts as lit): x = 0.5 again.
  s.lights[0].position = glm::vec3(10, 0, 0);
  EXPECT_EQ(light0(s).r, 99);
  // The k polynomial is in x, not in the distance (10): k = (1, 2, 0) -> 1 + 2 * 0.5 = 2,
  // A = 0.25, L = 50.
  s.lights[0].position = glm::vec3(0, 0, 10);
  s.lights[0].k = {1, 2, 0};
  EXPECT_EQ(light0(s).r, 49);
  // k is not normalised, even with a diffuse function (PR#10481): k = (2, 0, 0), CLAMP (D = 1)
  // -> A = 0.5 / 2 = 0.25, L = 50. Normalising k to (1, 0, 0) would give L = 100.
  s.lights[0].k = {2, 0, 0};
  s.control[0].diffuse_fn = kDfClamp;
  EXPECT_EQ(light0(s).r, 49);
}

TEST(XfLighting, RoundEachLightDiffersFromSumThenTruncate) {
  // Two lights, each 53 * (1 / 5) = 10.6 (SPOT, k = (5, 0, 0)), ambient 128, white material
  // (the identity above 127). Sum then truncate: 128 + 21.2 -> 149. Round each: 128 + 11 + 11 =
  // 150.
  XfLightingState s = one_channel(128, 255, 0b11, kDfNone, kAfSpot);
  for (int n = 0; n < 2; ++n) {
    s.lights[n] = light_at({0, 0, 3}, gray_color(53));
    s.lights[n].k = {5, 0, 0};
  }
  EXPECT_EQ(light0(s, kUp, LightRounding::SumThenTruncate).r, 149);
  EXPECT_EQ(light0(s, kUp, LightRounding::RoundEachLight).r, 150);
  // One light: 138.6 -> 138 truncated, 139 rounded.
  s.control[0].light_mask = 0b10;
  EXPECT_EQ(light0(s, kUp, LightRounding::SumThenTruncate).r, 138);
  EXPECT_EQ(light0(s, kUp, LightRounding::RoundEachLight).r, 139);
}

TEST(XfLighting, LightMaskSelectsLights) {
  // Lights 0 (colour 10), 3 (colour 40) and 7 (colour 80) exist; the mask picks 3 and 7.
  XfLightingState s = one_channel(128, 255, (1 << 3) | (1 << 7), kDfNone, kAfNone);
  s.lights[0] = light_at({0, 0, 1}, gray_color(10));
  s.lights[3] = light_at({0, 0, 1}, gray_color(40));
  s.lights[7] = light_at({0, 0, 1}, gray_color(80));
  EXPECT_EQ(light0(s).r, 128 + 40 + 80);
}

TEST(XfLighting, DegenerateInputsGiveDefinedValues) {
  // Zero normal: N = 0, so D = 0 for CLAMP and SIGNED. Ambient 50, white: (255 * 50) >> 8 = 49.
  XfLightingState s = one_channel(50, 255, 1, kDfClamp, kAfNone);
  s.lights[0] = light_at({0, 0, 5}, gray_color(100));
  EXPECT_EQ(light0(s, glm::vec3(0)).r, 49);
  s.control[0].diffuse_fn = kDfSigned;
  EXPECT_EQ(light0(s, glm::vec3(0)).r, 49);
  // A NaN normal is treated as no normal.
  EXPECT_EQ(light0(s, glm::vec3(kNaN, 0, 1)).r, 49);
  // Zero normal under SPEC: x = 0, A = a0 / k0 = 0.5, L = 50 + 50 = 100 -> 99.
  s.control[0].attenuation_fn = kAfSpec;
  s.control[0].diffuse_fn = kDfNone;
  s.lights[0].a = {0.5f, 1, 1};
  s.lights[0].k = {1, 1, 1};
  s.lights[0].direction = glm::vec3(0, 0, 1);
  EXPECT_EQ(light0(s, glm::vec3(0)).r, 99);

  // Light exactly at the vertex: l = N, so CLAMP gives D = 1: L = 50 + 100 = 150.
  s = one_channel(50, 255, 1, kDfClamp, kAfNone);
  s.lights[0] = light_at(kOrigin, gray_color(100));
  EXPECT_EQ(light0(s).r, 150);
  // ... and under SPOT, dist = 0: A = a0 / k0 = 1 / 2, L = 50 + 50 = 100 -> 99.
  s.control[0].attenuation_fn = kAfSpot;
  s.lights[0].k = {2, 7, 7};
  EXPECT_EQ(light0(s).r, 99);
  // Light at the vertex and a zero normal: l = N = 0, D = 0.
  EXPECT_EQ(light0(s, glm::vec3(0)).r, 49);
  // Denominator 0: A = 1 for a positive numerator (DSW SafeDivide): L = 150.
  s.lights[0].k = {0, 0, 0};
  EXPECT_EQ(light0(s).r, 150);

  // A huge A (k0 = 1e-30): 100 * 1e30 saturates. Material 200: (200 * 256) >> 8 = 200.
  s = one_channel(50, 200, 1, kDfNone, kAfSpot);
  s.lights[0] = light_at({0, 0, 1}, gray_color(100));
  s.lights[0].k = {1e-30f, 0, 0};
  EXPECT_EQ(light0(s).r, 200);
  // A infinite (1 / 1e-45 overflows float): still saturates.
  s.lights[0].k = {1e-45f, 0, 0};
  EXPECT_EQ(light0(s).r, 200);
  // Infinite A times D = 0 (a grazing light, CLAMP) is NaN in float: counted as no light.
  // Ambient only: (200 * 50) >> 8 = 39.
  s.control[0].diffuse_fn = kDfClamp;
  s.lights[0].position = glm::vec3(1, 0, 0);
  EXPECT_EQ(light0(s).r, 39);
  // Huge angular coefficients overflow to infinity: saturates.
  s.control[0].diffuse_fn = kDfNone;
  s.lights[0].k = {1, 0, 0};
  s.lights[0].a = {3e38f, 3e38f, 3e38f};
  s.lights[0].direction = glm::vec3(1, 0, 0);  // l = (1, 0, 0): x = 1
  EXPECT_EQ(light0(s).r, 200);
  // +inf and -inf contributions (SIGNED, one light in front, one behind) sum to NaN: 0.
  s = one_channel(50, 200, 0b11, kDfSigned, kAfSpot);
  s.lights[0] = light_at({0, 0, 1}, gray_color(100));
  s.lights[1] = light_at({0, 0, -1}, gray_color(100));
  s.lights[0].k = s.lights[1].k = {1e-45f, 0, 0};
  EXPECT_EQ(light0(s).r, 0);
  // A NaN light direction under SPOT: x = max(0, NaN) = 0, A = a0 / k0 = 1, L = 150 -> 150.
  s = one_channel(50, 255, 1, kDfNone, kAfSpot);
  s.lights[0] = light_at({0, 0, 1}, gray_color(100));
  s.lights[0].a = {1, 5, 5};
  s.lights[0].direction = glm::vec3(kNaN);
  EXPECT_EQ(light0(s).r, 150);
  // A NaN light position under SPOT: the distance term is NaN, the light counts as none.
  s.lights[0].position = glm::vec3(kNaN);
  EXPECT_EQ(light0(s).r, 49);
  // A light very far away (|v|^2 = 2^200 overflows float) still has its direction, l = (1, 0,
  // 0). Powers of two keep the normalisation exact, so D is exactly 1 or -1.
  s = one_channel(50, 255, 1, kDfClamp, kAfNone);
  s.lights[0] = light_at({std::ldexp(1.0f, 100), 0, 0}, gray_color(100));
  EXPECT_EQ(light0(s, glm::vec3(1, 0, 0)).r, 150);
  EXPECT_EQ(light0(s, glm::vec3(-1, 0, 0)).r, 49);
  // A tiny normal (|N|^2 = 2^-200 underflows float) is still a direction.
  EXPECT_EQ(light0(s, glm::vec3(std::ldexp(1.0f, -100), 0, 0)).r, 150);
}

TEST(XfLighting, AlphaUsesItsOwnControl) {
  XfLightingState s = one_channel(20, 255, 1, kDfNone, kAfNone);
  s.lights[0] = light_at({0, 0, 1}, Color8{0, 0, 0, 200});  // alpha-only light colour
  s.lights[1] = light_at({0, 0, 1}, Color8{150, 150, 150, 30});
  s.material[0] = Color8{255, 255, 255, 255};
  // COLOR0 lit by light 1 only; ALPHA0 unlit, material alpha 77 from the register.
  s.control[0].light_mask = 0b10;
  s.control[2].lighting = false;
  s.material[0].a = 77;
  Color8 out = light0(s);
  EXPECT_EQ(out.r, 170);  // L = 20 + 150 = 170
  EXPECT_EQ(out.a, 77);
  // ALPHA0 lit by light 0 (alpha 200) with ambient alpha from the vertex; COLOR0 unlit.
  s.control[0].lighting = false;
  s.control[2].lighting = true;
  s.control[2].light_mask = 0b01;
  s.control[2].ambient_source = kVtx;
  s.material[0] = Color8{9, 8, 7, 255};
  const std::array<Color8, kMaxChannels> vtx{Color8{1, 2, 3, 40}, Color8{}};
  out = light_vertex(s, kOrigin, kUp, vtx)[0];
  EXPECT_EQ(out.r, 9);    // unlit colour: the register material unchanged
  EXPECT_EQ(out.a, 240);  // L = 40 + 200
  // The alpha control's own diffuse function: CLAMP with the light behind gives L = 40 -> 39,
  // while the colour control is still unlit.
  s.control[2].diffuse_fn = kDfClamp;
  s.lights[0].position = glm::vec3(0, 0, -1);
  out = light_vertex(s, kOrigin, kUp, vtx)[0];
  EXPECT_EQ(out.a, 39);
  EXPECT_EQ(out.g, 8);
  // SIGNED: in front L = 40 + 200 = 240; behind L = 40 - 200 < 0 -> 0.
  s.control[2].diffuse_fn = kDfSigned;
  EXPECT_EQ(light_vertex(s, kOrigin, kUp, vtx)[0].a, 0);
  s.lights[0].position = glm::vec3(0, 0, 1);
  EXPECT_EQ(light_vertex(s, kOrigin, kUp, vtx)[0].a, 240);
}

TEST(XfLighting, ChannelsBeyondNumChannelsAreZero) {
  XfLightingState s = one_channel(50, 255, 0, kDfNone, kAfNone);
  s.control[1] = s.control[0];
  s.control[3] = s.control[0];
  s.ambient[1] = gray_color(200);
  // Non-zero vertex colours, so that "zero" cannot come from a pass-through.
  const std::array<Color8, kMaxChannels> vtx{gray_color(11), gray_color(22)};
  auto out = light_vertex(s, kOrigin, kUp, vtx);
  EXPECT_EQ(out[0], gray_color(49));
  EXPECT_EQ(out[1], (Color8{0, 0, 0, 0}));
  s.num_channels = 0;
  out = light_vertex(s, kOrigin, kUp, vtx);
  EXPECT_EQ(out[0], (Color8{0, 0, 0, 0}));
  s.num_channels = 2;
  out = light_vertex(s, kOrigin, kUp, vtx);
  EXPECT_EQ(out[1], gray_color(200));
}

// ---- texgen ----

TEST(XfTexGen, InitLoadsTheIdentityAtGxIdentityOnly) {
  const XfTexGenState s;
  const TexMatrix identity{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
  EXPECT_EQ(s.matrices[20], identity);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(s.matrices[i], TexMatrix{}) << i;
}

TEST(XfTexGen, IdentityFromTexCoordPassesST) {
  const XfTexGenState s;  // texgen n = (MTX2x4, TEXn, IDENTITY)
  TexGenInputs in;
  in.texcoords[0] = glm::vec2(0.25f, -3.5f);
  in.texcoords[3] = glm::vec2(7, 0.125f);
  EXPECT_EQ(generate_texcoord(s, 0, in), glm::vec3(0.25f, -3.5f, 1));
  EXPECT_EQ(generate_texcoord(s, 3, in), glm::vec3(7, 0.125f, 1));
}

TEST(XfTexGen, Mtx2x4OnTheRawNormal) {
  XfTexGenState s;
  s.texgens[0] = TexGen{1, 1, 30};  // MTX2x4, GX_TG_NRM, GX_TEXMTX0
  s.matrices[10] = TexMatrix{{{1, 2, 3, 0.5f}, {0, 0, 0, 0.25f}, {9, 9, 9, 9}}};
  TexGenInputs in;
  in.normal = glm::vec3(0.5f, 0.25f, 2);  // length != 1: used as sent
  // s = 0.5 + 0.5 + 6 + 0.5 = 7.5; t = 0.25; q = 1 (the third row is ignored for 2x4).
  EXPECT_EQ(generate_texcoord(s, 0, in), glm::vec3(7.5f, 0.25f, 1));
  // Position source, same matrix: (1, 2, 3, 1) -> 1 + 4 + 9 + 0.5 = 14.5.
  s.texgens[0].source = 0;
  in.position = glm::vec3(1, 2, 3);
  EXPECT_EQ(generate_texcoord(s, 0, in), glm::vec3(14.5f, 0.25f, 1));
}

TEST(XfTexGen, Mtx3x4GivesQWithoutDividing) {
  XfTexGenState s;
  s.texgens[2] = TexGen{0, 4, 57};  // MTX3x4, GX_TG_TEX0, GX_TEXMTX9
  s.matrices[19] = TexMatrix{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 2, 1}}};
  TexGenInputs in;
  in.texcoords[0] = glm::vec2(3, 4);
  // Form AB11: (3, 4, 1, 1). q = 2 * 1 + 1 = 3; s and t are not divided by q.
  EXPECT_EQ(generate_texcoord(s, 2, in), glm::vec3(3, 4, 3));
  // Normal source, form ABC1: (1, 1, 5, 1) -> q = 10 + 1 = 11.
  s.texgens[2].source = 1;
  in.normal = glm::vec3(1, 1, 5);
  EXPECT_EQ(generate_texcoord(s, 2, in), glm::vec3(1, 1, 11));
}

TEST(XfTexGen, NanInputsAreReplacedByOne) {
  XfTexGenState s;
  s.texgens[0] = TexGen{0, 4, 30};
  s.matrices[10] = TexMatrix{{{10, 0, 0, 0}, {0, 1, 0, 0}, {1, 2, 3, 4}}};
  TexGenInputs in;
  in.texcoords[0] = glm::vec2(kNaN, 2);
  // (NaN, 2, 1, 1) -> (1, 2, 1, 1): s = 10, t = 2, q = 1 + 4 + 3 + 4 = 12.
  EXPECT_EQ(generate_texcoord(s, 0, in), glm::vec3(10, 2, 12));
  s.texgens[0].source = 1;
  in.normal = glm::vec3(kNaN);
  // (1, 1, 1, 1): s = 10, t = 1, q = 1 + 2 + 3 + 4 = 10.
  EXPECT_EQ(generate_texcoord(s, 0, in), glm::vec3(10, 1, 10));
}

TEST(XfTexGenDeathTest, UnmodelledSourceIsABug) {
  XfTexGenState s;
  s.texgens[0].source = 2;  // GX_TG_BINRM
  EXPECT_DEATH(generate_texcoord(s, 0, TexGenInputs{}), "texgen source");
}

}  // namespace
}  // namespace lt::gx
