#include "gx/fifo/command_stream.h"

#include <bit>

#include "core/error.h"

namespace lt::gx::fifo {

void CommandStream::put_u32(u32 v) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes_.push_back(static_cast<u8>(v >> shift));
}

void CommandStream::put_f32(float v) {
  put_u32(float_bits(v));
}

void CommandStream::load_bp(u8 reg, u32 value, bool mirror) {
  put_u8(0x61);
  put_u32((static_cast<u32>(reg) << 24) | (value & 0xffffff));
  if (mirror) bp[reg] = value & 0xffffff;
}

void CommandStream::load_cp(u8 reg, u32 value) {
  put_u8(0x08);
  put_u8(reg);
  put_u32(value);
  cp[reg] = value;
}

void CommandStream::load_xf(u32 address, std::span<const u32> words) {
  for (size_t start = 0; start < words.size(); start += 16) {
    const size_t n = std::min<size_t>(16, words.size() - start);
    const u32 a = address + static_cast<u32>(start);
    put_u8(0x10);
    put_u32((static_cast<u32>(n - 1) << 16) | (a & 0xffff));
    for (size_t i = 0; i < n; ++i) {
      const u32 w = words[start + i];
      put_u32(w);
      const u32 at = a + static_cast<u32>(i);
      if (at < kXfMemoryWords) {
        xf_memory[at] = w;
      } else {
        LT_CHECK(at >= kXfRegisterBase && at < kXfRegisterBase + kXfRegisters,
                 "XF address out of the modelled range");
        xf_registers[at - kXfRegisterBase] = w;
      }
    }
  }
}

void CommandStream::begin(u8 primitive, u8 vat, u16 count) {
  put_u8(static_cast<u8>(0x80 | (primitive << 3) | (vat & 7)));
  put_u8(static_cast<u8>(count >> 8));
  put_u8(static_cast<u8>(count));
}

u32 float_bits(float v) {
  return std::bit_cast<u32>(v);
}
float bits_float(u32 v) {
  return std::bit_cast<float>(v);
}

}  // namespace lt::gx::fifo
