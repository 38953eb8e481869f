#include "gx/fifo/stream_reader.h"

#include "core/error.h"

namespace lt::gx::fifo {

namespace {
// Bytes of a position, normal or texture coordinate component of VAT type `type`: GX_U8, GX_S8
// 1, GX_U16, GX_S16 2, GX_F32 4 [OGC gx.h L93-97] [DHW VertexLoader_Position.cpp].
size_t stream_component_bytes(u32 type) {
  return type <= 1 ? 1 : type <= 3 ? 2 : 4;
}
// Bytes of a direct vertex colour of VAT type `type`: RGB565 2, RGB8 3, RGBX8 4, RGBA4 2, RGBA6
// 3, RGBA8 4 [OGC gx.h L98-103] [DHW VertexLoader_Color.cpp].
size_t stream_color_bytes(u32 type) {
  constexpr size_t kSizes[] = {2, 3, 4, 2, 3, 4};
  return type < 6 ? kSizes[type] : 4;
}

// The bytes one vertex takes under the CP registers' descriptor and the VAT of format `format` (the
// draw command's low three bits pick it [DHW OpcodeDecoding.h detail::RunCommand: vat = cmdbyte &
// GX_VAT_MASK, 0x07, in its case for opcodes GX_PRIMITIVE_START 0x80 .. GX_PRIMITIVE_END 0xBF]
// [DHW VertexLoaderManager.cpp RunVertices]): each attribute's direct bytes (F32 by default, a
// stored mesh's types otherwise), or its index, 1 byte for GX_INDEX8 (2) and 2 for GX_INDEX16
// (3) [OGC gx.h L82-85] [DHW VertexLoaderBase.cpp GetVertexSize].
size_t stream_vertex_size(const RegisterFile& r, u32 format) {
  const u32 lo = r.cp[0x50], hi = r.cp[0x60];
  const u32 vat_a = r.cp[0x70 + format], vat_b = r.cp[0x80 + format], vat_c = r.cp[0x90 + format];
  size_t n = 0;
  // `input` the descriptor's 2-bit field, `direct` the bytes sent directly, `indices` how many
  // indices an indexed attribute sends.
  auto add = [&](u32 input, size_t direct, size_t indices = 1) {
    n += input >= 2 ? (input - 1) * indices : input ? direct : 0;
  };
  // VAT A: position count bit 0 (XY, XYZ) and type 1-3, normal count bit 9 (XYZ, NBT) and type
  // 10-12, colour types 14-16 and 18-20, NormalIndex3 bit 31 [DHW CPMemory.h UVAT_group0]. An
  // NBT sends three vectors; indexed with NormalIndex3 one index each, else one for all three
  // [DHW VertexLoader_Normal.cpp GetSize].
  const bool nbt = field(vat_a, 9, 1) != 0, index3 = field(vat_a, 31, 1) != 0;
  add(field(lo, 9, 2), (field(vat_a, 0, 1) ? 3 : 2) * stream_component_bytes(field(vat_a, 1, 3)));
  add(field(lo, 11, 2), (nbt ? 9 : 3) * stream_component_bytes(field(vat_a, 10, 3)),
      nbt && index3 ? 3 : 1);
  add(field(lo, 13, 2), stream_color_bytes(field(vat_a, 14, 3)));
  add(field(lo, 15, 2), stream_color_bytes(field(vat_a, 18, 3)));
  // Each TEXn's element count bit: VAT A 21; VAT B 0, 9, 18, 27; VAT C 5, 14, 23; its type the
  // three bits above it [DHW CPMemory.h UVAT_group0..2].
  const u32 vat[8] = {vat_a, vat_b, vat_b, vat_b, vat_b, vat_c, vat_c, vat_c};
  const int count_bit[8] = {21, 0, 9, 18, 27, 5, 14, 23};
  for (size_t t = 0; t < 8; ++t) {
    const bool st = field(vat[t], count_bit[t], 1) != 0;
    add(field(hi, 2 * static_cast<int>(t), 2),
        (st ? 2 : 1) * stream_component_bytes(field(vat[t], count_bit[t] + 1, 3)));
  }
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
      if (reg >= 0xa0 && reg < 0xc0) ++ev.array_loads;
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
    } else if (op == 0x40) {  // CALL_DL: address, size [DHW OpcodeDecoding.h GX_CMD_CALL_DL]
      const u32 address = u32_();
      ev.display_lists.push_back({start, address, u32_()});
    } else if (op >= 0x80 && op < 0xc0) {
      need(2);
      StreamDraw d;
      d.primitive = static_cast<u8>((op >> 3) & 7);
      d.vat = op & 7;
      d.count = (u32{b[at]} << 8) | b[at + 1];
      at += 2;
      d.offset = at;
      d.vertex_size = stream_vertex_size(r, d.vat);
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
