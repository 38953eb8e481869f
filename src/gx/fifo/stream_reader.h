// Reads a GP command stream back, as Dolphin's command processor walks it: register loads into a
// register file (BP 0xE0..0xE7 kept apart by bit 23, TEV register or konst, as the hardware
// does [DHW BPStructs.cpp BPWritten, BPMEM_TEV_COLOR_RA]), draws skipped by the vertex size
// the current CP descriptor and format give. For tests and for reading a FIFO log's frame; it
// shares no field definition with the encoder beyond the opcodes.
#pragma once

#include <array>
#include <bitset>
#include <functional>
#include <string>
#include <vector>

#include "gx/fifo/command_stream.h"

namespace lt::gx::fifo {

struct RegisterFile {
  std::array<u32, kBpRegisters> bp{};
  std::bitset<kBpRegisters> bp_written;  // since the last clear_written()
  // BP 0xE0 + 2n / 0xE1 + 2n by the type bit 23: [n][0] = RA, [n][1] = BG.
  std::array<std::array<u32, 2>, 4> tev_registers{}, tev_konst{};
  std::array<u32, kCpRegisters> cp{};
  std::array<u32, kXfMemoryWords> xf_memory{};
  std::array<u32, kXfRegisters> xf_registers{};
  u32 xf(u32 address) const { return xf_registers[address - kXfRegisterBase]; }
};

struct StreamDraw {
  u8 primitive = 0, vat = 0;
  u32 count = 0;
  size_t offset = 0;       // of the first vertex in the stream
  size_t vertex_size = 0;  // bytes
};

// A GX_CallDispList in the stream: the list is in RAM, not read here (the caller finds its bytes,
// e.g. in a FIFO log's memory updates, and reads them with the registers as they stand).
struct StreamCall {
  size_t offset = 0;  // of the command in the stream
  u32 address = 0, size = 0;
};

struct StreamEvents {
  std::vector<StreamDraw> draws;
  std::vector<StreamCall> display_lists;
  std::vector<u32> copies;  // values written to BP 0x52 (EFB copy triggers), in order
  size_t bp_loads = 0, cp_loads = 0, xf_words = 0;
  size_t array_loads = 0;  // CP loads of an array's base (0xA0 + n) or stride (0xB0 + n)
};

// Applies every command of `bytes` to `regs`, calling `on_draw` (if given) at each draw with the
// registers as they stand. Throws InputError(`file`, "byte N", ...) on an opcode it does not know
// or a command cut short.
using DrawCallback = std::function<void(const RegisterFile&, const StreamDraw&)>;
StreamEvents read_stream(const std::vector<u8>& bytes, RegisterFile& regs, const std::string& file,
                         const DrawCallback& on_draw = {});

}  // namespace lt::gx::fifo
