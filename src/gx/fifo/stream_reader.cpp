#include "gx/fifo/stream_reader.h"

#include "core/error.h"

namespace lt::gx::fifo {

namespace {
// The bytes one vertex takes under the CP registers' descriptor and VAT 0 (direct attributes
// only; POS/NRM F32 XYZ, CLRn RGBA8, TEXn F32 S or ST - what the stream uses).
size_t stream_vertex_size(const RegisterFile& r) {
  const u32 lo = r.cp[0x50], hi = r.cp[0x60];
  const u32 vat_a = r.cp[0x70], vat_b = r.cp[0x80], vat_c = r.cp[0x90];
  size_t n = 0;
  if (field(lo, 9, 2)) n += 12;
  if (field(lo, 11, 2)) n += 12;
  if (field(lo, 13, 2)) n += 4;
  if (field(lo, 15, 2)) n += 4;
  // Each TEXn's element count bit: VAT A 21; VAT B 0, 9, 18, 27; VAT C 5, 14, 23
  // [DHW CPMemory.h UVAT_group0..2].
  const bool st[8] = {field(vat_a, 21, 1) != 0, field(vat_b, 0, 1) != 0,  field(vat_b, 9, 1) != 0,
                      field(vat_b, 18, 1) != 0, field(vat_b, 27, 1) != 0, field(vat_c, 5, 1) != 0,
                      field(vat_c, 14, 1) != 0, field(vat_c, 23, 1) != 0};
  for (int t = 0; t < 8; ++t)
    if (field(hi, 2 * t, 2)) n += st[t] ? 8 : 4;
  return n;
}
}  // namespace

StreamEvents read_stream(const std::vector<u8>& b, RegisterFile& r, const std::string& file,
                         const DrawCallback& on_draw) {
  StreamEvents ev;
  size_t at = 0;
  auto need = [&](size_t n) {
    if (b.size() - at < n)
      throw InputError(file, "byte " + std::to_string(at), "a command is cut short");
  };
  auto u32_ = [&]() {
    need(4);
    const u32 v = (u32{b[at]} << 24) | (u32{b[at + 1]} << 16) | (u32{b[at + 2]} << 8) | b[at + 3];
    at += 4;
    return v;
  };
  while (at < b.size()) {
    const size_t start = at;
    const u8 op = b[at++];
    if (op == 0x00 || op == 0x48) continue;  // NOP, invalidate vertex cache
    if (op == 0x08) {
      need(1);
      const u8 reg = b[at++];
      r.cp[reg] = u32_();
      ++ev.cp_loads;
    } else if (op == 0x10) {
      const u32 head = u32_();
      const u32 count = (head >> 16) + 1, address = head & 0xffff;
      for (u32 i = 0; i < count; ++i) {
        const u32 a = address + i, v = u32_();
        if (a < kXfMemoryWords) {
          r.xf_memory[a] = v;
        } else if (a >= kXfRegisterBase && a < kXfRegisterBase + kXfRegisters) {
          r.xf_registers[a - kXfRegisterBase] = v;
        } else {
          throw InputError(file, "byte " + std::to_string(start),
                           "an XF load to address " + std::to_string(a) + " outside XF");
        }
        ++ev.xf_words;
      }
    } else if (op == 0x61) {
      const u32 v = u32_();
      const u8 reg = static_cast<u8>(v >> 24);
      const u32 value = v & 0xffffff;
      ++ev.bp_loads;
      if (reg == 0x52) ev.copies.push_back(value);
      if (reg >= 0xe0 && reg <= 0xe7) {
        auto& target = (value >> 23) & 1 ? r.tev_konst : r.tev_registers;
        target[(reg - 0xe0) / 2][(reg - 0xe0) % 2] = value;
      }
      r.bp[reg] = value;
      r.bp_written.set(reg);
    } else if (op >= 0x80 && op < 0xc0) {
      need(2);
      StreamDraw d;
      d.primitive = static_cast<u8>((op >> 3) & 7);
      d.vat = op & 7;
      d.count = (u32{b[at]} << 8) | b[at + 1];
      at += 2;
      d.offset = at;
      d.vertex_size = stream_vertex_size(r);
      need(d.count * d.vertex_size);
      at += d.count * d.vertex_size;
      if (on_draw) on_draw(r, d);
      ev.draws.push_back(d);
    } else {
      throw InputError(file, "byte " + std::to_string(start),
                       "unknown GP opcode " + std::to_string(op));
    }
  }
  return ev;
}

}  // namespace lt::gx::fifo
