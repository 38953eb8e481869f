// The BP registers (setup unit, rasteriser, texture units, TEV, pixel engine) of a GX state: the
// values libogc's calls write, field by field, with each field's bit position and the call it
// comes from [OGC gx.c] and the register's layout in Dolphin [DHW BPMemory.h]. Pure functions
// of the modelled state (gx_state.h) plus the writers that send them in libogc's order.
#pragma once

#include <array>

#include "gx/fifo/command_stream.h"
#include "gx/gx_state.h"

namespace lt::gx::fifo {

// BP addresses [DHW BPMemory.h BPMEM_*] [OGC gx.c, the 0xNN000000 of each GX_LOAD_BP_REG].
namespace bp {
inline constexpr u8 kGenMode = 0x00, kCopyFilterPattern0 = 0x01, kIndirectMask = 0x0f,
                    kIndirectStage0 = 0x10, kScissorTopLeft = 0x20, kScissorBottomRight = 0x21,
                    kLinePointWidth = 0x22, kIndirectScale0 = 0x25, kIndirectScale1 = 0x26,
                    kTevOrder0 = 0x28, kTexCoordSize0 = 0x30, kZMode = 0x40, kBlendMode = 0x41,
                    kConstantAlpha = 0x42, kPixelControl = 0x43, kFieldMask = 0x44,
                    kCopySourceTopLeft = 0x49, kCopySourceSize = 0x4a, kCopyDestination = 0x4b,
                    kCopyStride = 0x4d, kCopyYScale = 0x4e, kClearAlphaRed = 0x4f,
                    kClearGreenBlue = 0x50, kClearZ = 0x51, kCopyTrigger = 0x52,
                    kCopyFilter0 = 0x53, kCopyFilter1 = 0x54, kRevisionBits = 0x58,
                    kScissorOffset = 0x59, kLoadTlut0 = 0x64, kLoadTlut1 = 0x65,
                    kTextureInvalidate = 0x66, kFieldMode = 0x68, kTevColorEnv0 = 0xc0,
                    kTevAlphaEnv0 = 0xc1, kTevRegisterRA0 = 0xe0, kTevRegisterBG0 = 0xe1,
                    kFogParam3 = 0xf1, kFogColor = 0xf2, kAlphaCompare = 0xf3, kZTextureBias = 0xf4,
                    kZTexture = 0xf5, kTevKonstSelect0 = 0xf6;
// Per texture map n: maps 0..3 at base + n, maps 4..7 at base + 0x20 + (n - 4)
// [OGC gx.c _gxtexmode0ids .. _gxteximg3ids, _gxtextlutids].
inline constexpr u8 kTexMode0 = 0x80, kTexMode1 = 0x84, kTexImage0 = 0x88, kTexImage1 = 0x8c,
                    kTexImage2 = 0x90, kTexImage3 = 0x94, kTexTlut = 0x98;
constexpr u8 texture_register(u8 base, int map) {
  return static_cast<u8>(base + (map < 4 ? map : 0x20 + map - 4));
}
}  // namespace bp

// The values of one pass's BP registers.
u32 gen_mode(const GxState& state);
u32 tev_order(const TevState& tev, int pair);  // stages 2 pair, 2 pair + 1
u32 tev_color_env(const TevStage& stage);
u32 tev_alpha_env(const TevStage& stage);
// GX_SetTevColorS10 / GX_SetTevKColor: the RA and BG halves, bit 23 telling konst from register.
std::array<u32, 2> tev_register(const ColorS10& value);
std::array<u32, 2> tev_konst(const Color8& value);
u32 tev_konst_select(const TevState& tev, int index);  // BP 0xF6 + index, index 0..7
u32 alpha_compare(const AlphaCompare& compare);
u32 blend_mode(const BlendMode& blend, bool dither);  // with GX_Init's colour/alpha update
u32 pixel_control(const PixelFormat& format);
u32 z_mode(const ZMode& z);

// A texture map's registers as GX_InitTexObj + GX_LoadTexObj write them, the image at the
// physical address `address` (32-byte aligned).
struct TextureRegisters {
  u32 mode0, mode1, image0, image1, image2, image3;
  u32 tlut;  // written for colour-indexed formats only
};
TextureRegisters texture_registers(const TextureObject& texture, int map, u32 address);

// GX_LoadTlut's registers: colour-indexed `t`'s palette, at the physical address `address`,
// into TMEM at t.tlut_offset.
void write_tlut_load(CommandStream& out, const TextureObject& t, u32 address);

// Every BP register GxState models, for one pass, in libogc's order; `textures[m]` is what map m
// holds (null: nothing) and `addresses[m]` where its tiles are in RAM; a colour-indexed map's
// palette is at `tlut_addresses[m]` and loaded into TMEM (GX_LoadTlut) before its registers.
void write_pass_bp(CommandStream& out, const GxState& state,
                   const std::array<const TextureObject*, kMaxTexMaps>& textures,
                   const std::array<u32, kMaxTexMaps>& addresses,
                   const std::array<u32, kMaxTexMaps>& tlut_addresses = {});

// The BP registers GX_Init sets that GxState does not model (copy filter, line width, scissor,
// pixel format, dither, field mask, fog off, indirect stages off, revision bits), for a frame of
// `size`.
void write_gx_init_bp(CommandStream& out, FrameSize size);

// GX_SetCopyClear(color, 0xffffff) [OGC gx.c L1891-1903].
void write_copy_clear(CommandStream& out, const Color8& color);

// An EFB copy of the whole frame with clear: to an RGBA8 texture at `address` (the frame's
// initial clear), or to the XFB at `address` (GX_CopyDisp(xfb, GX_TRUE), the frame's end).
// Both clear as GX_CopyDisp does: z mode forced to ALWAYS with update, blending off, then both
// restored from the mirror [OGC gx.c L2010-2054] - the texture copy only: the display copy ends
// the frame.
void write_clearing_texture_copy(CommandStream& out, FrameSize size, u32 address);
void write_display_copy(CommandStream& out, FrameSize size, u32 address);

}  // namespace lt::gx::fifo
