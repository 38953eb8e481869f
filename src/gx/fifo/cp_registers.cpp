#include "gx/fifo/cp_registers.h"

#include "core/error.h"
#include "gx/fifo/xf_registers.h"

namespace lt::gx::fifo {

namespace {
// GX_POS_XYZ 1, GX_NRM_XYZ 0, GX_CLR_RGBA 1, GX_TEX_S 0 / GX_TEX_ST 1; GX_F32 4, GX_RGBA8 5
// [OGC gx.h].
constexpr u32 kPosXyz = 1, kClrRgba = 1, kTexSt = 1, kF32 = 4, kRgba8 = 5;
constexpr u32 kDirect = 1;  // GX_DIRECT

// CP 0x30 / XF 0x1018: position-normal matrix index 0-5 (GX_PNMTX0 = 0), texcoord 0..3 matrix
// index at 6, 12, 18, 24; CP 0x40 / XF 0x1019: texcoords 4..7 at 0, 6, 12, 18 [OGC gx.c
// GX_SetTexCoordGen2 L2745-2775, GX_SetCurrentMtx L2931] [DHW CPMemory.h TMatrixIndexA/B].
std::array<u32, 2> matrix_indices(const XfTexGenState& t) {
  auto m = [&](int n) { return static_cast<u32>(t.texgens[static_cast<size_t>(n)].matrix); };
  return {place(0, 0, 6) | place(m(0), 6, 6) | place(m(1), 12, 6) | place(m(2), 18, 6) |
              place(m(3), 24, 6),
          place(m(4), 0, 6) | place(m(5), 6, 6) | place(m(6), 12, 6) | place(m(7), 18, 6)};
}
}  // namespace

VertexDescriptor sent_attributes(const GxState& s) {
  if (s.vertex.count() > 0) return s.vertex;
  VertexDescriptor v;
  v.type[kVaPos] = v.type[kVaNrm] = v.type[kVaClr0] = static_cast<u8>(kDirect);
  int highest = -1;
  for (int g = 0; g < s.texgen.num_texgens; ++g) {
    const u8 source = s.texgen.texgens[static_cast<size_t>(g)].source;
    if (source >= 4) highest = std::max(highest, source - 4);  // GX_TG_TEXn = 4 + n
  }
  for (int n = 0; n <= highest; ++n) v.type[static_cast<size_t>(kVaTex0 + n)] = kDirect;
  return v;
}

TexCoordFormats sent_formats(const TexCoordFormats& f) {
  TexCoordFormats out;
  for (int n = 0; n < kMaxTexGens; ++n)
    out.kind[static_cast<size_t>(n)] = f.is_uv(n) ? TexCoordFormats::ST : TexCoordFormats::S;
  return out;
}

u32 vcd_low(const VertexDescriptor& v) {
  return place(v.type[kVaPos], 9, 2) | place(v.type[kVaNrm], 11, 2) |
         place(v.type[kVaClr0], 13, 2) | place(v.type[kVaClr1], 15, 2);
}

u32 vcd_high(const VertexDescriptor& v) {
  u32 r = 0;
  for (int n = 0; n < kMaxTexGens; ++n)
    r |= place(v.type[static_cast<size_t>(kVaTex0 + n)], 2 * n, 2);
  return r;
}

std::array<u32, 3> vertex_attribute_formats(const TexCoordFormats& formats) {
  const TexCoordFormats f = sent_formats(formats);
  auto st = [&](int n) {
    return f.kind[static_cast<size_t>(n)] == TexCoordFormats::ST ? kTexSt : 0u;
  };
  // VAT A: position count 0, format 1-3; normal count 9, format 10-12; colour 0 count 13,
  // format 14-16; colour 1 17, 18-20; TEX0 count 21, format 22-24 (fractions 0: floats).
  const u32 a = place(kPosXyz, 0, 1) | place(kF32, 1, 3) | place(kF32, 10, 3) |
                place(kClrRgba, 13, 1) | place(kRgba8, 14, 3) | place(kClrRgba, 17, 1) |
                place(kRgba8, 18, 3) | place(st(0), 21, 1) | place(kF32, 22, 3) | place(1, 30, 1);
  // VAT B: TEX1 count 0 format 1-3, TEX2 9 / 10-12, TEX3 18 / 19-21, TEX4 27 / 28-30.
  const u32 b = place(st(1), 0, 1) | place(kF32, 1, 3) | place(st(2), 9, 1) | place(kF32, 10, 3) |
                place(st(3), 18, 1) | place(kF32, 19, 3) | place(st(4), 27, 1) |
                place(kF32, 28, 3) | place(1, 31, 1);
  // VAT C: TEX5 count 5 format 6-8, TEX6 14 / 15-17, TEX7 23 / 24-26.
  const u32 c = place(st(5), 5, 1) | place(kF32, 6, 3) | place(st(6), 14, 1) | place(kF32, 15, 3) |
                place(st(7), 23, 1) | place(kF32, 24, 3);
  return {a, b, c};
}

u32 vertex_specs(const VertexDescriptor& v, bool nbt) {
  const u32 colours = (v.has(kVaClr0) ? 1u : 0u) + (v.has(kVaClr1) ? 1u : 0u);
  u32 texcoords = 0;
  for (int n = 0; n < kMaxTexGens; ++n) texcoords += v.has(kVaTex0 + n) ? 1u : 0u;
  const u32 normals = v.has(kVaNrm) ? (nbt ? 2u : 1u) : 0u;
  return place(colours, 0, 2) | place(normals, 2, 2) | place(texcoords, 4, 4);
}

size_t vertex_size(const VertexDescriptor& v, const TexCoordFormats& formats) {
  const TexCoordFormats f = sent_formats(formats);
  size_t n = 0;
  if (v.has(kVaPos)) n += 12;
  if (v.has(kVaNrm)) n += 12;
  if (v.has(kVaClr0)) n += 4;
  if (v.has(kVaClr1)) n += 4;
  for (int t = 0; t < kMaxTexGens; ++t) {
    if (v.has(kVaTex0 + t)) n += f.kind[static_cast<size_t>(t)] == TexCoordFormats::ST ? 8 : 4;
  }
  return n;
}

void write_vat(CommandStream& out, const std::array<u32, 3>& vat, int format) {
  LT_CHECK(format >= 0 && format < 8, "a vertex format is GX_VTXFMT0..7");
  const auto n = static_cast<u8>(format);
  out.load_cp(static_cast<u8>(cp::kVatA + n), vat[0]);
  out.load_cp(static_cast<u8>(cp::kVatB + n), vat[1]);
  out.load_cp(static_cast<u8>(cp::kVatC + n), vat[2]);
}

void write_pass_cp(CommandStream& out, const GxState& s, int format) {
  const VertexDescriptor v = sent_attributes(s);
  out.load_cp(cp::kVcdLow, vcd_low(v));
  out.load_cp(cp::kVcdHigh, vcd_high(v));
  out.load_xf(xf::kVertexSpecs, vertex_specs(v));
  write_vat(out, vertex_attribute_formats(s.texcoord_formats), format);
  const auto idx = matrix_indices(s.texgen);
  out.load_cp(cp::kMatrixIndexA, idx[0]);
  out.load_xf(xf::kMatrixIndexA, idx[0]);
  out.load_cp(cp::kMatrixIndexB, idx[1]);
  out.load_xf(xf::kMatrixIndexB, idx[1]);
}

}  // namespace lt::gx::fifo
