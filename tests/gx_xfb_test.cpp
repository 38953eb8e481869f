// The console's output image (src/gx/xfb_copy.h): the EFB copied to the XFB as YUYV 4:2:2
// and decoded again, as Dolphin 5.0-17995's software renderer does. Every expected value below was
// worked out by hand from the formulas the code cites (EncodeXFB's integer BT.601 with its
// round-half-up, the [1 2 1]/4 chroma filter, TexDecoder_DecodeXFB's float inverse truncated
// toward zero); the arithmetic is in the comments so a reader can redo it.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "image/image.h"
#include "load/load_scene.h"
#include "gx/xfb_copy.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx {
namespace {

std::vector<Color8> flat(int width, int height, Color8 c) {
  return std::vector<Color8>(static_cast<size_t>(width) * height, c);
}

// Two identical EFB rows of `width` pixels: `left` for x < edge, `right` from there on.
std::vector<Color8> vertical_edge(int width, int edge, Color8 left, Color8 right) {
  std::vector<Color8> rows(2 * static_cast<size_t>(width), left);
  for (int y = 0; y < 2; ++y) {
    for (int x = edge; x < width; ++x) rows[static_cast<size_t>(y * width + x)] = right;
  }
  return rows;
}

constexpr Color8 kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255};

std::string str(const Color8& c) {
  return std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b);
}

// Every pixel of a flat 4x2 EFB of colour `in` is shown as `shown`.
void expect_flat(Color8 in, Color8 shown) {
  const auto out = efb_as_displayed(flat(4, 2, in), 4, 2, EfbCopyState{});
  for (const Color8& c : out) EXPECT_EQ(c, shown) << str(in) << " is shown as " << str(c);
}

// Greys: Y = round_half_up(220 g / 256) (66 + 129 + 25 = 220), U = V = 0; shown as
// int(1.164 Y). 0 -> Y 0 -> 0. 255: 56100 >> 8 = 219, bit 7 of 56100 clear -> Y 219 ->
// 1.164 * 219 = 254.916 -> 254: white is shown one LSB darker. 128: 28160 = 110 * 256 -> 128.04
// -> 128. 64: 14080 = 55 * 256 -> 64.02 -> 64. 200: 44000 >> 8 = 171, bit 7 set -> 172 ->
// 200.208 -> 200. 254: 55880 >> 8 = 218, bit 7 clear -> 253.752 -> 253. 1: 220 >> 8 = 0, bit 7
// set -> 1 -> 1.164 -> 1.
TEST(GxXfb, FlatGreys) {
  expect_flat({0, 0, 0, 255}, {0, 0, 0, 255});
  expect_flat({255, 255, 255, 255}, {254, 254, 254, 255});
  expect_flat({128, 128, 128, 255}, {128, 128, 128, 255});
  expect_flat({64, 64, 64, 255}, {64, 64, 64, 255});
  expect_flat({200, 200, 200, 255}, {200, 200, 200, 255});
  expect_flat({254, 254, 254, 255}, {253, 253, 253, 255});
  expect_flat({1, 1, 1, 255}, {1, 1, 1, 255});
}

// Primaries. Red: Y = (16830 >> 8 = 65) + bit 7 = 66, U = -9690 >> 8 = -38 (bit 7 of -9690
// clear), V = 28560 >> 8 = 111 + 1 = 112 -> R = 1.164*66 + 1.596*112 = 255.58 -> 255,
// G = 76.824 + 14.896 - 91.056 = 0.66 -> 0, B = 76.824 - 76.646 = 0.18 -> 0.
// Green: Y = 32895 >> 8 = 128, U = -18870 >> 8 = -74, V = -23970 >> 8 = -94 (bits 7 clear) ->
// R = 148.992 - 150.024 = -1.03 -> 0, G = 148.992 + 29.008 + 76.422 = 254.42 -> 254,
// B = 148.992 - 149.258 -> 0. Blue: Y = 6375 >> 8 = 24 + 1 = 25, U = 112, V = -4590 >> 8 = -18
// -> R = 29.1 - 28.728 = 0.37 -> 0, G = 29.1 - 43.904 + 14.634 = -0.17 -> 0,
// B = 29.1 + 225.904 = 255.004 -> 255.
TEST(GxXfb, FlatPrimaries) {
  expect_flat(kRed, {255, 0, 0, 255});
  expect_flat(kGreen, {0, 254, 0, 255});
  expect_flat(kBlue, {0, 0, 255, 255});
}

// A hand-written probe FIFO log (a throwaway writer, not in this repository): Dolphin showed
// an EFB of (255, 128, 0) as (255, 127, 0). Y = 33342 >> 8 = 130, U = -19162 >> 8 = -75,
// V = 16528 >> 8 = 64 + 1 = 65 -> R = 151.32 + 103.74 -> 255,
// G = 151.32 + 29.4 - 52.845 = 127.875 -> 127, B = 151.32 - 151.275 = 0.045 -> 0.
TEST(GxXfb, OrangeAsDolphinShowedIt) {
  expect_flat({255, 128, 0, 255}, {255, 127, 0, 255});
}

// The bytes in RAM for flat red: Y + 16 = 82 on both pixels, 128 + U = 90 on the even one,
// 128 + V = 240 on the odd one.
TEST(GxXfb, FlatRedInRam) {
  const auto xfb = encode_xfb(flat(2, 2, kRed), 2, 2, EfbCopyState{});
  for (size_t p = 0; p < xfb.size(); p += 2) {
    EXPECT_EQ(xfb[p], (XfbPixel{82, 90}));
    EXPECT_EQ(xfb[p + 1], (XfbPixel{82, 240}));
  }
}

// Red | blue with the edge at an even column (4): the pair (4, 5) filters U and V over columns
// 3, 4, 5 = red, blue, blue: U = (-38 + 2*112 + 112) >> 2 = 298 >> 2 = 74, V = (112 - 36 - 18)
// >> 2 = 14; both keep blue's Y 25: R = 29.1 + 22.344 -> 51, G = 29.1 - 29.008 - 11.382 -> 0,
// B = 29.1 + 149.258 -> 178. Pairs (2, 3) and (6, 7) read one colour only.
TEST(GxXfb, VerticalEdgeAtAnEvenColumnBleedsIntoTheRightPair) {
  const auto out = efb_as_displayed(vertical_edge(8, 4, kRed, kBlue), 8, 2, EfbCopyState{});
  const Color8 r{255, 0, 0, 255}, b{0, 0, 255, 255}, mix{51, 0, 178, 255};
  const std::vector<Color8> want = {r, r, r, r, mix, mix, b, b};
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(out[static_cast<size_t>(y * 8 + x)], want[x]) << "column " << x << " row " << y;
  }
}

// The edge at an odd column (5): the pair (4, 5) reads red, red, blue: U = (-38 - 76 + 112) >> 2
// = -2 >> 2 = -1 (a floor), V = (112 + 224 - 18) >> 2 = 79. Column 4 keeps red's Y 66:
// R = 76.824 + 126.084 -> 202, G = 76.824 + 0.392 - 64.227 = 12.99 -> 12, B = 76.824 - 2.017 ->
// 74. Column 5 keeps blue's Y 25: R = 29.1 + 126.084 -> 155, G -> 0, B = 29.1 - 2.017 -> 27.
TEST(GxXfb, VerticalEdgeAtAnOddColumnMixesThePairAcrossIt) {
  const auto out = efb_as_displayed(vertical_edge(8, 5, kRed, kBlue), 8, 2, EfbCopyState{});
  const Color8 r{255, 0, 0, 255}, b{0, 0, 255, 255};
  const std::vector<Color8> want = {r, r, r, r, {202, 12, 74, 255}, {155, 0, 27, 255}, b, b};
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(out[static_cast<size_t>(y * 8 + x)], want[x]) << "column " << x << " row " << y;
  }
}

// For any edge position and colours: luma is per pixel (each XFB Y is its own colour's), and
// chroma reaches at most the pixels next to the edge - a pair filters columns x-1..x+1 around its
// even pixel x, so only the pair holding column edge-1 or edge can mix, i.e. columns edge-1,
// edge, edge+1 (two of them for a given parity).
TEST(GxXfb, ChromaBleedsAtMostOnePixelFromAVerticalEdge) {
  const std::vector<Color8> colours = {kRed, kGreen, kBlue, {30, 200, 90, 255}, {250, 250, 0, 255}};
  const int w = 12;
  for (const Color8& a : colours) {
    for (const Color8& b : colours) {
      const auto flat_a = efb_as_displayed(flat(w, 2, a), w, 2, {});
      const auto flat_b = efb_as_displayed(flat(w, 2, b), w, 2, {});
      const auto ya = encode_xfb(flat(w, 2, a), w, 2, {}), yb = encode_xfb(flat(w, 2, b), w, 2, {});
      for (int edge = 1; edge < w; ++edge) {
        const auto xfb = encode_xfb(vertical_edge(w, edge, a, b), w, 2, {});
        const auto out = decode_xfb(xfb, w, 2);
        for (int x = 0; x < w; ++x) {
          const size_t i = static_cast<size_t>(x);
          EXPECT_EQ(xfb[i].y, (x < edge ? ya : yb)[i].y) << str(a) << "|" << str(b) << " @" << edge;
          if (x < edge - 1 || x > edge + 1)
            EXPECT_EQ(out[i], (x < edge ? flat_a : flat_b)[i]) << x << " @" << edge;
        }
      }
    }
  }
}

// GX_Init's vertical filter {0,0,21,22,21,0,0} puts all 64 on the current line: a horizontal
// edge reaches no row next to it; every row is shown as its own flat colour.
TEST(GxXfb, HorizontalEdgeIsUntouchedByGxInitsFilter) {
  const int w = 4, h = 6;
  auto efb = flat(w, h, kRed);
  std::fill(efb.begin() + w * h / 2, efb.end(), kBlue);
  const auto out = efb_as_displayed(efb, w, h, EfbCopyState{});
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      EXPECT_EQ(out[static_cast<size_t>(y * w + x)],
                (y < h / 2 ? Color8{255, 0, 0, 255} : Color8{0, 0, 255, 255}))
          << x << "," << y;
    }
  }
}

// A filter that weighs the lines around, {0,16,0,32,0,16,0}, on grey rows 80, 100, 200, 40:
// row 0 reads itself above (the copy starts at EFB line 0): (80*16 + 80*32 + 100*16) >> 6 = 85;
// row 1: (1280 + 3200 + 3200) >> 6 = 120; row 2: (1600 + 6400 + 640) >> 6 = 135; row 3, bottom
// clamped, reads itself below: (3200 + 1280 + 640) >> 6 = 80. Lumas + 16: 85 -> 18700 >> 8 = 73
// -> 89; 120 -> 26400 >> 8 = 103 -> 119; 135 -> 29700 >> 8 = 116 -> 132; 80 -> 17600 >> 8 = 68
// + bit 7 -> 69 -> 85.
TEST(GxXfb, VerticalFilterWeighsTheLinesAroundAndClampsAtTopAndBottom) {
  EfbCopyState copy;
  copy.vertical_filter = {0, 16, 0, 32, 0, 16, 0};
  const u8 rows[] = {80, 100, 200, 40};
  std::vector<Color8> efb;
  for (u8 g : rows) efb.insert(efb.end(), 2, Color8{g, g, g, 255});
  const auto xfb = encode_xfb(efb, 2, 4, copy);
  const u8 want[] = {89, 119, 132, 85};
  for (int y = 0; y < 4; ++y) {
    EXPECT_EQ(xfb[static_cast<size_t>(2 * y)].y, want[y]) << "row " << y;
    EXPECT_EQ(xfb[static_cast<size_t>(2 * y)].uv, 128) << "a grey has no chroma";
  }
}

// Coefficients summing over 64 brighten, and the sum clamps at 255: grey 200 with
// {0,0,32,32,32,0,0} is 200*96 >> 6 = 300 -> 255 -> Y 219 -> 235 in RAM.
TEST(GxXfb, VerticalFilterClampsAt255) {
  EfbCopyState copy;
  copy.vertical_filter = {0, 0, 32, 32, 32, 0, 0};
  const auto xfb = encode_xfb(flat(2, 2, {200, 200, 200, 255}), 2, 2, copy);
  EXPECT_EQ(xfb[0].y, 235);
}

// Gamma 1.0 (GX_Init's) changes no byte: every grey keeps the luma of the integer formula.
// Gamma 2.2 brightens: 128 -> pow(128/255, 1/2.2) * 255 = 186.4 -> 186 -> Y = 40920 >> 8 = 159
// + bit 7 = 160 -> 176 in RAM.
TEST(GxXfb, Gamma) {
  for (int g = 0; g < 256; ++g) {
    const u8 v = static_cast<u8>(g);
    const int y = 220 * g;
    const int want = (y >> 8) + ((y >> 7) & 1) + 16;
    EXPECT_EQ(encode_xfb(flat(2, 2, {v, v, v, 255}), 2, 2, {})[0].y, want) << g;
  }
  EfbCopyState copy;
  copy.gamma = kGamma2_2;
  EXPECT_EQ(encode_xfb(flat(2, 2, {128, 128, 128, 255}), 2, 2, copy)[0].y, 176);
}

// The XFB holds pixel pairs: an odd width (or height, GX_SetDispCopySrc's other multiple of 2)
// cannot be copied, and the refusal says so.
TEST(GxXfb, OddSizesAreRefused) {
  EXPECT_EQ(xfb_size_refusal(640, 480), "");
  EXPECT_NE(xfb_size_refusal(641, 480).find("even width and height"), std::string::npos);
  EXPECT_NE(xfb_size_refusal(640, 479), "");
}

TEST(GxXfb, OddWidthOnTheCommandLineIsOneLineAndExit2) {
  test::TempDir dir;
  const test::RunResult r =
      test::run_ltrender("render " + (test::source_dir() / "scenes/backlit_sphere.json").string() +
                         " --path gx --variant t=vertex:out=xfb --width 321 --height 240 -o " +
                         (dir / "o.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("even width and height"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

TEST(GxXfb, VariantAxis) {
  const PathInfo& gx = find_path("gx");
  EXPECT_EQ(gx.parse_variant("t=vertex:out=efb"), "t=vertex");
  EXPECT_EQ(gx.parse_variant("out=xfb:t=vertex"), "t=vertex:out=xfb");
  EXPECT_EQ(gx.parse_variant("lobe=xf-spec:out=xfb"), "lobe=xf-spec:out=xfb");
  try {
    gx.parse_variant("t=vertex:out=tv");
    ADD_FAILURE() << "out=tv parsed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("efb or xfb"), std::string::npos) << e.what();
  }
}

// The path: out=xfb is the EFB image of out=efb put through the copy, pixel for pixel, and the
// coverage (alpha) is the same; and the round trip is not an identity, so the picture differs.
TEST(GxXfb, PathShowsTheCopiedEfb) {
  const Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  const int w = 160, h = 120;
  const Image efb_img = render_scene(scene, "gx", "t=vertex", w, h);
  const Image xfb_img = render_scene(scene, "gx", "t=vertex:out=xfb", w, h);
  std::vector<Color8> efb;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float* p = efb_img.at(x, y);
      efb.push_back({to_unorm8(p[0]), to_unorm8(p[1]), to_unorm8(p[2]), 255});
    }
  }
  const auto want = efb_as_displayed(efb, w, h, EfbCopyState{});
  int differ = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float* p = xfb_img.at(x, y);
      const Color8& c = want[static_cast<size_t>(y * w + x)];
      for (int ch = 0; ch < 3; ++ch) {
        ASSERT_EQ(to_unorm8(p[ch]), c[ch]) << x << "," << y << " channel " << ch;
        differ += c[ch] != efb[static_cast<size_t>(y * w + x)][ch];
      }
      EXPECT_EQ(p[3], efb_img.at(x, y)[3]) << "coverage at " << x << "," << y;
    }
  }
  EXPECT_GT(differ, 0);
}

}  // namespace
}  // namespace lt::gx
