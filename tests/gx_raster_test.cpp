// The gx path's setup unit, rasteriser and EFB against hand-computed cases: coverage at pixel
// centres, the fill rule on shared and outer edges, slivers, the clipper's cull and clip, depth
// order, early z and the conversions of Dolphin's software renderer. Every expectation below is
// worked out in the comment beside it from the rules of rasteriser.h (Dolphin's
// DrawTriangleFrontFace), not read off the code's output. The same rules against Dolphin itself:
// tests/dolphin_raster_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "paths/gx/clipper.h"
#include "paths/gx/pixel_stage.h"
#include "paths/gx/rasteriser.h"

namespace lt::gx {
namespace {

using Pixel = std::pair<int, int>;  // (x, y)

// A vertex whose screen position snaps to the 1/16-pixel integer (X, Y): screen = 342 +
// (X + 9) / 16, exact in float, so snap_to_subpixels gives X back. Sample point of pixel (x, y)
// is (16 x, 16 y) in these units.
RasterVertex snapped(int X, int Y, float z = 0.0f, Color8 color = {}) {
  RasterVertex v;
  v.screen = {342.0f + static_cast<float>(X + 9) / 16.0f,
              342.0f + static_cast<float>(Y + 9) / 16.0f, z};
  v.clip = {0, 0, 0, 1};
  v.color = {color, color};
  return v;
}

const Scissor kScissor{0, 0, 32, 32, 342, 342};

std::set<Pixel> covered(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c) {
  std::set<Pixel> out;
  Triangle t;
  if (!setup_triangle(a, b, c, 1, 0, kScissor, t)) return out;
  for (int y = 0; y < 32; ++y) {
    s32 xb, xe;
    covered_span(t, y, xb, xe);
    for (s32 x = xb; x < xe; ++x) out.insert({x, y});
  }
  return out;
}

// Every pixel whose sample point passes the three half-space tests, by brute force over the
// bounding box: the per-pixel form of the test, to hold covered_span's solved spans to.
std::set<Pixel> covered_by_brute_force(const Triangle& t) {
  std::set<Pixel> out;
  for (int y = t.min_y; y < t.max_y; ++y)
    for (int x = t.min_x; x < t.max_x; ++x) {
      bool in = true;
      for (size_t e = 0; e < 3; ++e)
        in = in && t.c[e] + t.dx[e] * (int64_t{y} * 16) - t.dy[e] * (int64_t{x} * 16) > 0;
      if (in) out.insert({x, y});
    }
  return out;
}

TEST(GxRaster, SnappingRoundsAsDolphinsIround) {
  // 16 * (screen - 342) = 2.5 -> (int) 2, fraction 0.5 >= 0.5 -> 3, minus 9 = -6. -2.5 and
  // -2.75 -> (int) -2, fractions -0.5 and -0.75 are not >= 0.5 -> -2 -> -11: a negative value
  // never rounds down (round-to-nearest would give -3 for -2.75, so -12).
  EXPECT_EQ(snap_to_subpixels(342.0f + 2.5f / 16, 342), -6);
  EXPECT_EQ(snap_to_subpixels(342.0f - 2.5f / 16, 342), -11);
  EXPECT_EQ(snap_to_subpixels(342.0f - 2.75f / 16, 342), -11);
  EXPECT_EQ(snap_to_subpixels(342.0f + 2.75f / 16, 342), -6);
  EXPECT_EQ(snap_to_subpixels(342.0f + 2.25f / 16, 342), -7);
  // A vertex at pixel centre (x + 9/16) snaps onto the sample point 16 x.
  EXPECT_EQ(snap_to_subpixels(342.0f + 5.5625f, 342), 80);
}

TEST(GxRaster, RightTriangleCoversTheSamplePointsInsideIt) {
  // Corners at screen (0, 0), (0, 4), (4, 0) pixels: snapped (-9, -9), (-9, 55), (55, -9). Pixel
  // (x, y) samples (x + 9/16, y + 9/16): inside while x + y + 1.125 < 4, so x + y <= 2 with
  // x, y >= 0 - six pixels. (This winding is the one the rasteriser draws: counter-clockwise on
  // the screen, y down.)
  const std::set<Pixel> expected{{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {0, 2}};
  EXPECT_EQ(covered(snapped(-9, -9), snapped(-9, 55), snapped(55, -9)), expected);
  // The other winding has every half-space function negative inside: nothing (the clipper swaps
  // a back face's vertices before it gets here).
  EXPECT_TRUE(covered(snapped(-9, -9), snapped(55, -9), snapped(-9, 55)).empty());
}

TEST(GxRaster, QuadOnPixelCentresCoversItsTopLeftPixelsEachOnce) {
  // A square with corners on the sample points of pixels (0, 0) and (4, 4), split along its
  // diagonal. Edges through sample points: the left edge (DY < 0) and the top edge (DY == 0,
  // DX > 0) get the fill convention's +1 and keep their pixels; the right and bottom edges do
  // not. The diagonal's pixels (i, i) go to exactly one of the two triangles. So pixels
  // [0, 4) x [0, 4): 16 pixels, none twice, none on column 4 or row 4.
  const RasterVertex a = snapped(0, 0), b = snapped(0, 64), c = snapped(64, 64), d = snapped(64, 0);
  const std::set<Pixel> lower = covered(a, b, c);  // (0,0) (0,4) (4,4): left and bottom edges
  const std::set<Pixel> upper = covered(a, c, d);  // (0,0) (4,4) (4,0): top and right edges
  std::set<Pixel> all;
  for (const Pixel& p : lower) EXPECT_EQ(upper.count(p), 0u) << p.first << "," << p.second;
  all.insert(lower.begin(), lower.end());
  all.insert(upper.begin(), upper.end());
  std::set<Pixel> expected;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) expected.insert({x, y});
  EXPECT_EQ(all, expected);
  EXPECT_EQ(lower.size() + upper.size(), 16u);
  // The diagonal pixels belong to the lower triangle: for edge (4,4)->(0,0) of the lower one,
  // DY = 64 > 0 gets no +1 and is 0 there; for the upper one's (0,0)->(4,4), DY = -64 < 0 gets
  // the +1. So (i, i) is the upper triangle's.
  for (int i = 0; i < 4; ++i) EXPECT_EQ(upper.count({i, i}), 1u) << i;
  // A vertex exactly on a pixel centre: (0, 0) is covered (two inclusive edges meet there),
  // (4, 4) and (4, 0) and (0, 4) are not.
  EXPECT_EQ(all.count({0, 0}), 1u);
  EXPECT_EQ(all.count({4, 4}), 0u);
}

TEST(GxRaster, SliverOneSixteenthWideCoversTheColumnItsLeftEdgeHolds) {
  // (32, 0), (32, 128), (33, 0): a sliver 1/16 pixel wide whose left edge runs through the
  // sample points of column 2. Left edge inclusive (+1); the long edge e = 128 - y is > 0 for
  // y < 128, so rows 0..7; the top edge (DY == 0, DX > 0) is inclusive: row 0 too. 8 pixels.
  std::set<Pixel> expected;
  for (int y = 0; y < 8; ++y) expected.insert({2, y});
  EXPECT_EQ(covered(snapped(32, 0), snapped(32, 128), snapped(33, 0)), expected);
  // Moved 1/16 to the right it holds no sample point: nothing.
  EXPECT_TRUE(covered(snapped(33, 0), snapped(33, 128), snapped(34, 0)).empty());
  // A zero-area triangle (three collinear points) covers nothing: the three functions sum to
  // twice the area (0) plus at most two +1s, so they cannot all be positive.
  EXPECT_TRUE(covered(snapped(0, 0), snapped(32, 32), snapped(64, 64)).empty());
  EXPECT_TRUE(covered(snapped(16, 16), snapped(16, 16), snapped(16, 16)).empty());
}

TEST(GxRaster, SolvedSpansEqualThePerPixelTest) {
  // covered_span solves the half-space tests per row; the brute-force test per pixel must give
  // the same pixels for triangles of every orientation, including edges through sample points.
  const int pts[][6] = {{-9, -9, -9, 55, 55, -9},     {0, 0, 0, 64, 64, 64},
                        {5, 3, 17, 200, 300, 41},     {250, 10, 13, 77, 170, 330},
                        {100, 0, 0, 100, 200, 100},   {32, 0, 32, 128, 33, 0},
                        {480, 480, -40, 300, 511, 2}, {7, 7, 8, 500, 9, 7}};
  for (const auto& p : pts) {
    Triangle t;
    const RasterVertex a = snapped(p[0], p[1]), b = snapped(p[2], p[3]), c = snapped(p[4], p[5]);
    for (int order = 0; order < 2; ++order) {
      const bool ok = order == 0 ? setup_triangle(a, b, c, 0, 0, kScissor, t)
                                 : setup_triangle(a, c, b, 0, 0, kScissor, t);
      if (!ok) continue;
      std::set<Pixel> spans;
      for (int y = t.min_y; y < t.max_y; ++y) {
        s32 xb, xe;
        covered_span(t, y, xb, xe);
        for (s32 x = xb; x < xe; ++x) spans.insert({x, y});
      }
      EXPECT_EQ(spans, covered_by_brute_force(t)) << p[0] << " " << p[1] << " order " << order;
    }
  }
}

TEST(GxRaster, ScissorClipsTheBoundingBox) {
  // A triangle far larger than the 32 x 32 scissor covers exactly the scissored pixels it
  // contains: corners (-160, -160), (-160, 1600), (1600, -160) cover x + y + 1.125 < 110.
  const std::set<Pixel> px = covered(snapped(-169, -169), snapped(-169, 1751), snapped(1751, -169));
  EXPECT_EQ(px.size(), 32u * 32u);
  EXPECT_EQ(px.count({31, 31}), 1u);
}

TEST(GxRaster, ConversionsAreDolphinsX86Casts) {
  // Colours: (u16)(s32) value, masked by ~(c >> 8), into a u8.
  EXPECT_EQ(raster_color(0.0f), 0);
  EXPECT_EQ(raster_color(254.999f), 254);
  EXPECT_EQ(raster_color(255.9f), 255);
  EXPECT_EQ(raster_color(256.0f), 0);  // 0x100 & ~0x1 = 0x100 -> low byte 0
  EXPECT_EQ(raster_color(258.7f), 2);  // 0x102 & 0xfffe = 0x102 -> 2
  EXPECT_EQ(raster_color(-0.9f), 0);   // (int) -0.9 = 0
  EXPECT_EQ(raster_color(-3.0f), 0);   // 0xfffd & ~0xff = 0xff00 -> 0
  EXPECT_EQ(raster_color(std::numeric_limits<float>::quiet_NaN()), 0);  // INT_MIN -> 0
  // Depth: clamped to [0, 2^24 - 1] in float, then truncated; NaN passes the clamp: INT_MIN.
  EXPECT_EQ(raster_depth(-5.0f), 0u);
  EXPECT_EQ(raster_depth(1234.75f), 1234u);
  EXPECT_EQ(raster_depth(2e7f), 16777215u);
  EXPECT_EQ(raster_depth(std::numeric_limits<float>::quiet_NaN()), 0x80000000u);
  EXPECT_EQ(x86_float_to_int(2147483648.0f), INT32_MIN);
  EXPECT_EQ(x86_float_to_int(-2147483648.0f), INT32_MIN);
  EXPECT_EQ(x86_float_to_int(-7.9f), -7);
}

TEST(GxRaster, AttributesAreEvaluatedFromVertexZerosPixelPlusTheOffset) {
  // Colour 0 along x from 0 to 64 over 64 sample units (4 pixels): dfdx = 16 a pixel. Vertex 0
  // at snapped (0, 0) is screen 9/16 into pixel 0; its pixel is (0 + 15) >> 4 = 0, and the
  // planes are measured from x_off = (0 - 9/16) + 0.495 = -0.0675. Pixel x: 16 * (x - 0.0675)
  // = 16 x - 1.08, so pixel 2 gets 30.92 -> 30 and pixel 0 gets -1.08 -> 0 (negative clamps).
  Triangle t;
  const RasterVertex a = snapped(0, 0, 0, {0, 0, 0, 0}), b = snapped(0, 64, 0, {0, 0, 0, 0}),
                     c = snapped(64, 0, 0, {64, 0, 0, 0});
  ASSERT_TRUE(setup_triangle(a, b, c, 1, 0, kScissor, t));
  RasterPixel px;
  raster_pixel(t, 2, 0, false, px);
  EXPECT_EQ(px.color[0].r, 30);
  raster_pixel(t, 0, 0, false, px);
  EXPECT_EQ(px.color[0].r, 0);
  raster_pixel(t, 1, 1, false, px);  // 16 * 0.9325 = 14.92 -> 14 (y does not change it)
  EXPECT_EQ(px.color[0].r, 14);
  raster_pixel(t, 1, 1, true, px);  // the shader backends' rounding: 15
  EXPECT_EQ(px.color[0].r, 15);
}

// ---- the clipper ----

// A vertex in clip space with w = 1 for a 32 x 32 viewport: screen x = 16 x + 358, y = -16 y
// + 358 (GX_SetViewport(0, 0, 32, 32, 0, 1)).
RasterVertex clip_vertex(float x, float y, float z = -0.5f, float w = 1.0f) {
  RasterVertex v;
  v.clip = {x, y, z, w};
  return v;
}
const Viewport kViewport{16.0f, -16.0f, 16777215.0f, 358.0f, 358.0f, 16777215.0f};

TEST(GxClipper, CullModesRemoveTheFacesLibogcNames) {
  // (-0.5,-0.5) (0.5,-0.5) (0,0.5) is counter-clockwise with y up: the clip-space winding
  // (x0 w2 - x2 w0) y1 + (x2 y0 - x0 y2) w1 + (y2 w0 - y0 w2) x1 = (-0.5)(-0.5) + (0.25) + (1)(0.5)
  // = 1 > 0: not a back face for Dolphin. libogc's GX_CULL_BACK is hardware mode 1, which culls
  // exactly these (a mesh wound for GL shows its inside under GX_Init's mode).
  const RasterVertex a = clip_vertex(-0.5f, -0.5f), b = clip_vertex(0.5f, -0.5f),
                     c = clip_vertex(0.0f, 0.5f);
  ClippedTriangles out;
  EXPECT_EQ(clip_triangle(a, b, c, kCullBack, kViewport, out), TriangleFate::Culled);
  EXPECT_EQ(clip_triangle(a, b, c, kCullAll, kViewport, out), TriangleFate::Culled);
  EXPECT_EQ(clip_triangle(a, b, c, kCullFront, kViewport, out), TriangleFate::Drawn);
  EXPECT_EQ(clip_triangle(a, c, b, kCullFront, kViewport, out), TriangleFate::Culled);
  ASSERT_EQ(clip_triangle(a, c, b, kCullBack, kViewport, out), TriangleFate::Drawn);
  // A back face is drawn with its last two vertices swapped: (a, b, c) again.
  ASSERT_EQ(out.count, 1);
  EXPECT_EQ(out.vertices[out.triangles[0][1]].clip, b.clip);
  EXPECT_EQ(out.vertices[out.triangles[0][2]].clip, c.clip);
  // Screen positions: 16 x + 358 and -16 y + 358.
  EXPECT_EQ(out.vertices[out.triangles[0][0]].screen.x, 350.0f);
  EXPECT_EQ(out.vertices[out.triangles[0][0]].screen.y, 366.0f);
}

TEST(GxClipper, TrianglesOutsideOnePlaneAreRejectedAndCrossingOnesClipped) {
  ClippedTriangles out;
  // All three right of x = w: rejected before culling.
  EXPECT_EQ(clip_triangle(clip_vertex(1.5f, 0), clip_vertex(2, 0), clip_vertex(1.5f, 1), kCullNone,
                          kViewport, out),
            TriangleFate::Rejected);
  // All in front of the near plane (z < -w): rejected.
  EXPECT_EQ(clip_triangle(clip_vertex(0, 0, -2), clip_vertex(0.5f, 0, -2), clip_vertex(0, 0.5f, -2),
                          kCullNone, kViewport, out),
            TriangleFate::Rejected);
  // Crossing x = w: (0, 0) (2, 0) (0, 1) cut at x = 1 into a quad (0,0) (1,0) (1,0.5) (0,1):
  // two triangles. The new vertex on edge (0,0)-(2,0) is lerped from the outside vertex (2, 0)
  // toward (0, 0) by t = d / (d - d_prev) with d = w - x = -1 outside, 1 inside: t = 0.5 -> x = 1.
  ASSERT_EQ(clip_triangle(clip_vertex(0, 0), clip_vertex(0, 1), clip_vertex(2, 0), kCullNone,
                          kViewport, out),
            TriangleFate::Drawn);
  EXPECT_EQ(out.count, 2);
  float max_x = -1;
  for (int k = 0; k < out.count; ++k)
    for (u8 i : out.triangles[static_cast<size_t>(k)])
      max_x = std::max(max_x, out.vertices[i].clip.x);
  EXPECT_EQ(max_x, 1.0f);
  // Colours lerp in 8-bit steps: from 200 outside to 100 inside at t = 0.5: t8 = 128,
  // 200 + ((-100 * 128) >> 8) = 200 - 50 = 150.
  RasterVertex o = clip_vertex(2, 0), i1 = clip_vertex(0, 0), i2 = clip_vertex(0, 1);
  o.color[0] = {200, 0, 0, 0};
  i1.color[0] = {100, 0, 0, 0};
  i2.color[0] = {100, 0, 0, 0};
  ASSERT_EQ(clip_triangle(i1, i2, o, kCullNone, kViewport, out), TriangleFate::Drawn);
  bool found = false;
  for (const RasterVertex& v : out.vertices)
    if (v.clip.x == 1.0f && v.clip.y == 0.0f) found = found || v.color[0].r == 150;
  EXPECT_TRUE(found);
}

// Bad geometry keeps the contract: a NaN, infinite or huge vertex, a triangle behind the eye,
// one with no area: nothing is drawn and nothing crashes (Dolphin's s32 edge arithmetic would
// overflow past kMaxSnapped, rasteriser.cpp; a NaN position snaps to INT_MIN there).
TEST(GxClipper, NonFiniteHugeAndDegenerateTrianglesDrawNothing) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const RasterVertex a = clip_vertex(-0.5f, -0.5f), b = clip_vertex(0.5f, -0.5f),
                     c = clip_vertex(0.0f, 0.5f);
  for (const RasterVertex& bad :
       {clip_vertex(nan, 0.5f), clip_vertex(0.0f, 0.5f, nan), clip_vertex(0.0f, 0.5f, -0.5f, nan),
        clip_vertex(inf, 0.5f), clip_vertex(0.0f, -inf)}) {
    ClippedTriangles out;
    const TriangleFate fate = clip_triangle(a, b, bad, kCullNone, kViewport, out);
    // Whatever the clipper decides, no triangle it hands on sets up with a non-finite or
    // out-of-range position: every such one is refused by setup_triangle.
    if (fate != TriangleFate::Drawn) continue;
    for (int k = 0; k < out.count; ++k) {
      const auto& tri = out.triangles[static_cast<size_t>(k)];
      Triangle t;
      const RasterVertex& v0 = out.vertices[tri[0]];
      const RasterVertex& v1 = out.vertices[tri[1]];
      const RasterVertex& v2 = out.vertices[tri[2]];
      const bool finite = std::isfinite(v0.screen.x) && std::isfinite(v0.screen.y) &&
                          std::isfinite(v1.screen.x) && std::isfinite(v1.screen.y) &&
                          std::isfinite(v2.screen.x) && std::isfinite(v2.screen.y);
      if (!finite) {
        EXPECT_FALSE(setup_triangle(v0, v1, v2, 1, 0, kScissor, t));
      }
    }
  }
  // Behind the eye: w = -1 and z + w < 0 at all three, outside the near plane: rejected.
  ClippedTriangles out;
  EXPECT_EQ(
      clip_triangle(clip_vertex(-0.5f, -0.5f, 0.5f, -1.0f), clip_vertex(0.5f, -0.5f, 0.5f, -1.0f),
                    clip_vertex(0, 0.5f, 0.5f, -1.0f), kCullNone, kViewport, out),
      TriangleFate::Rejected);
  // Screen positions past what Dolphin's integers hold, and NaN ones, set up nothing.
  Triangle t;
  RasterVertex huge = snapped(0, 0);
  huge.screen.x = 1e30f;
  EXPECT_FALSE(setup_triangle(snapped(0, 0), snapped(64, 0), huge, 1, 0, kScissor, t));
  RasterVertex not_a_number = snapped(0, 0);
  not_a_number.screen.y = nan;
  EXPECT_FALSE(setup_triangle(snapped(0, 0), snapped(64, 0), not_a_number, 1, 0, kScissor, t));
  // Three points on a line cover no pixel: every sample point fails one edge test.
  EXPECT_TRUE(covered(snapped(0, 0), snapped(64, 64), snapped(128, 128)).empty());
}

// ---- depth and the EFB ----

// A program whose TEV writes the rasterised colour 0 (RASC, RASA): no texture, one channel.
GxState flat_colour_state() {
  GxState st;
  st.lighting.num_channels = 1;
  st.texgen.num_texgens = 0;
  st.tev.num_stages = 1;
  TevStage& s0 = st.tev.stages[0];
  s0.texmap = kTexMapNull;
  s0.texcoord = kTexCoordNull;
  s0.channel = 4;                                            // GX_COLOR0A0
  s0.color = TevCombiner{15, 15, 15, 10, 0, 0, 0, true, 0};  // d = RASC
  s0.alpha = TevCombiner{7, 7, 7, 5, 0, 0, 0, true, 0};      // d = RASA
  st.cull_mode = kCullNone;
  return st;
}

// Draws a 4 x 4-pixel square of colour `c` at constant screen depth `z` under `state`.
void draw_square(const GxState& state, float z, Color8 c, Efb& efb) {
  const RasterVertex a = snapped(0, 0, z, c), b = snapped(0, 64, z, c), d = snapped(64, 64, z, c),
                     e = snapped(64, 0, z, c);
  std::vector<Triangle> tris(2);
  ASSERT_TRUE(setup_triangle(a, b, d, 1, 0, kScissor, tris[0]));
  ASSERT_TRUE(setup_triangle(a, d, e, 1, 0, kScissor, tris[1]));
  PixelProgram p;
  p.state = &state;
  draw_triangles(tris, p, false, efb);
}

TEST(GxEfb, DepthOrderFollowsTheCompareAndTheDrawOrder) {
  const Color8 red{200, 0, 0, 255}, green{0, 200, 0, 255}, grey{64, 64, 64, 255};
  GxState st = flat_colour_state();
  Efb efb;
  // GX_Init's LEQUAL: an equal depth drawn second wins.
  efb.clear(32, 32, grey, 0xffffff);
  draw_square(st, 1000.0f, red, efb);
  draw_square(st, 1000.0f, green, efb);
  EXPECT_EQ(efb.color[0], green);
  EXPECT_EQ(efb.depth[0], 1000u);
  EXPECT_EQ(efb.color[4], grey);  // pixel (4, 0): outside the square (right edge exclusive)
  EXPECT_EQ(efb.covered[4], 0);
  // LESS: the first stays.
  st.z.func = 1;
  efb.clear(32, 32, grey, 0xffffff);
  draw_square(st, 1000.0f, red, efb);
  draw_square(st, 1000.0f, green, efb);
  EXPECT_EQ(efb.color[0], red);
  // LEQUAL, the second farther: the first stays; with update off the depth stays the clear's.
  st.z.func = 3;
  efb.clear(32, 32, grey, 0xffffff);
  draw_square(st, 1000.0f, red, efb);
  draw_square(st, 2000.0f, green, efb);
  EXPECT_EQ(efb.color[0], red);
  st.z.update = false;
  efb.clear(32, 32, grey, 0xffffff);
  draw_square(st, 1000.0f, red, efb);
  EXPECT_EQ(efb.depth[0], 0xffffffu);
  // Z beyond the 24-bit range clamps to 2^24 - 1, which LEQUAL passes against the clear.
  st.z.update = true;
  efb.clear(32, 32, grey, 0xffffff);
  draw_square(st, 3e7f, red, efb);
  EXPECT_EQ(efb.color[0], red);
  EXPECT_EQ(efb.depth[0], 16777215u);
  // With the test off nothing is compared and nothing written, whatever the update bit says.
  st.z.enable = false;
  efb.clear(32, 32, grey, 500);
  draw_square(st, 1000.0f, red, efb);
  EXPECT_EQ(efb.color[0], red);
  EXPECT_EQ(efb.depth[0], 500u);
}

TEST(GxEfb, EarlyDepthWritesDepthForPixelsTheAlphaTestDiscards) {
  // GX_Init's GX_SetZCompLoc(GX_TRUE): depth is tested and written before the TEV, so a pixel
  // the alpha test discards still leaves its depth, and a farther square behind it fails.
  const Color8 red{200, 0, 0, 255}, green{0, 200, 0, 255}, grey{64, 64, 64, 255};
  GxState discard = flat_colour_state();
  discard.alpha_compare = AlphaCompare{0, 0, 0, 0, 0};  // NEVER and NEVER
  const GxState keep = flat_colour_state();
  Efb efb;
  efb.clear(32, 32, grey, 0xffffff);
  draw_square(discard, 500.0f, red, efb);
  EXPECT_EQ(efb.color[0], grey);
  EXPECT_EQ(efb.depth[0], 500u);
  EXPECT_EQ(efb.covered[0], 1);
  draw_square(keep, 1000.0f, green, efb);
  EXPECT_EQ(efb.color[0], grey);
}

}  // namespace
}  // namespace lt::gx
