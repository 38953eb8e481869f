// Bit-exact tests of the EFB end of the GX path (src/gx/efb.h): the 8-bit store of the TEV
// output, the alpha test and the blend unit (gx-hardware.md §1.5; Dolphin SW EfbInterface).
#include <gtest/gtest.h>

#include "gx/efb.h"

namespace lt::gx {
namespace {

constexpr u8 kNone = 0, kBlend = 1, kLogic = 2, kSubtract = 3;
constexpr u8 kZero = 0, kOne = 1, kSrcClr = 2, kInvSrcClr = 3, kSrcAlpha = 4, kInvSrcAlpha = 5,
             kDstAlpha = 6, kInvDstAlpha = 7;
constexpr u8 kNever = 0, kLess = 1, kEqual = 2, kLEqual = 3, kGreater = 4, kNEqual = 5, kGEqual = 6,
             kAlways = 7;
constexpr u8 kAnd = 0, kOr = 1, kXor = 2, kXnor = 3;

ColorS10 color_s10(int r, int g, int b, int a) {
  return {static_cast<s16>(r), static_cast<s16>(g), static_cast<s16>(b), static_cast<s16>(a)};
}

BlendMode mode(u8 type, u8 src, u8 dst, u8 logic = 0) {
  BlendMode m;
  m.type = type;
  m.src = src;
  m.dst = dst;
  m.logic = logic;
  return m;
}

TEST(GxEfb, TevToEfbKeepsLow8Bits) {
  EXPECT_EQ(tev_to_efb(color_s10(-1, 300, 128, 0)), (Color8{255, 44, 128, 0}));
  EXPECT_EQ(tev_to_efb(color_s10(1023, -1024, 256, 255)), (Color8{255, 0, 0, 255}));
  EXPECT_EQ(tev_to_efb(color_s10(-256, 511, -129, 7)), (Color8{0, 255, 127, 7}));
}

TEST(GxEfb, AlphaTestComparisons) {
  const u8 ref = 100;
  struct Row {
    u8 comp;
    bool below, at, above;  // alpha = 99, 100, 101
  };
  const Row rows[] = {
      {kNever, false, false, false}, {kLess, true, false, false},    {kEqual, false, true, false},
      {kLEqual, true, true, false},  {kGreater, false, false, true}, {kNEqual, true, false, true},
      {kGEqual, false, true, true},  {kAlways, true, true, true},
  };
  for (const Row& r : rows) {
    // comp1 ALWAYS with AND: the result is comp0 alone.
    AlphaCompare c{r.comp, ref, kAnd, kAlways, 0};
    EXPECT_EQ(alpha_test(c, 99), r.below) << int(r.comp);
    EXPECT_EQ(alpha_test(c, 100), r.at) << int(r.comp);
    EXPECT_EQ(alpha_test(c, 101), r.above) << int(r.comp);
    // And comp1 alone, with comp0 NEVER under OR.
    AlphaCompare d{kNever, 0, kOr, r.comp, ref};
    EXPECT_EQ(alpha_test(d, 99), r.below) << int(r.comp);
    EXPECT_EQ(alpha_test(d, 100), r.at) << int(r.comp);
    EXPECT_EQ(alpha_test(d, 101), r.above) << int(r.comp);
  }
  // Extremes: LESS 0 never passes, GREATER 255 never passes.
  EXPECT_FALSE(alpha_test({kLess, 0, kAnd, kAlways, 0}, 0));
  EXPECT_FALSE(alpha_test({kGreater, 255, kAnd, kAlways, 0}, 255));
}

TEST(GxEfb, AlphaTestOps) {
  // comp0 = (alpha >= 50), comp1 = (alpha <= 150): alpha 10 gives F,T; 100 T,T; 200 T,F.
  const struct {
    u8 op;
    bool at10, at100, at200;
  } rows[] = {
      {kAnd, false, true, false},
      {kOr, true, true, true},
      {kXor, true, false, true},
      {kXnor, false, true, false},
  };
  for (const auto& r : rows) {
    AlphaCompare c{kGEqual, 50, r.op, kLEqual, 150};
    EXPECT_EQ(alpha_test(c, 10), r.at10) << int(r.op);
    EXPECT_EQ(alpha_test(c, 100), r.at100) << int(r.op);
    EXPECT_EQ(alpha_test(c, 200), r.at200) << int(r.op);
  }
  // XNOR of two false terms passes; XOR of two true terms fails.
  EXPECT_TRUE(alpha_test({kNever, 0, kXnor, kNever, 0}, 5));
  EXPECT_FALSE(alpha_test({kAlways, 0, kXor, kAlways, 0}, 5));
  // GX_Init's setting passes everything.
  for (int a = 0; a < 256; ++a) EXPECT_TRUE(alpha_test(AlphaCompare{}, static_cast<u8>(a)));
}

TEST(GxEfb, BlendNoneWritesSource) {
  const Color8 src{1, 2, 3, 4}, dst{200, 100, 50, 255};
  EXPECT_EQ(blend(BlendMode{}, src, dst), src);
  EXPECT_EQ(blend(mode(kNone, kOne, kOne), src, dst), src);
}

TEST(GxEfb, BlendOneOneSaturates) {
  const BlendMode m = mode(kBlend, kOne, kOne);
  EXPECT_EQ(blend(m, {200, 100, 0, 9}, {100, 50, 255, 0}), (Color8{255, 150, 255, 9}));
  EXPECT_EQ(blend(m, {0, 1, 254, 0}, {0, 1, 1, 0}), (Color8{0, 2, 255, 0}));
}

// The blend unit blends alpha like the colours [DSW BlendColor, i < 4]; what the EFB keeps of
// it is the pixel format's business (GxEfb.RgbA6StoresSixBitsAndAlpha).
TEST(GxEfb, BlendZero) {
  EXPECT_EQ(blend(mode(kBlend, kZero, kZero), {200, 100, 50, 77}, {10, 20, 30, 0}),
            (Color8{0, 0, 0, 0}));
  EXPECT_EQ(blend(mode(kBlend, kZero, kOne), {200, 100, 50, 77}, {10, 20, 30, 0}),
            (Color8{10, 20, 30, 0}));
  EXPECT_EQ(blend(mode(kBlend, kOne, kZero), {200, 100, 50, 77}, {10, 20, 30, 0}),
            (Color8{200, 100, 50, 77}));
}

TEST(GxEfb, BlendSrcAlphaUsesWidenedFactors) {
  const BlendMode m = mode(kBlend, kSrcAlpha, kInvSrcAlpha);
  // alpha 128: sf' = 129, df' = 127.
  //   r: (200*129 + 0*127) >> 8 = 25800 >> 8 = 100
  //   g: (100*129 + 100*127) >> 8 = 25600 >> 8 = 100
  //   b: (0*129 + 255*127) >> 8 = 32385 >> 8 = 126  (a /255 blend would give 127)
  //   a: (128*129 + 0*127) >> 8 = 16512 >> 8 = 64
  EXPECT_EQ(blend(m, {200, 100, 0, 128}, {0, 100, 255, 0}), (Color8{100, 100, 126, 64}));
  // alpha 64: sf' = 64, df' = 191 + 1 = 192: r (200*64 + 40*192) >> 8 = 20480 >> 8 = 80;
  // a (64*64) >> 8 = 16.
  EXPECT_EQ(blend(m, {200, 0, 255, 64}, {40, 255, 0, 0}), (Color8{80, 191, 63, 16}));
  // alpha 255 and 0 are exact: src and dst.
  EXPECT_EQ(blend(m, {17, 18, 19, 255}, {1, 2, 3, 0}), (Color8{17, 18, 19, 255}));
  EXPECT_EQ(blend(m, {17, 18, 19, 0}, {1, 2, 3, 0}), (Color8{1, 2, 3, 0}));
  // INVSRCALPHA as source factor, SRCALPHA as destination: alpha 128 -> sf' 127, df' 129;
  // a (128*127) >> 8 = 63.
  EXPECT_EQ(blend(mode(kBlend, kInvSrcAlpha, kSrcAlpha), {200, 100, 0, 128}, {0, 100, 255, 0}),
            (Color8{99, 100, 128, 63}));
}

// Factor 2/3 reads the destination colour as a source factor and the source colour as a
// destination factor. With src 255 and dst 100 the two products differ:
// src*dst' = (255*100) >> 8 = 99, dst*src' = (100*256) >> 8 = 100.
TEST(GxEfb, BlendColourFactorsReadTheOtherOperand) {
  // Alpha takes the other operand's alpha the same way: 1 and 0 give 0 both ways, and the
  // inverses 1 * 256 >> 8 = 1 and 0.
  const Color8 src{255, 128, 0, 1}, dst{100, 255, 77, 0};
  EXPECT_EQ(blend(mode(kBlend, kSrcClr, kZero), src, dst), (Color8{99, 128, 0, 0}));
  EXPECT_EQ(blend(mode(kBlend, kZero, kSrcClr), src, dst), (Color8{100, 128, 0, 0}));
  // Inverse: r src*(255-dst)' = (255*(155+1)) >> 8 = 155; dst*(255-src)' gives
  // g (255*127) >> 8 = 126 and b (77*256) >> 8 = 77.
  EXPECT_EQ(blend(mode(kBlend, kInvSrcClr, kZero), src, dst), (Color8{155, 0, 0, 1}));
  EXPECT_EQ(blend(mode(kBlend, kZero, kInvSrcClr), src, dst), (Color8{0, 126, 77, 0}));
}

// RGB8_Z24 stores no alpha; Dolphin reads the destination alpha back as 255, so DSTALPHA is one
// and INVDSTALPHA zero (the alphas: 3 * 256 >> 8 = 3, 255 * 256 >> 8 = 255, 3 + 255 clamped).
TEST(GxEfb, BlendDstAlphaIsOpaqueInRgb8) {
  const Color8 src{200, 100, 50, 3}, dst = efb_stored(kPixelRgb8Z24, {10, 20, 30, 0});
  EXPECT_EQ(dst, (Color8{10, 20, 30, 255}));
  EXPECT_EQ(blend(mode(kBlend, kDstAlpha, kZero), src, dst), (Color8{200, 100, 50, 3}));
  EXPECT_EQ(blend(mode(kBlend, kInvDstAlpha, kOne), src, dst), (Color8{10, 20, 30, 255}));
  EXPECT_EQ(blend(mode(kBlend, kOne, kDstAlpha), src, dst), (Color8{210, 120, 80, 255}));
  EXPECT_EQ(blend(mode(kBlend, kOne, kInvDstAlpha), src, dst), (Color8{200, 100, 50, 3}));
}

// RGBA6_Z24 keeps the top 6 bits of r, g, b and a and reads them back as v << 2 | v >> 4 [DSW
// SetPixelAlphaColor, GetPixelColor, Convert6To8]: 200 -> 50 -> 200 | 3 = 203, 100 -> 25 ->
// 100 | 1 = 101, 50 -> 12 -> 48 | 0 = 48, 255 -> 63 -> 252 | 3 = 255, 3 -> 0 -> 0. Its alpha
// then weighs a DSTALPHA blend: dst alpha 128 -> 32 -> 128 | 2 = 130, so sf' = 131 and r of
// (200 * 131) >> 8 = 102.
TEST(GxEfb, RgbA6StoresSixBitsAndAlpha) {
  EXPECT_EQ(efb_stored(kPixelRgba6Z24, {200, 100, 50, 255}), (Color8{203, 101, 48, 255}));
  EXPECT_EQ(efb_stored(kPixelRgba6Z24, {3, 4, 252, 3}), (Color8{0, 4, 255, 0}));
  // RGB565_Z16 is kept as RGB8_Z24 by Dolphin's software renderer ("not supported correctly
  // yet"): 8 bits, alpha read as 255.
  EXPECT_EQ(efb_stored(kPixelRgb565Z16, {201, 7, 33, 9}), (Color8{201, 7, 33, 255}));
  const Color8 dst = efb_stored(kPixelRgba6Z24, {0, 0, 0, 128});
  EXPECT_EQ(dst.a, 130);
  EXPECT_EQ(blend(mode(kBlend, kDstAlpha, kZero), {200, 0, 0, 0}, dst).r, 102);
}

// Dithering [DSW Dither]: RGBA6_Z24 only, r g b (not a) get ((c - (c >> 6)) + d) & 0xfc with
// the 2x2 Bayer d = {{0, 2}, {3, 1}}[y & 1][x & 1], then the 6-bit storage. c = 201:
// 201 - 3 = 198; + 0 = 198 & 0xfc = 196 -> 49 -> 196 | 3 = 199 at (0, 0); + 2 = 200 -> 50 ->
// 203 at (1, 0); + 3 = 201 & 0xfc = 200 -> 203 at (0, 1); + 1 = 199 & 0xfc = 196 -> 199 at
// (1, 1). Without the dither 201 -> 50 -> 203 everywhere.
TEST(GxEfb, DitherIsTheBayerOffsetOfRgbA6Only) {
  const Color8 c{201, 201, 201, 201};
  EXPECT_EQ(efb_written(kPixelRgba6Z24, true, 0, 0, c), (Color8{199, 199, 199, 203}));
  EXPECT_EQ(efb_written(kPixelRgba6Z24, true, 1, 0, c), (Color8{203, 203, 203, 203}));
  EXPECT_EQ(efb_written(kPixelRgba6Z24, true, 0, 1, c), (Color8{203, 203, 203, 203}));
  EXPECT_EQ(efb_written(kPixelRgba6Z24, true, 1, 1, c), (Color8{199, 199, 199, 203}));
  EXPECT_EQ(efb_written(kPixelRgba6Z24, false, 0, 0, c), (Color8{203, 203, 203, 203}));
  // RGB8_Z24 and RGB565_Z16 are not dithered (Dolphin: "No blending for RGB8 mode").
  EXPECT_EQ(efb_written(kPixelRgb8Z24, true, 0, 0, c), (Color8{201, 201, 201, 255}));
  EXPECT_EQ(efb_written(kPixelRgb565Z16, true, 1, 0, c), (Color8{201, 201, 201, 255}));
}

TEST(GxEfb, BlendSubtract) {
  // dst - src clamped at 0; the factors play no part.
  EXPECT_EQ(blend(mode(kSubtract, kOne, kOne), {30, 60, 0, 5}, {100, 50, 0, 0}),
            (Color8{70, 0, 0, 0}));
  EXPECT_EQ(blend(mode(kSubtract, kZero, kZero), {1, 255, 10, 5}, {255, 255, 9, 9}),
            (Color8{254, 0, 0, 4}));
}

TEST(GxEfb, BlendLogicOps) {
  const u8 s = 0xCA, d = 0xAC;  // 11001010, 10101100
  const u8 expect[16] = {
      0x00,  // CLEAR
      0x88,  // AND
      0x42,  // REVAND  s & ~d
      0xCA,  // COPY
      0x24,  // INVAND  ~s & d
      0xAC,  // NOOP
      0x66,  // XOR
      0xEE,  // OR
      0x11,  // NOR
      0x99,  // EQUIV
      0x53,  // INV     ~d
      0xDB,  // REVOR   s | ~d
      0x35,  // INVCOPY ~s
      0xBD,  // INVOR   ~s | d
      0x77,  // NAND
      0xFF,  // SET
  };
  for (u8 op = 0; op < 16; ++op) {
    const Color8 out = blend(mode(kLogic, kOne, kOne, op), {s, 0x0F, 0xFF, 42}, {d, 0xF0, 0x00, 0});
    EXPECT_EQ(out.r, expect[op]) << int(op);
  }
  // Other channels too, alpha included: XOR of 0x0F/0xF0, 0xFF/0x00 and 42/0.
  EXPECT_EQ(blend(mode(kLogic, kOne, kOne, 6), {1, 0x0F, 0xFF, 42}, {1, 0xF0, 0x00, 0}),
            (Color8{0, 0xFF, 0xFF, 42}));
  // NOR of 42 (0x2A) and 0 is 0xD5.
  EXPECT_EQ(blend(mode(kLogic, kOne, kOne, 8), {0, 0, 0, 42}, {0, 0, 0, 0}).a, 0xD5);
}

}  // namespace
}  // namespace lt::gx
