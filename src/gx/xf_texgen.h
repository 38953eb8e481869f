// The XF texture-coordinate generators (gx-hardware.md §3.1): each texgen multiplies one source
// row (position, normal or an input texcoord) by a 2x4 or 3x4 matrix from XF matrix memory.
// The normal source is the raw vertex-stream normal: object space, not normalised, no normal
// matrix [DSW TransformUnit.cpp; DHW VertexShaderGen `coord.xyz = rawnormal.xyz`].
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "gx/gx_types.h"

namespace lt::gx {

// GX_SetTexCoordGen(texcoord, type, source, matrix) in libogc's constants [OGC gx.h L2726]:
// type GX_TG_MTX3x4 0 / GX_TG_MTX2x4 1; source GX_TG_POS 0, GX_TG_NRM 1, GX_TG_TEX0..7 4..11;
// matrix GX_TEXMTX0..9 = 30, 33, .., 57 or GX_IDENTITY 60. GX_Init: every texgen n is
// (MTX2x4, TEXn, IDENTITY) [OGC gx.c __GX_InitGX].
struct TexGen {
  u8 type = 1, source = 4, matrix = 60;
  bool operator==(const TexGen&) const = default;
};

// XF matrix memory rows used for texture matrices: 3 rows of 4 floats at each of GX_TEXMTX0..9
// and GX_IDENTITY (row index / 3). GX_LoadTexMtxImm with GX_MTX2x4 writes 2 rows, GX_MTX3x4 3
// [OGC gx.c L2902-2918]. GX_Init loads the identity at GX_IDENTITY [OGC gx.c __GX_InitGX].
using TexMatrix = std::array<std::array<float, 4>, 3>;

struct XfTexGenState {
  int num_texgens = 1;  // GX_Init: 1
  std::array<TexGen, kMaxTexGens> texgens{TexGen{1, 4, 60},  TexGen{1, 5, 60}, TexGen{1, 6, 60},
                                          TexGen{1, 7, 60},  TexGen{1, 8, 60}, TexGen{1, 9, 60},
                                          TexGen{1, 10, 60}, TexGen{1, 11, 60}};
  // Indexed by matrix id / 3 (0..20): GX_PNMTX0..9 share the space but are not texture matrices.
  std::array<TexMatrix, 21> matrices{};
  XfTexGenState();
  bool operator==(const XfTexGenState&) const = default;
};

// The vertex inputs a texgen may read (raw, as the vertex stream sends them).
struct TexGenInputs {
  glm::vec3 position{0};                           // object-space position
  glm::vec3 normal{0};                             // object-space normal, as sent
  std::array<glm::vec2, kMaxTexGens> texcoords{};  // GX_VA_TEX0..7
};

// (s, t, q) of texgen `index`; q = 1 for MTX2x4. Never NaN: a NaN input component is replaced by
// 1, as Dolphin's software renderer does [DSW TransformTexCoordRegular].
glm::vec3 generate_texcoord(const XfTexGenState& state, int index, const TexGenInputs& in);

}  // namespace lt::gx
