// The XF (transform unit) lighting: per vertex, each colour channel's 8-bit RGBA from the
// channel control, the ambient and material colours and up to 8 hardware lights
// (gx-hardware.md §2). XF arithmetic is float (Dolphin uses host 32-bit floats [DSW
// TransformUnit.cpp]); the result is converted to 8 bits, clamped before the material multiply,
// and multiplied as (mat * (l + (l >> 7))) >> 8 [DSW TransformColor] [HWT gxtest/lighting.cpp L86].
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "gx/gx_types.h"

namespace lt::gx {

// One hardware light as GX_LoadLightObj copies it into XF memory [OGC gx.c L4587-4641]: colour,
// angular coefficients a0..a2, distance coefficients k0..k2, eye-space position and the direction
// slot (GX_InitLightDir stores the *negated* direction [OGC gx.c L4686-4693]; GX_InitSpecularDirHA
// stores the half-angle vector as given).
struct XfLight {
  Color8 color{};
  std::array<float, 3> a{1, 0, 0}, k{1, 0, 0};
  glm::vec3 position{0}, direction{0};
  bool operator==(const XfLight&) const = default;
};

// libogc's constants [OGC gx.h L172-203], the values ChannelControl stores.
inline constexpr u8 kSrcReg = 0, kSrcVtx = 1;
inline constexpr u8 kDiffuseNone = 0, kDiffuseSigned = 1, kDiffuseClamp = 2;
inline constexpr u8 kAttnSpec = 0, kAttnSpot = 1, kAttnNone = 2;

// GX_SetChanCtrl, in libogc's terms [OGC gx.h L1873, gx.c L2193-2209]. attn_fn is libogc's
// GX_AF_SPEC 0 / GX_AF_SPOT 1 / GX_AF_NONE 2; GX_SetChanCtrl forces diff_fn to GX_DF_NONE when
// attn_fn is GX_AF_SPEC (gx.c L2195), and the parser stores the forced value.
struct ChannelControl {
  bool lighting = false;   // GX_ENABLE: lit; GX_DISABLE: the material colour passes unchanged
  u8 ambient_source = 0;   // GX_SRC_REG 0, GX_SRC_VTX 1
  u8 material_source = 1;  // GX_Init: GX_SRC_VTX [OGC gx.c __GX_InitGX]
  u8 light_mask = 0;       // bit n = GX_LIGHTn
  u8 diffuse_fn = 0;       // GX_DF_NONE 0, GX_DF_SIGNED 1, GX_DF_CLAMP 2
  u8 attenuation_fn = 2;   // GX_AF_NONE
  bool operator==(const ChannelControl&) const = default;
};

// How the per-light contributions become one 8-bit value. The sources disagree and no hardware
// test settles it (gx-hardware.md §2.4): Dolphin's software renderer sums in float and truncates
// once [DSW TransformColor]; its shader backends round each light to an integer before summing
// [DHW LightingShaderGen GenerateLightShader]. The path uses the first (the software renderer
// is the bit-level model); the second exists so docs/porting-to-the-wii.md can say how far.
enum class LightRounding { SumThenTruncate, RoundEachLight };

struct XfLightingState {
  int num_channels = 0;  // GX_SetNumChans; GX_Init leaves 0
  // Controls of COLOR0, COLOR1, ALPHA0, ALPHA1 (GX_COLOR0A0 sets 0 and 2, GX_COLOR1A1 1 and 3).
  std::array<ChannelControl, 4> control{};
  // Ambient and material registers per channel (RGB from the COLORn control, A from ALPHAn).
  // GX_Init: ambient black, material white [OGC gx.c __GX_InitGX].
  std::array<Color8, kMaxChannels> ambient{Color8{0, 0, 0, 0}, Color8{0, 0, 0, 0}};
  std::array<Color8, kMaxChannels> material{Color8{255, 255, 255, 255}, Color8{255, 255, 255, 255}};
  std::array<XfLight, kMaxLights> lights{};
  bool operator==(const XfLightingState&) const = default;
};

// The two channel colours of one vertex. `position` and `normal` are in eye space (after the
// position and normal matrices); the normal is normalised here. `vertex_colors` are the vertex's
// CLR0 / CLR1 (material or ambient source GX_SRC_VTX). Channels beyond num_channels are zero.
// Never NaN: a zero normal lights nothing, and a light exactly at the vertex takes l = N.
std::array<Color8, kMaxChannels> light_vertex(
    const XfLightingState& state, const glm::vec3& position, const glm::vec3& normal,
    const std::array<Color8, kMaxChannels>& vertex_colors,
    LightRounding rounding = LightRounding::SumThenTruncate);

}  // namespace lt::gx
