#include "gx/rasteriser.h"

// Dolphin citations are to Source/Core/VideoBackends/Software/Rasterizer.cpp of the software
// renderer, by function (docs/spec/gx-hardware.md §0 names the versions read; the scissor-era
// versions read agree on every rule used here). tests/dolphin_raster_test.cpp holds the rules
// against Debian's Dolphin.

namespace lt::gx {

namespace {

// [DSW iround]: "int t = (int)x; if ((x - t) >= 0.5) return t + 1; return t;" - truncation, then
// up when the fraction is at least a half, so negative values round toward zero or up.
s32 dolphin_iround(float x) {
  const s32 t = x86_float_to_int(x);
  if ((x - static_cast<float>(t)) >= 0.5) return t + 1;
  return t;
}

// [DSW Slope::Slope]: the plane through (f0, f1, f2) at the three vertices, from the context's
// vertex deltas, in Dolphin's order of operations.
struct SlopeContext {
  float dx10, dx20, dy10, dy20;
};

Slope make_slope(float f0, float f1, float f2, const SlopeContext& ctx) {
  const float delta_20 = f2 - f0;
  const float delta_10 = f1 - f0;
  const float a = delta_20 * ctx.dy10 - delta_10 * ctx.dy20;
  const float b = ctx.dx20 * delta_10 - ctx.dx10 * delta_20;
  const float c = ctx.dx20 * ctx.dy10 - ctx.dx10 * ctx.dy20;
  return {f0, a / c, b / c};
}

// floor(a / b) for b > 0.
int64_t floor_div(int64_t a, int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

// Snapped screen coordinates (1/16 pixel, from the scissor origin) up to this keep Dolphin's s32
// edge arithmetic exact: |C| <= 4 M^2 and an edge test adds at most 2^16 M, 1.4e9 < 2^31 for
// M = 12000 (750 pixels: the EFB is 640 x 528, and the clipper keeps vertices on the viewport).
// Beyond it Dolphin's integers overflow; such a triangle (only a NaN or infinite position gets
// there) is not drawn. The console's rule refuses the same triangles: its 750 pixels are
// M = 2.9e8 units, |C| <= 4 M^2 = 3.5e17 and C plus a row's term 6 M^2 < 2^63.
constexpr float kMaxSnapped = 12000.0f;

// ceil(a / b) for b > 0.
int64_t ceil_div(int64_t a, int64_t b) {
  return floor_div(a + b - 1, b);
}

// The shader backends' rounding of an interpolated colour (gx-hardware.md §2.5), clamped to
// 0..255; NaN as 0.
u8 rounded_color(float v) {
  if (!(v == v)) return 0;
  return static_cast<u8>(std::clamp(std::floor(v + 0.5f), 0.0f, 255.0f));
}

}  // namespace

s32 snap_to_subpixels(float screen, int offset) {
  return dolphin_iround(16.0f * (screen - static_cast<float>(offset))) - 9;
}

int64_t console_subpixels(float screen, int offset) {
  // Exact in double for |screen| >= 256 (console_subpixels' comment in rasteriser.h): the
  // difference has at most 34 significant bits and 12 * 2^15 adds two.
  const double units = (static_cast<double>(screen) - offset) * kConsoleUnitsPerPixel;
  return std::llround(units) - kConsoleSampleOffset;
}

bool setup_triangle(const RasterVertex& v0, const RasterVertex& v1, const RasterVertex& v2,
                    int channels, int texgens, const Scissor& scissor, Triangle& t,
                    CoverageRule rule) {
  const float x_off = static_cast<float>(scissor.x_off), y_off = static_cast<float>(scissor.y_off);
  const RasterVertex* v[3] = {&v0, &v1, &v2};
  int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) {
    const float sx = 16.0f * (v[i]->screen.x - x_off), sy = 16.0f * (v[i]->screen.y - y_off);
    if (!(std::fabs(sx) < kMaxSnapped && std::fabs(sy) < kMaxSnapped)) return false;
    // "28.4 fixed-point coordinates. rounded to nearest and adjusted to match hardware output"
    // [DSW DrawTriangleFrontFace]: the -9 puts pixel centres at 9/16 of a pixel.
    X[i] = snap_to_subpixels(v[i]->screen.x, scissor.x_off);
    Y[i] = snap_to_subpixels(v[i]->screen.y, scissor.y_off);
  }
  // The planes are measured from vertex 0's pixel on Dolphin's grid under either rule.
  t.origin.x0 = static_cast<s32>((X[0] + 0xF) >> 4);
  t.origin.y0 = static_cast<s32>((Y[0] + 0xF) >> 4);
  const bool console = rule == CoverageRule::Console;
  t.unit = console ? kConsoleUnitsPerPixel : 16;
  if (console) {
    for (int i = 0; i < 3; ++i) {
      X[i] = console_subpixels(v[i]->screen.x, scissor.x_off);
      Y[i] = console_subpixels(v[i]->screen.y, scissor.y_off);
    }
  }
  // Bounding box in pixels: ceil(v / unit), the first sample point at or past v ((v + 15) >> 4,
  // an arithmetic shift, for Dolphin's 16), then the scissor.
  auto pixel = [console](int64_t units) {
    return static_cast<s32>(console ? ceil_div(units, kConsoleUnitsPerPixel) : (units + 0xF) >> 4);
  };
  t.min_x = std::max(pixel(std::min({X[0], X[1], X[2]})), scissor.left);
  t.max_x = std::min(pixel(std::max({X[0], X[1], X[2]})), scissor.right);
  t.min_y = std::max(pixel(std::min({Y[0], Y[1], Y[2]})), scissor.top);
  t.max_y = std::min(pixel(std::max({Y[0], Y[1], Y[2]})), scissor.bottom);
  if (t.min_x >= t.max_x || t.min_y >= t.max_y) return false;

  // Edges 1-2, 2-3, 3-1: e = C + DX * y - DY * x with C = DY * X1 - DX * Y1, plus one where
  // "DY < 0 || (DY == 0 && DX > 0)" [DSW "Correct for fill convention"].
  for (int e = 0; e < 3; ++e) {
    const int a = e, b = (e + 1) % 3;
    const int64_t dx = X[a] - X[b], dy = Y[a] - Y[b];
    int64_t c = dy * X[a] - dx * Y[a];
    if (dy < 0 || (dy == 0 && dx > 0)) ++c;
    t.c[static_cast<size_t>(e)] = c;
    t.dx[static_cast<size_t>(e)] = dx;
    t.dy[static_cast<size_t>(e)] = dy;
  }

  // The planes [DSW SlopeContext]: through vertex 0, measured from its pixel (above).
  // "adjust a little less than 0.5"
  constexpr float kAdjust = 0.495f;
  t.origin.x_off = (static_cast<float>(t.origin.x0) - (v0.screen.x - x_off)) + kAdjust;
  t.origin.y_off = (static_cast<float>(t.origin.y0) - (v0.screen.y - y_off)) + kAdjust;
  const SlopeContext ctx{v1.screen.x - v0.screen.x, v2.screen.x - v0.screen.x,
                         v1.screen.y - v0.screen.y, v2.screen.y - v0.screen.y};
  t.z = make_slope(v0.screen.z, v1.screen.z, v2.screen.z, ctx);
  const float w[3] = {1.0f / v0.clip.w, 1.0f / v1.clip.w, 1.0f / v2.clip.w};
  t.w = make_slope(w[0], w[1], w[2], ctx);
  t.channels = channels;
  t.texgens = texgens;
  for (int c = 0; c < channels; ++c)
    for (int i = 0; i < 4; ++i)
      t.color[static_cast<size_t>(c)][static_cast<size_t>(i)] =
          make_slope(v0.color[static_cast<size_t>(c)][i], v1.color[static_cast<size_t>(c)][i],
                     v2.color[static_cast<size_t>(c)][i], ctx);
  // Texture coordinates are interpolated as s * (1/w) and divided back per pixel.
  for (int g = 0; g < texgens; ++g) {
    const size_t gi = static_cast<size_t>(g);
    for (int i = 0; i < 3; ++i)
      t.tex[gi][static_cast<size_t>(i)] =
          make_slope(v0.tex[gi][i] * w[0], v1.tex[gi][i] * w[1], v2.tex[gi][i] * w[2], ctx);
  }
  return true;
}

void covered_span(const Triangle& t, s32 y, s32& x_begin, s32& x_end) {
  int64_t lo = t.min_x, hi = t.max_x;
  if (y < t.min_y || y >= t.max_y) {
    x_begin = x_end = 0;
    return;
  }
  const int64_t sample_y = int64_t{y} * t.unit;
  for (size_t e = 0; e < 3 && lo < hi; ++e) {
    // e(x) = A - B x with A = c + dx (y unit), B = unit dy; covered where e(x) > 0.
    const int64_t a = t.c[e] + t.dx[e] * sample_y;
    const int64_t b = t.unit * t.dy[e];
    if (b > 0) {
      hi = std::min(hi, ceil_div(a, b));  // x < a / b
    } else if (b < 0) {
      lo = std::max(lo, floor_div(-a, -b) + 1);  // e(x) = a + |b| x > 0: x > -a / |b|
    } else if (a <= 0) {
      hi = lo;
    }
  }
  x_begin = static_cast<s32>(lo);
  x_end = static_cast<s32>(std::max(lo, hi));
}

namespace {

u32 raster_pixel_depth(const Triangle& t, s32 x, s32 y) {
  return raster_depth(slope_value(t.z, t.origin, x, y));
}

void raster_pixel_attributes(const Triangle& t, s32 x, s32 y, bool round_colors, RasterPixel& out) {
  for (int c = 0; c < t.channels; ++c) {
    for (int i = 0; i < 4; ++i) {
      const float v =
          slope_value(t.color[static_cast<size_t>(c)][static_cast<size_t>(i)], t.origin, x, y);
      out.color[static_cast<size_t>(c)][i] = round_colors ? rounded_color(v) : raster_color(v);
    }
  }
  for (int g = 0; g < t.texgens; ++g) {
    const std::array<float, 2> st = raster_texcoord_float(t, g, x, y);
    out.uv[static_cast<size_t>(g)] = {raster_texcoord(st[0]), raster_texcoord(st[1])};
  }
}

}  // namespace

std::array<float, 2> raster_texcoord_float(const Triangle& t, int g, s32 x, s32 y) {
  // [DSW BuildBlock]: "invW = 1.0f / WSlope.GetValue(x, y)"; "q = TexSlopes[i][2] * invW; if (q
  // != 0.0f) projection = invW / q"; s and t times the projection.
  const float inv_w = 1.0f / slope_value(t.w, t.origin, x, y);
  const auto& s = t.tex[static_cast<size_t>(g)];
  float projection = inv_w;
  const float q = slope_value(s[2], t.origin, x, y) * inv_w;
  if (q != 0.0f) projection = inv_w / q;
  return {slope_value(s[0], t.origin, x, y) * projection,
          slope_value(s[1], t.origin, x, y) * projection};
}

QuadTexcoords quad_texcoords(const Triangle& t, int g, s32 x, s32 y) {
  // [DSW DrawTriangleFrontFace]: blocks start at "minx & ~(BLOCK_SIZE - 1)", so every block's
  // corner is even; BuildBlock computes its four pixels' coordinates whether covered or not.
  const s32 bx = x & ~1, by = y & ~1;
  const std::array<float, 2> p00 = raster_texcoord_float(t, g, bx, by);
  const std::array<float, 2> p10 = raster_texcoord_float(t, g, bx + 1, by);
  const std::array<float, 2> p01 = raster_texcoord_float(t, g, bx, by + 1);
  return {p00[0], p00[1], p10[0], p10[1], p01[0], p01[1]};
}

void raster_pixel(const Triangle& t, s32 x, s32 y, bool round_colors, RasterPixel& out) {
  out.z = raster_pixel_depth(t, x, y);
  raster_pixel_attributes(t, x, y, round_colors, out);
}

}  // namespace lt::gx
