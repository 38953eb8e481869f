// The CP registers (command processor: what a vertex in the stream holds and how each attribute
// is encoded) of a GX state, as libogc's GX_SetVtxDesc / GX_SetVtxAttrFmt / GX_SetTexCoordGen
// leave them, with the XF's copies libogc sends beside them (vertex specs, matrix indices).
#pragma once

#include <array>

#include "gx/fifo/command_stream.h"
#include "gx/gx_state.h"

namespace lt::gx::fifo {

// CP addresses [DHW CPMemory.h] [OGC gx.c GX_LOAD_CP_REG calls]; the VAT registers of format n
// are kVat* + n [DHW CPMemory.h CP_VAT_REG_A..C: "+ n"] (the gx variant's :vat=n; default 0).
namespace cp {
inline constexpr u8 kMatrixIndexA = 0x30, kMatrixIndexB = 0x40, kVcdLow = 0x50, kVcdHigh = 0x60,
                    kVatA = 0x70, kVatB = 0x80, kVatC = 0x90;
}

// The attributes each vertex of a pass carries: the program's descriptor, or for a program that
// declares none (program_check.h: it gets the whole stream) POS, NRM, CLR0 and GX_VA_TEX0..n up
// to the highest one a texgen reads.
VertexDescriptor sent_attributes(const GxState& state);
// What each GX_VA_TEXn is sent as: the program's GX_TEX_S / GX_TEX_ST, or the default of
// TexCoordFormats::is_uv where it set none.
TexCoordFormats sent_formats(const TexCoordFormats& formats);

// VCD low: position 9-10, normal 11-12, colour 0 13-14, colour 1 15-16 (2 bits each, 1 =
// GX_DIRECT); VCD high: GX_VA_TEXn at 2n [OGC gx.c __SETVCDATTR L2295-2367]
// [DHW CPMemory.h TVtxDesc].
u32 vcd_low(const VertexDescriptor& vertex);
u32 vcd_high(const VertexDescriptor& vertex);
// VAT A/B/C of GX_VTXFMT0 for the stream's formats: position XYZ F32, normal XYZ F32, colours
// RGBA8, texture coordinates F32 with S or ST [OGC gx.c __SETVCDFMT L2533-2620, GX_Init's
// __GX_InitRevBits: VAT A bit 30 and VAT B bit 31 set] [DHW CPMemory.h UVAT_group0..2].
std::array<u32, 3> vertex_attribute_formats(const TexCoordFormats& formats);
// XF 0x1008: colours 0-1, normals 2-3, texture coordinates 4-7, counted from the descriptor;
// the normals 2 where the normal is sent as an NBT (`nbt`: libogc's vcdNrms, set by
// GX_SetVtxDesc(GX_VA_NBT, ...)) [OGC gx.c __GX_XfVtxSpecs L751-776, __SETVCDATTR "case
// GX_VA_NBT"] [DHW XFMemory.h INVTXSPEC].
u32 vertex_specs(const VertexDescriptor& vertex, bool nbt = false);

// Bytes one vertex of the stream takes (F32 positions and normals, RGBA8 colours, F32 S or ST).
size_t vertex_size(const VertexDescriptor& vertex, const TexCoordFormats& formats);

// The pass's descriptor, formats and matrix indices, as libogc's __GX_SetDirtyState sends them
// before a draw: VCD (with the XF's vertex specs), VAT of vertex format `format` (0..7: the one
// the pass's draws name), matrix indices (CP and XF).
void write_pass_cp(CommandStream& out, const GxState& state, int format = 0);
// VAT A/B/C of vertex format `format` (CP 0x70/0x80/0x90 + format) set to `vat`.
void write_vat(CommandStream& out, const std::array<u32, 3>& vat, int format);

}  // namespace lt::gx::fifo
