#include "gx/clipper.h"

#include <utility>

// Dolphin citations are to Source/Core/VideoBackends/Software/Clipper.cpp and
// NativeVertexFormat.h of the software renderer, by function (see docs/spec/gx-hardware.md §0
// for the versions read); every rule below was also checked against Debian's Dolphin
// (5.0-17995) by the DolphinRaster tests (tests/dolphin_raster_test.cpp).

namespace lt::gx {

namespace {

// [DSW CLIP_POS_X_BIT .. CLIP_NEG_Z_BIT], in the order ClipTriangle clips.
enum ClipPlane : int {
  kPosX = 0x01,
  kNegX = 0x02,
  kPosY = 0x04,
  kNegY = 0x08,
  kPosZ = 0x10,
  kNegZ = 0x20,
};

// [DSW CalcClipMask]. GX clips z to [-w, 0]; the "positive z" test is w * z > 0 (beyond the far
// plane, or behind the eye with z < 0), as Dolphin writes it.
int clip_mask(const glm::vec4& p) {
  int mask = 0;
  if (p.w - p.x < 0) mask |= kPosX;
  if (p.x + p.w < 0) mask |= kNegX;
  if (p.w - p.y < 0) mask |= kPosY;
  if (p.y + p.w < 0) mask |= kNegY;
  if (p.w * p.z > 0) mask |= kPosZ;
  if (p.z + p.w < 0) mask |= kNegZ;
  return mask;
}

// The signed test of a clip plane (a, b, c, d) [DSW CLIP_DOTPROD]: x*a + y*b + z*c + w*d, each
// product and sum its own float operation (0 * inf is NaN there too).
struct PlaneCoefficients {
  int bit;
  float a, b, c, d;
};
// [DSW ClipTriangle: the six POLY_CLIP lines]. The "positive z" plane is (0, 0, 0, 1): the
// triangle is cut where w < 0 (behind the eye), not at the far plane, which the rasteriser's
// clamp of z to 2^24 - 1 stands in for.
constexpr PlaneCoefficients kPlanes[6] = {
    {kPosX, -1, 0, 0, 1}, {kNegX, 1, 0, 0, 1}, {kPosY, 0, -1, 0, 1},
    {kNegY, 0, 1, 0, 1},  {kPosZ, 0, 0, 0, 1}, {kNegZ, 0, 0, 1, 1},
};

float plane_distance(const PlaneCoefficients& p, const glm::vec4& v) {
  return v.x * p.a + v.y * p.b + v.z * p.c + v.w * p.d;
}

// [DSW DIFFERENT_SIGNS]: one of the two at most 0, the other above.
bool different_signs(float x, float y) {
  return (x <= 0 && y > 0) || (x > 0 && y <= 0);
}

// The vertex at t from `a` (outside) toward `b` [DSW OutputVertexData::Lerp]: positions and
// texture coordinates a + (b - a) * t in float; colours in 8-bit steps, a + (((b - a) * t8) >> 8)
// with t8 = (u16)(t * 256) and an arithmetic shift (the floor of a negative step).
RasterVertex lerp(float t, const RasterVertex& a, const RasterVertex& b) {
  RasterVertex r;
  for (int i = 0; i < 4; ++i) r.clip[i] = a.clip[i] + ((b.clip[i] - a.clip[i]) * t);
  const int t8 = static_cast<u16>(t * 256);
  for (size_t c = 0; c < kMaxChannels; ++c)
    for (int i = 0; i < 4; ++i)
      r.color[c][i] =
          static_cast<u8>(a.color[c][i] + (((b.color[c][i] - a.color[c][i]) * t8) >> 8));
  for (size_t g = 0; g < kMaxTexGens; ++g)
    for (int i = 0; i < 3; ++i) r.tex[g][i] = a.tex[g][i] + ((b.tex[g][i] - a.tex[g][i]) * t);
  return r;
}

// [DSW PerspectiveDivide]: x * (1 / w) * wd + x_orig, left to right; the 342-pixel offset stays
// in (the rasteriser takes it off with the scissor offset).
void perspective_divide(RasterVertex& v, const Viewport& vp) {
  const float inv_w = 1.0f / v.clip.w;
  v.screen.x = v.clip.x * inv_w * vp.wd + vp.x_orig;
  v.screen.y = v.clip.y * inv_w * vp.ht + vp.y_orig;
  v.screen.z = v.clip.z * inv_w * vp.z_range + vp.far_z;
}

// [DSW IsBackface]: the sign of the clip-space winding, terms in Dolphin's order. A positive
// viewport height flips it (Dolphin's fix for a game that sets one); ltrender's viewport is
// always negative (y down), so that branch is never taken here.
bool is_backface(const glm::vec4& p0, const glm::vec4& p1, const glm::vec4& p2,
                 const Viewport& vp) {
  const float normal_z = (p0.x * p2.w - p2.x * p0.w) * p1.y + (p2.x * p0.y - p0.x * p2.y) * p1.w +
                         (p2.y * p0.w - p0.y * p2.w) * p1.x;
  bool backface = normal_z <= 0.0f;
  if (vp.ht > 0) backface = !backface;
  return backface;
}

}  // namespace

u8 hardware_cull_mode(u8 gx_cull_mode) {
  static constexpr u8 kCullToHardware[4] = {0, 2, 1, 3};
  return kCullToHardware[gx_cull_mode & 3];
}

TriangleFate clip_triangle(const RasterVertex& v0, const RasterVertex& v1, const RasterVertex& v2,
                           u8 gx_cull_mode, const Viewport& viewport, ClippedTriangles& out) {
  out.count = 0;
  // [DSW IsTriviallyRejected]: every vertex outside one and the same plane.
  if (clip_mask(v0.clip) & clip_mask(v1.clip) & clip_mask(v2.clip)) return TriangleFate::Rejected;
  // [DSW ProcessTriangle]: hardware mode 1 (Back) culls the triangles that are not back faces,
  // mode 2 (Front) the back faces, 3 both; a back face is then drawn with v1 and v2 swapped.
  const bool backface = is_backface(v0.clip, v1.clip, v2.clip, viewport);
  const u8 hw = hardware_cull_mode(gx_cull_mode);
  if (!backface && (hw == 1 || hw == 3)) return TriangleFate::Culled;
  if (backface && (hw == 2 || hw == 3)) return TriangleFate::Culled;
  auto& vs = out.vertices;
  vs[0] = v0;
  vs[1] = backface ? v2 : v1;
  vs[2] = backface ? v1 : v2;

  // [DSW ClipTriangle]: Sutherland-Hodgman against each plane any vertex is outside of, new
  // vertices appended after the three; a plane that leaves fewer than 3 corners ends the
  // clipping with nothing drawn.
  constexpr int kCapacity = static_cast<int>(std::tuple_size_v<decltype(out.vertices)>);
  std::array<int, kCapacity + 1> list_a{0, 1, 2}, list_b{};
  int* in = list_a.data();
  int* next = list_b.data();
  int n = 3, vertices = 3;
  const int mask = clip_mask(vs[0].clip) | clip_mask(vs[1].clip) | clip_mask(vs[2].clip);
  for (const PlaneCoefficients& plane : kPlanes) {
    if (!(mask & plane.bit)) continue;
    int prev = in[0];
    float d_prev = plane_distance(plane, vs[static_cast<size_t>(prev)].clip);
    int kept = 0;
    in[n] = in[0];
    for (int j = 1; j <= n; ++j) {
      const int cur = in[j];
      const float d = plane_distance(plane, vs[static_cast<size_t>(cur)].clip);
      if (d_prev >= 0) {
        if (kept == kCapacity) return TriangleFate::ClippedAway;
        next[kept++] = prev;
      }
      if (different_signs(d, d_prev)) {
        // A convex polygon crosses a plane twice; float noise on a sliver could make it cross
        // more often than Dolphin's arrays hold (there it would overrun them): drawn as nothing.
        if (vertices == kCapacity || kept == kCapacity) return TriangleFate::ClippedAway;
        // Always from the vertex outside toward the one inside [DSW POLY_CLIP].
        if (d < 0) {
          vs[static_cast<size_t>(vertices)] =
              lerp(d / (d - d_prev), vs[static_cast<size_t>(cur)], vs[static_cast<size_t>(prev)]);
        } else {
          vs[static_cast<size_t>(vertices)] = lerp(
              d_prev / (d_prev - d), vs[static_cast<size_t>(prev)], vs[static_cast<size_t>(cur)]);
        }
        next[kept++] = vertices++;
      }
      prev = cur;
      d_prev = d;
    }
    if (kept < 3) return TriangleFate::ClippedAway;
    std::swap(in, next);
    n = kept;
  }
  // The polygon as a fan from its first corner [DSW ClipTriangle "transform the poly in inlist
  // into triangles"], each corner divided once.
  for (int j = 0; j < n; ++j) perspective_divide(vs[static_cast<size_t>(in[j])], viewport);
  for (int j = 2; j < n; ++j)
    out.triangles[static_cast<size_t>(out.count++)] = {
        static_cast<u8>(in[0]), static_cast<u8>(in[j - 1]), static_cast<u8>(in[j])};
  return TriangleFate::Drawn;
}

}  // namespace lt::gx
