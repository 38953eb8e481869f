#include "gx/fifo/state_decoder.h"

#include "gx/clipper.h"
#include "gx/fifo/cp_registers.h"
#include "gx/texture_format.h"

namespace lt::gx::fifo {

namespace {

float xf_float(const RegisterFile& r, u32 address) {
  return bits_float(r.xf_memory[address]);
}

Color8 xf_color(u32 w) {
  return {static_cast<u8>(w >> 24), static_cast<u8>(w >> 16), static_cast<u8>(w >> 8),
          static_cast<u8>(w)};
}

s16 s11(u32 v) {
  return static_cast<s16>((v & 0x400) ? static_cast<int>(v) - 0x800 : static_cast<int>(v));
}

TevCombiner combiner(u32 env, bool alpha) {
  TevCombiner c;
  if (alpha) {
    c.d = static_cast<u8>(field(env, 4, 3));
    c.c = static_cast<u8>(field(env, 7, 3));
    c.b = static_cast<u8>(field(env, 10, 3));
    c.a = static_cast<u8>(field(env, 13, 3));
  } else {
    c.d = static_cast<u8>(field(env, 0, 4));
    c.c = static_cast<u8>(field(env, 4, 4));
    c.b = static_cast<u8>(field(env, 8, 4));
    c.a = static_cast<u8>(field(env, 12, 4));
  }
  c.bias = static_cast<u8>(field(env, 16, 2));
  c.op = static_cast<u8>(field(env, 18, 1));
  c.clamp = field(env, 19, 1) != 0;
  c.scale = static_cast<u8>(field(env, 20, 2));
  c.dest = static_cast<u8>(field(env, 22, 2));
  return c;
}

}  // namespace

DecodedPass decode_pass(const RegisterFile& r, u32 vat) {
  DecodedPass out;
  GxState& s = out.state;
  // BP 0x00 GenMode.
  const u32 gen = r.bp[0x00];
  s.texgen.num_texgens = static_cast<int>(field(gen, 0, 4));
  s.lighting.num_channels = static_cast<int>(field(gen, 4, 3));
  s.tev.num_stages = static_cast<int>(field(gen, 10, 4)) + 1;
  // libogc's swap of front and back is its own inverse.
  s.cull_mode = hardware_cull_mode(static_cast<u8>(field(gen, 14, 2)));
  // TEV stages: orders 0x28.., combiners 0xC0 / 0xC1 + 2n, konst selects and swaps 0xF6..
  for (int st = 0; st < kMaxTevStages; ++st) {
    TevStage& stage = s.tev.stages[static_cast<size_t>(st)];
    const u32 order = r.bp[0x28 + st / 2] >> ((st & 1) ? 12 : 0);
    stage.texmap = field(order, 6, 1) ? static_cast<u8>(field(order, 0, 3)) : kTexMapNull;
    stage.texcoord = static_cast<u8>(field(order, 3, 3));
    const u32 channel = field(order, 7, 3);
    stage.channel = channel == 0 ? 4 : channel == 1 ? 5 : 6;  // COLOR0A0, COLOR1A1, COLORZERO
    const u32 color = r.bp[0xc0 + 2 * st], alpha = r.bp[0xc1 + 2 * st];
    stage.color = combiner(color, false);
    stage.alpha = combiner(alpha, true);
    stage.ras_swap = static_cast<u8>(field(alpha, 0, 2));
    stage.tex_swap = static_cast<u8>(field(alpha, 2, 2));
    const u32 ksel = r.bp[0xf6 + st / 2];
    stage.konst_color_sel = static_cast<u8>(field(ksel, (st & 1) ? 14 : 4, 5));
    stage.konst_alpha_sel = static_cast<u8>(field(ksel, (st & 1) ? 19 : 9, 5));
  }
  for (int t = 0; t < 4; ++t) {
    const u32 rg = r.bp[0xf6 + 2 * t], ba = r.bp[0xf7 + 2 * t];
    s.tev.swap_tables[static_cast<size_t>(t)] = {
        static_cast<u8>(field(rg, 0, 2)), static_cast<u8>(field(rg, 2, 2)),
        static_cast<u8>(field(ba, 0, 2)), static_cast<u8>(field(ba, 2, 2))};
    const auto& reg = r.tev_registers[static_cast<size_t>(t)];
    s.tev.registers[static_cast<size_t>(t)] = {
        s11(field(reg[0], 0, 11)), s11(field(reg[1], 12, 11)), s11(field(reg[1], 0, 11)),
        s11(field(reg[0], 12, 11))};
    const auto& k = r.tev_konst[static_cast<size_t>(t)];
    s.tev.konst[static_cast<size_t>(t)] = {
        static_cast<u8>(field(k[0], 0, 8)), static_cast<u8>(field(k[1], 12, 8)),
        static_cast<u8>(field(k[1], 0, 8)), static_cast<u8>(field(k[0], 12, 8))};
  }
  // Pixel engine: alpha test 0xF3, z mode 0x40, blend 0x41.
  const u32 ac = r.bp[0xf3];
  s.alpha_compare = {static_cast<u8>(field(ac, 16, 3)), static_cast<u8>(field(ac, 0, 8)),
                     static_cast<u8>(field(ac, 22, 2)), static_cast<u8>(field(ac, 19, 3)),
                     static_cast<u8>(field(ac, 8, 8))};
  const u32 z = r.bp[0x40];
  s.z = {field(z, 0, 1) != 0, static_cast<u8>(field(z, 1, 3)), field(z, 4, 1) != 0};
  const u32 bm = r.bp[0x41];
  s.blend.type = field(bm, 11, 1) ? 3 : field(bm, 0, 1) ? 1 : field(bm, 1, 1) ? 2 : 0;
  s.blend.src = static_cast<u8>(field(bm, 8, 3));
  s.blend.dst = static_cast<u8>(field(bm, 5, 3));
  s.blend.logic = static_cast<u8>(field(bm, 12, 4));
  s.dither = field(bm, 2, 1) != 0;
  // PE control 0x43: pixel format 0-2, z format 3-5.
  const u32 pe = r.bp[0x43];
  s.pixel_format = {static_cast<u8>(field(pe, 0, 3)), static_cast<u8>(field(pe, 3, 3))};
  // Texture maps whose image was (re)loaded.
  for (int m = 0; m < kMaxTexMaps; ++m) {
    const int offset = m < 4 ? m : 0x20 + m - 4;
    if (!r.bp_written.test(static_cast<size_t>(0x88 + offset))) continue;
    const u32 mode0 = r.bp[static_cast<size_t>(0x80 + offset)];
    const u32 image0 = r.bp[static_cast<size_t>(0x88 + offset)];
    TextureObject t;
    t.wrap_s = static_cast<u8>(field(mode0, 0, 2));
    t.wrap_t = static_cast<u8>(field(mode0, 2, 2));
    t.linear = field(mode0, 4, 1) != 0;
    // The LOD fields (bp_registers.cpp texture_registers): absent when they are GX_InitTexObj's
    // without mipmaps (min filter = mag filter, the rest zero).
    const u32 mode1 = r.bp[static_cast<size_t>(0x84 + offset)];
    TextureLod lod;
    lod.min_filter = static_cast<u8>(field(mode0, 5, 3));
    lod.diagonal = field(mode0, 8, 1) != 0;
    lod.bias = static_cast<std::int8_t>(static_cast<u8>(field(mode0, 9, 8)));
    lod.max_aniso = static_cast<u8>(field(mode0, 19, 2));
    lod.bias_clamp = field(mode0, 21, 1) != 0;
    lod.min_lod = static_cast<u8>(field(mode1, 0, 8));
    lod.max_lod = static_cast<u8>(field(mode1, 8, 8));
    TextureLod plain;
    plain.min_filter = t.linear ? 4 : 0;
    if (lod != plain) t.lod = lod;
    t.width = static_cast<int>(field(image0, 0, 10)) + 1;
    t.height = static_cast<int>(field(image0, 10, 10)) + 1;
    t.format = static_cast<u8>(field(image0, 20, 4));
    if (is_indexed(static_cast<TexFormat>(t.format))) {
      // TexTLUT 0x98 + map: the palette's TMEM offset 0-9, format 10-11 [DHW BPMemory.h TexTLUT].
      const u32 tlut = r.bp[static_cast<size_t>(0x98 + offset)];
      t.tlut_offset = static_cast<u16>(field(tlut, 0, 10));
      t.tlut_format = static_cast<u8>(field(tlut, 10, 2));
    }
    s.textures[static_cast<size_t>(m)] = t;
    out.texture_addresses[static_cast<size_t>(m)] = r.bp[static_cast<size_t>(0x94 + offset)] << 5;
  }
  // XF: channels.
  s.lighting.num_channels = static_cast<int>(r.xf(0x1009));  // must agree with genmode
  for (u32 c = 0; c < 2; ++c) {
    s.lighting.ambient[c] = xf_color(r.xf(0x100a + c));
    s.lighting.material[c] = xf_color(r.xf(0x100c + c));
  }
  for (u32 c = 0; c < 4; ++c) {
    const u32 w = r.xf(0x100e + c);
    ChannelControl& ctl = s.lighting.control[c];
    ctl.material_source = static_cast<u8>(field(w, 0, 1));
    ctl.lighting = field(w, 1, 1) != 0;
    ctl.light_mask = static_cast<u8>(field(w, 2, 4) | (field(w, 11, 4) << 4));
    ctl.ambient_source = static_cast<u8>(field(w, 6, 1));
    ctl.diffuse_fn = static_cast<u8>(field(w, 7, 2));
    ctl.attenuation_fn = !field(w, 9, 1) ? 2 : field(w, 10, 1) ? 1 : 0;  // NONE, SPOT, SPEC
  }
  for (u32 i = 0; i < kMaxLights; ++i) {
    const u32 base = 0x600 + 16 * i;
    XfLight& l = s.lighting.lights[i];
    l.color = xf_color(r.xf_memory[base + 3]);
    for (u32 j = 0; j < 3; ++j) {
      l.a[j] = xf_float(r, base + 4 + j);
      l.k[j] = xf_float(r, base + 7 + j);
    }
    l.position = {xf_float(r, base + 10), xf_float(r, base + 11), xf_float(r, base + 12)};
    l.direction = {xf_float(r, base + 13), xf_float(r, base + 14), xf_float(r, base + 15)};
  }
  // XF: texgens, their matrix indices (XF 0x1018 / 0x1019) and the texture matrices.
  s.texgen.num_texgens = static_cast<int>(r.xf(0x103f));
  const u32 idx_a = r.xf(0x1018), idx_b = r.xf(0x1019);
  for (u32 g = 0; g < kMaxTexGens; ++g) {
    const u32 w = r.xf(0x1040 + g);
    TexGen& t = s.texgen.texgens[g];
    t.type = field(w, 1, 1) ? 0 : 1;  // STQ: GX_TG_MTX3x4 (0); ST: GX_TG_MTX2x4 (1)
    const u32 row = field(w, 7, 5);
    t.source = static_cast<u8>(row == 0 ? 0 : row == 1 ? 1 : row - 1);
    t.matrix = static_cast<u8>(g < 4 ? field(idx_a, 6 + 6 * g, 6) : field(idx_b, 6 * (g - 4), 6));
  }
  s.texgen.matrices = {};
  for (u32 id = 30; id <= 60; id += 3)
    for (u32 row = 0; row < 3; ++row)
      for (u32 c = 0; c < 4; ++c)
        s.texgen.matrices[id / 3][row][c] = xf_float(r, 4 * id + 4 * row + c);
  // CP: descriptor and the texture coordinate formats of the draw's VAT.
  const u32 lo = r.cp[0x50], hi = r.cp[0x60];
  s.vertex = {};
  s.vertex.type[kVaPos] = static_cast<u8>(field(lo, 9, 2));
  s.vertex.type[kVaNrm] = static_cast<u8>(field(lo, 11, 2));
  s.vertex.type[kVaClr0] = static_cast<u8>(field(lo, 13, 2));
  s.vertex.type[kVaClr1] = static_cast<u8>(field(lo, 15, 2));
  for (int n = 0; n < kMaxTexGens; ++n)
    s.vertex.type[static_cast<size_t>(kVaTex0 + n)] = static_cast<u8>(field(hi, 2 * n, 2));
  const u32 vat_a = r.cp[0x70 + vat], vat_b = r.cp[0x80 + vat], vat_c = r.cp[0x90 + vat];
  const u32 st[8] = {field(vat_a, 21, 1), field(vat_b, 0, 1),  field(vat_b, 9, 1),
                     field(vat_b, 18, 1), field(vat_b, 27, 1), field(vat_c, 5, 1),
                     field(vat_c, 14, 1), field(vat_c, 23, 1)};
  for (size_t n = 0; n < 8; ++n)
    s.texcoord_formats.kind[n] = st[n] ? TexCoordFormats::ST : TexCoordFormats::S;
  return out;
}

GxState canonical_state(const GxState& in, const TextureObject* map0_fallback) {
  GxState s = in;
  for (TevStage& st : s.tev.stages) {
    if (st.channel == kColorNull) st.channel = 6;
    if (st.texcoord == kTexCoordNull) st.texcoord = 0;
  }
  s.vertex = sent_attributes(in);
  s.texcoord_formats = sent_formats(in.texcoord_formats);
  if (!s.textures[0] && map0_fallback) s.textures[0] = *map0_fallback;
  for (auto& t : s.textures)
    if (t) {
      t->data.clear();
      t->levels = 1;  // the registers hold no level count: the LOD range says what is read
      TextureLod plain;
      plain.min_filter = t->linear ? 4 : 0;
      if (t->lod && *t->lod == plain) t->lod.reset();
      t->tlut.clear();  // in memory, loaded by BP_LOADTLUT1; the register holds where and how
    }
  for (size_t i = 0; i < 10; ++i) s.texgen.matrices[i] = {};
  return s;
}

}  // namespace lt::gx::fifo
