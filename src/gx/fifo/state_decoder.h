// A pass's GxState read back from the registers the stream left (stream_reader.h): the inverse
// of libogc's calls as the hardware holds them, written from the register layouts [DHW
// BPMemory.h, XFMemory.h, CPMemory.h] without the encoder's helpers, so a test can hold the two
// against each other. What the registers cannot tell apart, the decoder returns in one form
// (canonical_state() gives the original in that form).
#pragma once

#include <array>

#include "gx/fifo/stream_reader.h"
#include "gx/gx_state.h"

namespace lt::gx::fifo {

struct DecodedPass {
  GxState state;  // textures: format, size, wrap and filter; data left empty
  std::array<u32, kMaxTexMaps> texture_addresses{};  // where each loaded map's image is
};

// Maps count as loaded where their image registers were written since the register file's
// bp_written was last cleared. The texture coordinate formats are read from the VAT of vertex
// format `vat` (the draw command's StreamDraw::vat).
DecodedPass decode_pass(const RegisterFile& regs, u32 vat = 0);

// `state` as the registers hold it: a TEV order's null colour channel is the zero channel (both
// write 7), a null texcoord is texcoord 0, the descriptor is what is sent (cp_registers.h
// sent_attributes), each GX_VA_TEXn format is explicit, GX_TEXMAP0 holds `map0_fallback` where
// the program loaded nothing (the emulator's LUT), texture data and palettes are dropped, and
// the position-matrix slots of texgen.matrices (ids 0..27) are zero: the encoder writes texture
// matrices only.
GxState canonical_state(const GxState& state, const TextureObject* map0_fallback);

}  // namespace lt::gx::fifo
