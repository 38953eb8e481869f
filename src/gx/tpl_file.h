// libogc's TPL texture files: what `TPL_OpenTPLFromMemory` / `TPL_GetTexture` /
// `TPL_GetTextureCI` read [OGC tpl.c L13-54, L147-187, L210-310] and devkitPro's gxtexconv writes
// (docs/textures.md "TPL files"). Every field big-endian (the console's order):
//   0  u32 version 0x0020AF30 (gxtexconv's `tplVersion`; libogc reads it and checks nothing)
//   4  u32 number of textures n
//   8  u32 header size, 12
//  12  n x (u32 offset of the image header, u32 offset of the palette header or 0)
// image header, 36 bytes: u16 height, u16 width, u32 format (GX_TF_*), u32 offset of the texel
//   data, u32 wrap s, u32 wrap t, u32 min filter, u32 mag filter, f32 LOD bias, u8 edge LOD,
//   u8 min LOD, u8 max LOD, u8 unpacked. max LOD > 0 makes libogc call GX_InitTexObj with
//   mipmaps on and GX_InitTexObjLOD; the levels 0 .. max LOD follow one another in the data.
// palette header, 12 bytes: u16 entries, u8 unpacked, u8 pad, u32 format (GX_TL_*), u32 offset
//   of the entries (2 bytes each).
// The writer puts the headers first and every texel and palette block on a 32-byte boundary (GX
// reads textures from 32-byte aligned addresses [OGC gx.h L4262]; gxtexconv pads the same way).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "gx/texture_format.h"

namespace lt::gx {

inline constexpr u32 kTplVersion = 0x0020AF30;

struct TplTexture {
  TexFormat format = TexFormat::I8;
  int width = 0, height = 0;
  int levels = 1;        // max LOD + 1
  std::vector<u8> data;  // mip_chain_bytes(format, width, height, levels)
  u32 wrap_s = 0, wrap_t = 0;            // GX_CLAMP 0, GX_REPEAT 1, GX_MIRROR 2
  u32 min_filter = 1, mag_filter = 1;    // GX_LINEAR; GX_LIN_MIP_LIN 5 for a mip chain
  float lod_bias = 0;
  u8 edge_lod = 0, min_lod = 0;
  TlutFormat tlut_format = TlutFormat::RGB565;
  std::vector<u8> tlut;  // colour-indexed formats: entries, 2 bytes each; else empty
  bool operator==(const TplTexture&) const = default;
};

std::vector<u8> write_tpl(const std::vector<TplTexture>& textures);

// Throws InputError naming `file` and the byte offset of the first field that is wrong: a
// header or block past the end of the file, a format libogc does not know, a size outside
// 1..1024, a max LOD past the chain's length, a colour-indexed texture without its palette or
// with more entries than its format can name.
std::vector<TplTexture> read_tpl(std::span<const u8> bytes, const std::string& file);

}  // namespace lt::gx
