// The GP command stream a frame is sent as: the bytes the CPU writes to the graphics FIFO, big
// endian as the PowerPC writes them, and a mirror of the last value written to every BP, CP and
// XF register (the snapshot a Dolphin FIFO log carries in its header, fifo_log.h).
//
// Opcodes [DHW OpcodeDecoding.h Opcode] [OGC gx.c GX_LOAD_BP_REG / GX_LOAD_CP_REG /
// GX_LOAD_XF_REGS macros]: 0x08 LoadCP (register byte, u32), 0x10 LoadXF (u32 (count - 1) << 16 |
// address, then count u32), 0x61 LoadBP (u32 register << 24 | value), 0x80 | primitive << 3 | vat
// a draw with a u16 vertex count.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "gx/gx_types.h"

namespace lt::gx::fifo {

inline constexpr size_t kBpRegisters = 256;       // BP address space [DHW BPMemory.h BPMemory]
inline constexpr size_t kCpRegisters = 256;       // CP register snapshot [DHW FifoDataFile.h]
inline constexpr size_t kXfMemoryWords = 0x1000;  // XF matrix and light memory
inline constexpr u32 kXfRegisterBase = 0x1000;
inline constexpr size_t kXfRegisters = 0x58;  // XF 0x1000..0x1057 [DHW XFMemory.h XFMemory]

// GX_TRIANGLES: primitive 2 [OGC gx.h GX_TRIANGLES 0x90] [DHW OpcodeDecoding.h Primitive].
inline constexpr u8 kPrimitiveTriangles = 2;
// A draw's vertex count is a u16 [OGC gx.c GX_Begin].
inline constexpr size_t kMaxDrawVertices = 65535;

class CommandStream {
 public:
  // BP register `reg` (0..255) takes the low 24 bits of `value`. `mirror` false for triggers
  // (the EFB copy, texture invalidation) whose value is an event, not a state.
  void load_bp(u8 reg, u32 value, bool mirror = true);
  void load_cp(u8 reg, u32 value);
  // Consecutive XF words from `address`, split into loads of at most 16 words (the count libogc
  // sends in one GX_LOAD_XF_REGS for a light or a matrix).
  void load_xf(u32 address, std::span<const u32> words);
  void load_xf(u32 address, u32 word) { load_xf(address, std::span<const u32>(&word, 1)); }
  // A draw header of `count` vertices; the caller appends exactly that many vertices.
  void begin(u8 primitive, u8 vat, u16 count);
  void put_u8(u8 v) { bytes_.push_back(v); }
  void put_u32(u32 v);
  void put_f32(float v);

  const std::vector<u8>& bytes() const { return bytes_; }
  // The stream's bytes, moved out (a recorded frame keeps them: a seeded scene's is ~16 MB).
  std::vector<u8> take_bytes() && { return std::move(bytes_); }
  size_t position() const { return bytes_.size(); }

  std::array<u32, kBpRegisters> bp{};
  std::array<u32, kCpRegisters> cp{};
  std::array<u32, kXfMemoryWords> xf_memory{};
  std::array<u32, kXfRegisters> xf_registers{};

 private:
  std::vector<u8> bytes_;
};

// A float's bits, as the FIFO and XF memory hold it (IEEE single, the Broadway's format).
u32 float_bits(float v);
float bits_float(u32 v);

// The value of `bits` bits at `shift` of `reg`, and `v` placed there (masked to the field).
constexpr u32 field(u32 reg, int shift, int bits) {
  return (reg >> shift) & ((1u << bits) - 1);
}
constexpr u32 place(u32 v, int shift, int bits) {
  return (v & ((1u << bits) - 1)) << shift;
}

}  // namespace lt::gx::fifo
