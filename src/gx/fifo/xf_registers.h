// The XF registers and memory (transform unit: matrices, lights, colour channels, texgens,
// viewport, projection) of a GX state, as libogc's calls write them [OGC gx.c] into the layout
// Dolphin reads [DHW XFMemory.h].
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "gx/fifo/bp_registers.h"
#include "gx/fifo/command_stream.h"
#include "gx/gx_state.h"
#include "gx/transform_unit.h"

namespace lt::gx::fifo {

// XF addresses [DHW XFMemory.h XFMEM_*] [OGC gx.c GX_LOAD_XF_REG(S) calls].
namespace xf {
inline constexpr u32 kPositionMatrices = 0x000, kNormalMatrices = 0x400, kPostMatrices = 0x500,
                     kLights = 0x600, kLightWords = 16;
inline constexpr u32 kError = 0x1000, kClipDisable = 0x1005, kVertexSpecs = 0x1008,
                     kNumChannels = 0x1009, kAmbient0 = 0x100a, kMaterial0 = 0x100c,
                     kChannelControl0 = 0x100e, kDualTexture = 0x1012, kMatrixIndexA = 0x1018,
                     kMatrixIndexB = 0x1019, kViewport = 0x101a, kProjection = 0x1020,
                     kNumTexGens = 0x103f, kTexGen0 = 0x1040, kPostMatrixInfo0 = 0x1050;
// Matrix id m (GX_PNMTX0 0, GX_TEXMTX0 30 .. GX_IDENTITY 60) is 4 m in XF memory, rows of 4
// floats [OGC gx.c GX_LoadPosMtxImm, GX_LoadTexMtxImm L2902-2918]; GX_DTTIDENTITY (125) is
// post matrix 61: 0x500 + 4 * 61 [OGC gx.h GX_DTTMTX0 64, GX_DTTIDENTITY 125].
inline constexpr u32 kPostIdentity = 61;
}  // namespace xf

// GX_SetChanCtrl [OGC gx.c L2193-2209]: material source 0, lighting enable 1, lights 0..3 at
// 2-5, ambient source 6, diffuse function 7-8, attenuation enable 9 (attn_fn != GX_AF_NONE),
// attenuation select 10 (attn_fn != GX_AF_SPEC), lights 4..7 at 11-14
// [DHW XFMemory.h LitChannel].
u32 channel_control(const ChannelControl& control);
// GX_SetTexCoordGen(n, type, source, matrix) [OGC gx.c L2658-2744]: projection 1 (1 = STQ for
// GX_TG_MTX3x4), input form 2 (1 = ABC1 for the position and normal rows), source row 7-11
// (0 position, 1 normal, 5 + n GX_TG_TEXn) [DHW XFMemory.h TexMtxInfo].
u32 texgen_word(const TexGen& texgen);

// A view transform's projection (paths/gx/camera_transform.h makes the frame's) in
// GX_LoadProjectionMtx's seven words [OGC gx.c L1797-1830]: perspective (p0 = m00, p1 = m02,
// p2 = m11, p3 = m12, p4, p5, 0) or orthographic (.. m03 .. m13 .., 1).
std::array<u32, 7> projection_words(const ViewTransform& transform);
// GX_SetViewport(0, 0, w, h, 0, 1): w/2, -h/2, 2^24 - 1, w/2 + 342, h/2 + 342, 2^24 - 1
// [OGC gx.c GX_SetViewportJitter L1767-1791, field 1: no half-line shift] (frame_viewport's).
std::array<u32, 6> viewport_words(FrameSize size);

// Every XF register GxState models for one pass: colour channels (count, ambient, material,
// controls), the 8 lights, texgens (count, rows, post-transform rows), texture matrices.
void write_pass_xf(CommandStream& out, const GxState& state);

// GX_PNMTX0 (3 rows of 4) and its normal matrix (3 rows of 3): the camera's (write_view_xf) or an
// object's, for a mesh sent in its own coordinates (paths/gx/scene_vertices.h ObjectSpaceMesh).
void write_matrices_xf(CommandStream& out, const std::array<float, 12>& position,
                       const std::array<float, 9>& normal);
// The frame's camera: GX_LoadPosMtxImm / GX_LoadNrmMtxImm(GX_PNMTX0) - the scene's positions
// arrive camera-relative, so the position matrix is the world-to-eye rotation with no
// translation (paths/gx/scene_vertices.h) - the viewport and the projection.
void write_view_xf(CommandStream& out, const ViewTransform& transform, FrameSize size);

// The XF state GX_Init sets beyond GxState: the error register 0x3f, dual texture transform on
// (0x1012 = 1) [OGC gx.c __GX_InitRevBits L238-253], clipping on (GX_SetClipMode(GX_CLIP_ENABLE)
// = 0), and the post-transform identity GX_DTTIDENTITY [OGC gx.c __GX_InitGX].
void write_gx_init_xf(CommandStream& out);

}  // namespace lt::gx::fifo
