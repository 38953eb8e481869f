// XF texgens (gx-hardware.md §3.1), as Dolphin's software renderer computes regular texgens
// [DSW TransformUnit.cpp TransformTexCoordRegular, MultiplyVec3Mat24/34, MultiplyVec2Mat24/34].
#include "gx/xf_texgen.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lt::gx {

namespace {

// libogc's constants [OGC gx.h L365-394]: texgen types and sources.
constexpr u8 kMtx3x4 = 0, kMtx2x4 = 1;
constexpr u8 kSourcePosition = 0, kSourceNormal = 1, kSourceTex0 = 4, kSourceTex7 = 11;
constexpr u8 kIdentityRow = 60;  // GX_IDENTITY [OGC gx.h L235]

// The source row as a 4-vector. POS and NRM have input form ABC1, (x, y, z, 1); TEXn has form
// AB11, (s, t, 1, 1) [OGC gx.c L2658-2730] [DHW XFMemory.h TexMtxInfo]. The normal is the raw
// vertex-stream normal: no normal matrix, not normalised [DSW: source `normal[0]` of the input
// vertex] [DHW VertexShaderGen `coord.xyz = rawnormal.xyz`].
glm::vec4 source_row(u8 source, const TexGenInputs& in) {
  if (source == kSourcePosition) return glm::vec4(in.position, 1.0f);
  if (source == kSourceNormal) return glm::vec4(in.normal, 1.0f);
  // Binormal, tangent, colour and emboss sources are not modelled; the parser refuses them.
  LT_CHECK(source >= kSourceTex0 && source <= kSourceTex7,
           "texgen source must be GX_TG_POS, GX_TG_NRM or GX_TG_TEX0..7");
  const glm::vec2 st = in.texcoords[source - kSourceTex0];
  return glm::vec4(st, 1.0f, 1.0f);
}

// A NaN input component is replaced by 1 before the multiply, as DSW TransformTexCoordRegular
// does ("needed to fix eyelids in Shadow the Hedgehog", Dolphin bug 11458). The constant 1s of
// the input forms are never NaN.
float nan_to_one(float x) {
  return std::isnan(x) ? 1.0f : x;
}

// One matrix row times the source: m0*a + m1*b + m2*c + m3, summed left to right as DSW's
// MultiplyVec3Mat24 does. For form AB11 (c = 1) this is bit-identical to MultiplyVec2Mat24's
// m0*a + m1*b + m2 + m3, since m2 * 1 is exact.
float row_dot(const std::array<float, 4>& m, const glm::vec4& in) {
  return m[0] * in.x + m[1] * in.y + m[2] * in.z + m[3] * in.w;
}

}  // namespace

XfTexGenState::XfTexGenState() {
  // GX_Init loads the 3x4 identity at GX_IDENTITY [OGC gx.c __GX_InitGX]; the rest of matrix
  // memory starts zero.
  matrices[kIdentityRow / 3] = TexMatrix{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
}

glm::vec3 generate_texcoord(const XfTexGenState& state, int index, const TexGenInputs& in) {
  LT_CHECK(index >= 0 && index < kMaxTexGens, "texgen index out of range");
  const TexGen& gen = state.texgens[index];
  LT_CHECK(gen.type == kMtx3x4 || gen.type == kMtx2x4,
           "texgen type must be GX_TG_MTX3x4 or GX_TG_MTX2x4");
  // Matrix ids are XF row numbers; every texture-capable matrix starts on a multiple of 3 (the
  // GX_PNMTXn, GX_TEXMTXn and GX_IDENTITY ids [OGC gx.h L210-235]).
  LT_CHECK(gen.matrix % 3 == 0 && gen.matrix / 3 < static_cast<int>(state.matrices.size()),
           "texgen matrix must be a matrix id (a multiple of 3, at most GX_IDENTITY = 60)");
  glm::vec4 src = source_row(gen.source, in);
  src = glm::vec4(nan_to_one(src.x), nan_to_one(src.y), nan_to_one(src.z), src.w);
  const TexMatrix& m = state.matrices[gen.matrix / 3];
  const float s = row_dot(m[0], src);
  const float t = row_dot(m[1], src);
  // MTX2x4: q = 1. MTX3x4: q is the third row; the divide by q happens after interpolation, in
  // the rasteriser [DSW Rasterizer.cpp BuildBlock]. GX_Init's post-transform is the identity
  // (GX_DTTIDENTITY), which leaves finite values as they are.
  const float q = gen.type == kMtx2x4 ? 1.0f : row_dot(m[2], src);
  // "When q is 0, the GameCube appears to have a special case" [DSW TransformTexCoordRegular]:
  // s and t are halved and clamped to [-1, 1] at the vertex (devkitPro's neheGX Lesson08 shows
  // it, Dolphin's comment says).
  if (q == 0.0f)
    return glm::vec3(std::clamp(s / 2.0f, -1.0f, 1.0f), std::clamp(t / 2.0f, -1.0f, 1.0f), q);
  return glm::vec3(s, t, q);
}

}  // namespace lt::gx
