#include "gx/fifo/bp_registers.h"

#include "gx/clipper.h"
#include "gx/fifo/display_copy.h"
#include "gx/texture_format.h"
#include "gx/tmem.h"

namespace lt::gx::fifo {

namespace {

// libogc's hardware value of a TEV order's colour channel: GX_COLOR0A0 (4) -> 0, GX_COLOR1A1 (5)
// -> 1, GX_COLORZERO (6) -> 7; GX_COLORNULL writes GX_ALPHA_BUMP's 7 too, the zero channel
// [OGC gx.c L101 _gxtevcolid, L4003-4004] [DHW BPMemory.h RasColorChan: 7 = Zero].
u32 channel_id(u8 channel) {
  static constexpr u8 kTevColorId[9] = {0, 1, 0, 1, 0, 1, 7, 5, 6};
  return channel == kColorNull || channel > 8 ? 7u : kTevColorId[channel];
}

// One half of a TEV order: texmap 3 bits, texcoord 3 bits, map enable 1 bit, channel 3 bits, at
// 0 (even stage) or 12 (odd stage) [OGC gx.c GX_SetTevOrder L3988-4031] [DHW BPMemory.h
// TwoTevStageOrders]. A null texmap writes map 0 with enable 0; a null texcoord writes 0.
u32 order_half(const TevStage& s) {
  const bool map = s.texmap != kTexMapNull;
  return place(map ? s.texmap : 0, 0, 3) | place(s.texcoord < kMaxTexGens ? s.texcoord : 0, 3, 3) |
         place(map, 6, 1) | place(channel_id(s.channel), 7, 3);
}

// The fields GX_SetTevColorOp / GX_SetTevAlphaOp write, bits 16-23 of both combiners: bias
// 16-17 (3 on a compare stage), op / compare 18, clamp 19, scale / compare mode 20-21, dest
// 22-23 [OGC gx.c L3893-3927] [DHW BPMemory.h TevStageCombiner::ColorCombiner].
u32 combiner_op(const TevCombiner& c) {
  return place(c.bias, 16, 2) | place(c.op, 18, 1) | place(c.clamp, 19, 1) | place(c.scale, 20, 2) |
         place(c.dest, 22, 2);
}

// A texture cache region's register (TexImage1 even, TexImage2 odd): TMEM address >> 5 in bits
// 0-14, cache width 15-17 and height 18-20, 3 for 32 KiB [OGC gx.c GX_InitTexCacheRegion
// L3149-3191]; the region is libogc's default for the map and format (gx/tmem.h).
u32 tmem_region(u32 tmem_address) {
  return place(tmem_address >> 5, 0, 15) | place(3, 15, 3) | place(3, 18, 3);
}

}  // namespace

// genmode [OGC gx.c GX_SetNumTexGens L2937 bits 0-3, GX_SetNumChans L3982 bits 4-6,
// GX_SetNumTevStages L4033 bits 10-13 (count - 1), GX_SetCullMode L3929 bits 14-15 through
// cm2hw = {0, 2, 1, 3}, GX_SetNumIndStages bits 16-18 = 0, GX_SetCoPlanar bit 19 = 0,
// GX_SetPixelFmt bit 9 multisampling, set for GX_PF_RGB565_Z16 only] [DHW BPMemory.h GenMode].
u32 gen_mode(const GxState& s) {
  return place(static_cast<u32>(s.texgen.num_texgens), 0, 4) |
         place(static_cast<u32>(s.lighting.num_channels), 4, 3) |
         place(s.pixel_format.pixel == kPixelRgb565Z16, 9, 1) |
         place(static_cast<u32>(s.tev.num_stages - 1), 10, 4) |
         place(hardware_cull_mode(s.cull_mode), 14, 2);
}

// PE control: pixel format 0-2 (libogc's realfmt table maps GX_PF_RGB8_Z24..GX_PF_Z24 to
// themselves), z format 3-5, GX_SetZCompLoc(GX_TRUE) bit 6 [OGC gx.c GX_SetPixelFmt,
// GX_SetZCompLoc] [DHW BPMemory.h PEControl].
u32 pixel_control(const PixelFormat& f) {
  return place(f.pixel, 0, 3) | place(f.z, 3, 3) | place(1, 6, 1);
}

u32 tev_order(const TevState& tev, int pair) {
  return order_half(tev.stages[static_cast<size_t>(2 * pair)]) |
         (order_half(tev.stages[static_cast<size_t>(2 * pair + 1)]) << 12);
}

// Colour combiner: d 0-3, c 4-7, b 8-11, a 12-15 [OGC gx.c GX_SetTevColorIn L3871-3880].
u32 tev_color_env(const TevStage& s) {
  const TevCombiner& c = s.color;
  return place(c.d, 0, 4) | place(c.c, 4, 4) | place(c.b, 8, 4) | place(c.a, 12, 4) |
         combiner_op(c);
}

// Alpha combiner: ras swap 0-1, tex swap 2-3 [OGC gx.c GX_SetTevSwapMode L4068-4074], d 4-6,
// c 7-9, b 10-12, a 13-15 [OGC gx.c GX_SetTevAlphaIn L3882-3891].
u32 tev_alpha_env(const TevStage& s) {
  const TevCombiner& c = s.alpha;
  return place(s.ras_swap, 0, 2) | place(s.tex_swap, 2, 2) | place(c.d, 4, 3) | place(c.c, 7, 3) |
         place(c.b, 10, 3) | place(c.a, 13, 3) | combiner_op(c);
}

// GX_SetTevColorS10: RA = r (11 bits) | a << 12, BG = b | g << 12, bit 23 clear = a register
// [OGC gx.c L3790-3803] [DHW BPMemory.h TevReg].
std::array<u32, 2> tev_register(const ColorS10& v) {
  return {place(static_cast<u32>(v.r), 0, 11) | place(static_cast<u32>(v.a), 12, 11),
          place(static_cast<u32>(v.b), 0, 11) | place(static_cast<u32>(v.g), 12, 11)};
}

// GX_SetTevKColor: the same halves with 8-bit values and bit 23 set = a konst colour
// [OGC gx.c L3805-3818].
std::array<u32, 2> tev_konst(const Color8& v) {
  return {place(v.r, 0, 8) | place(v.a, 12, 8) | place(1, 23, 1),
          place(v.b, 0, 8) | place(v.g, 12, 8) | place(1, 23, 1)};
}

// BP 0xF6 + i: swap table i / 2's (r, g) for even i, (b, a) for odd i in bits 0-1 and 2-3
// [OGC gx.c GX_SetTevSwapModeTable L4076-4088]; stage 2i's konst colour select 4-8 and alpha
// select 9-13, stage 2i + 1's 14-18 and 19-23 [OGC gx.c GX_SetTevKColorSel L4046-4055,
// GX_SetTevKAlphaSel L4057-4066] [DHW BPMemory.h TevKSel].
u32 tev_konst_select(const TevState& tev, int i) {
  const auto& table = tev.swap_tables[static_cast<size_t>(i / 2)];
  const int first = (i & 1) ? 2 : 0;
  const TevStage& even = tev.stages[static_cast<size_t>(2 * i)];
  const TevStage& odd = tev.stages[static_cast<size_t>(2 * i + 1)];
  return place(table[static_cast<size_t>(first)], 0, 2) |
         place(table[static_cast<size_t>(first + 1)], 2, 2) | place(even.konst_color_sel, 4, 5) |
         place(even.konst_alpha_sel, 9, 5) | place(odd.konst_color_sel, 14, 5) |
         place(odd.konst_alpha_sel, 19, 5);
}

// ref0 0-7, ref1 8-15, comp0 16-18, comp1 19-21, op 22-23 [OGC gx.c GX_SetAlphaCompare
// L4039-4044] [DHW BPMemory.h AlphaTest].
u32 alpha_compare(const AlphaCompare& a) {
  return place(a.ref0, 0, 8) | place(a.ref1, 8, 8) | place(a.comp0, 16, 3) | place(a.comp1, 19, 3) |
         place(a.op, 22, 2);
}

// cmode0: blend enable 0 (GX_BM_BLEND or GX_BM_SUBTRACT), logic 1, dither 2, colour update 3,
// alpha update 4, dst factor 5-7, src factor 8-10, subtract 11, logic op 12-15 [OGC gx.c
// GX_SetBlendMode L3735-3751, GX_SetDither L4415, GX_SetColorUpdate / GX_SetAlphaUpdate
// L4377-4387] [DHW BPMemory.h BlendMode]. GX_Init enables dither and both updates; dithering
// only acts on the 6-bit pixel formats, not RGB8_Z24 [DHW BPMemory.h BlendMode::dither].
u32 blend_mode(const BlendMode& b, bool dither) {
  constexpr u8 kBlend = 1, kLogic = 2, kSubtract = 3;  // GX_BM_* [OGC gx.h]
  return place(b.type == kBlend || b.type == kSubtract, 0, 1) | place(b.type == kLogic, 1, 1) |
         place(dither, 2, 1) | place(1, 3, 1) | place(1, 4, 1) | place(b.dst, 5, 3) |
         place(b.src, 8, 3) | place(b.type == kSubtract, 11, 1) | place(b.logic, 12, 4);
}

// enable 0, function 1-3, update 4 [OGC gx.c GX_SetZMode L2948-2954] [DHW BPMemory.h ZMode].
u32 z_mode(const ZMode& z) {
  return place(z.enable, 0, 1) | place(z.func, 1, 3) | place(z.update, 4, 1);
}

// GX_InitTexObj [OGC gx.c L3226-3298] and GX_InitTexObjLOD [L3310-3334]: mode0 wrap s 0-1,
// wrap t 2-3, mag filter 4 (1 linear), min filter 5-7 (4 linear, 0 near, the mip filters 1, 2,
// 5, 6: _gx2HWFiltConv), diagonal LOD 8 (!edgelod), LOD bias 9-16 (s2.5), max anisotropy 19-20,
// bias clamp 21; mode1 min LOD 0-7, max LOD 8-15 (u4.4); without LOD fields (no mipmaps) the
// min filter is the mag filter and the rest zero. image0 width - 1 0-9, height - 1 10-19,
// format 20-23; image3 the physical address >> 5 [DHW BPMemory.h TexMode0, TexMode1, TexImage0,
// TexImage3]. image1 / image2: the TMEM region (tmem_region), a mipmapped texture's when it has
// levels past the first.
TextureRegisters texture_registers(const TextureObject& t, int map, u32 address) {
  TextureRegisters r{};
  TextureLod lod;
  lod.min_filter = t.linear ? 4 : 0;
  if (t.lod) lod = *t.lod;
  r.mode0 = place(t.wrap_s, 0, 2) | place(t.wrap_t, 2, 2) | place(t.linear, 4, 1) |
            place(lod.min_filter, 5, 3) | place(lod.diagonal, 8, 1) |
            place(static_cast<u8>(lod.bias), 9, 8) | place(lod.max_aniso, 19, 2) |
            place(lod.bias_clamp, 21, 1);
  r.mode1 = place(lod.min_lod, 0, 8) | place(lod.max_lod, 8, 8);
  r.image0 = place(static_cast<u32>(t.width - 1), 0, 10) |
             place(static_cast<u32>(t.height - 1), 10, 10) | place(t.format, 20, 4);
  const TexCacheRegion region =
      texture_cache_region(static_cast<TexFormat>(t.format), t.levels > 1, map);
  r.image1 = tmem_region(region.even);
  r.image2 = tmem_region(region.odd);
  r.image3 = place(address >> 5, 0, 24);
  // The TLUT register GX_LoadTexObj writes for a colour-indexed texture: the palette's TMEM
  // offset 0-9 and format 10-11 [OGC gx.c GX_LoadTlut L3661 tmem_addr_base,
  // GX_LoadTexObjPreloaded L3467-3472] [DHW BPMemory.h TexTLUT].
  r.tlut = place(t.tlut_offset, 0, 10) | place(t.tlut_format, 10, 2);
  return r;
}

// GX_LoadTlut [OGC gx.c L3648-3663]: the texture-state flush (__GX_FlushTextureState writes the
// indirect mask, 0xff since GX_Init [OGC gx.c L746-749]), BP_LOADTLUT0 with the palette's
// address >> 5, BP_LOADTLUT1 with its TMEM offset (0-9) and the lines of the whole region
// (10-20: libogc loads the region's size, gx/tmem.h tlut_region_entries_at), which copies it
// into TMEM [DHW BPStructs.cpp BPMEM_LOADTLUT1], the flush again.
void write_tlut_load(CommandStream& out, const TextureObject& t, u32 address) {
  const int entries = tlut_region_entries_at(t.tlut_offset);
  out.load_bp(bp::kIndirectMask, 0xff);
  out.load_bp(bp::kLoadTlut0, place(address >> 5, 0, 24));
  out.load_bp(bp::kLoadTlut1,
              place(t.tlut_offset, 0, 10) | place(static_cast<u32>(tlut_lines(entries)), 10, 11));
  out.load_bp(bp::kIndirectMask, 0xff);
}

void write_pass_bp(CommandStream& out, const GxState& s,
                   const std::array<const TextureObject*, kMaxTexMaps>& textures,
                   const std::array<u32, kMaxTexMaps>& addresses,
                   const std::array<u32, kMaxTexMaps>& tlut_addresses) {
  out.load_bp(bp::kGenMode, gen_mode(s));
  const TevState& tev = s.tev;
  for (int pair = 0; pair < kMaxTevStages / 2; ++pair)
    out.load_bp(static_cast<u8>(bp::kTevOrder0 + pair), tev_order(tev, pair));
  for (int st = 0; st < kMaxTevStages; ++st) {
    const TevStage& stage = tev.stages[static_cast<size_t>(st)];
    out.load_bp(static_cast<u8>(bp::kTevColorEnv0 + 2 * st), tev_color_env(stage));
    out.load_bp(static_cast<u8>(bp::kTevAlphaEnv0 + 2 * st), tev_alpha_env(stage));
  }
  // Registers first, konsts second, each as libogc sends it: RA, then BG three times (the two
  // extra writes "should obviously flush the Write Gather Pipe" [OGC gx.c L3785-3787]).
  auto write_pair = [&](int index, const std::array<u32, 2>& halves) {
    out.load_bp(static_cast<u8>(bp::kTevRegisterRA0 + 2 * index), halves[0]);
    for (int i = 0; i < 3; ++i)
      out.load_bp(static_cast<u8>(bp::kTevRegisterBG0 + 2 * index), halves[1]);
  };
  for (int r = 0; r < kTevRegisters; ++r)
    write_pair(r, tev_register(tev.registers[static_cast<size_t>(r)]));
  for (int k = 0; k < kMaxKonstColors; ++k)
    write_pair(k, tev_konst(tev.konst[static_cast<size_t>(k)]));
  for (int i = 0; i < 8; ++i)
    out.load_bp(static_cast<u8>(bp::kTevKonstSelect0 + i), tev_konst_select(tev, i));
  out.load_bp(bp::kAlphaCompare, alpha_compare(s.alpha_compare));
  out.load_bp(bp::kZMode, z_mode(s.z));
  out.load_bp(bp::kBlendMode, blend_mode(s.blend, s.dither));
  out.load_bp(bp::kPixelControl, pixel_control(s.pixel_format));
  // Texture maps: GX_LoadTexObj's six registers for every map that holds a texture, then the
  // setup unit's sizes of each texcoord an enabled stage fetches a map with (libogc's
  // __SetSURegs from __GX_SetSUTexRegs at the next draw: size - 1 in bits 0-15, the wrap's low
  // bit in 16 [OGC gx.c L848-867, L869-921]; gx_state.h texcoord_scales), then
  // GX_InvalidateTexAll [OGC gx.c L3605-3611].
  const auto scales = texcoord_scales(s, textures);
  for (int m = 0; m < kMaxTexMaps; ++m) {
    const TextureObject* t = textures[static_cast<size_t>(m)];
    if (!t) continue;
    const TextureRegisters r = texture_registers(*t, m, addresses[static_cast<size_t>(m)]);
    const bool indexed = is_indexed(static_cast<TexFormat>(t->format));
    if (indexed) write_tlut_load(out, *t, tlut_addresses[static_cast<size_t>(m)]);
    out.load_bp(bp::texture_register(bp::kTexMode0, m), r.mode0);
    out.load_bp(bp::texture_register(bp::kTexMode1, m), r.mode1);
    out.load_bp(bp::texture_register(bp::kTexImage0, m), r.image0);
    out.load_bp(bp::texture_register(bp::kTexImage1, m), r.image1);
    out.load_bp(bp::texture_register(bp::kTexImage2, m), r.image2);
    out.load_bp(bp::texture_register(bp::kTexImage3, m), r.image3);
    if (indexed) out.load_bp(bp::texture_register(bp::kTexTlut, m), r.tlut);
  }
  for (u32 coord = 0; coord < kMaxTexGens; ++coord) {
    const TexCoordScale& scale = scales[coord];
    if (scale.s == 0) continue;
    out.load_bp(static_cast<u8>(bp::kTexCoordSize0 + 2 * coord),
                place(scale.s - 1, 0, 16) | place(scale.wrap_s & 1, 16, 1));
    out.load_bp(static_cast<u8>(bp::kTexCoordSize0 + 2 * coord + 1),
                place(scale.t - 1, 0, 16) | place(scale.wrap_t & 1, 16, 1));
  }
  out.load_bp(bp::kTextureInvalidate, 0x001000, false);
  out.load_bp(bp::kTextureInvalidate, 0x001100, false);
}

void write_gx_init_bp(CommandStream& out, FrameSize size) {
  const u32 w = static_cast<u32>(size.width), h = static_cast<u32>(size.height);
  // GX_SetLineWidth(6, GX_TO_ZERO), GX_SetPointSize(6, GX_TO_ZERO): widths 0-7 and 8-15
  // [OGC gx.c GX_SetLineWidth, GX_SetPointSize].
  out.load_bp(bp::kLinePointWidth, place(6, 0, 8) | place(6, 8, 8));
  // GX_SetScissor(0, 0, w, h): top 0-10, left 12-22 of the corners, both offset by 342
  // [OGC gx.c L3957-3972]; GX_SetScissorBoxOffset(0, 0): (0 + 342) >> 1 in 0-9 and 10-19
  // [OGC gx.c L3974-3980] [DHW BPMemory.h ScissorPos, ScissorOffset].
  out.load_bp(bp::kScissorTopLeft, place(kScreenOffset, 0, 11) | place(kScreenOffset, 12, 11));
  out.load_bp(bp::kScissorBottomRight,
              place(kScreenOffset + h - 1, 0, 11) | place(kScreenOffset + w - 1, 12, 11));
  out.load_bp(bp::kScissorOffset,
              place(kScreenOffset >> 1, 0, 10) | place(kScreenOffset >> 1, 10, 10));
  // GX_Init's z mode and blend mode (GxState's defaults), so the frame's clearing copy - which
  // clears only what the colour update and z update bits let through [DHW BPStructs.cpp
  // BPMEM_TRIGGER_EFB_COPY, ClearScreen] - starts from them, as after GX_Init.
  out.load_bp(bp::kZMode, z_mode(ZMode{}));
  out.load_bp(bp::kBlendMode, blend_mode(BlendMode{}, GxState{}.dither));
  // GX_SetDstAlpha(GX_DISABLE, 0): constant alpha off [OGC gx.c GX_SetDstAlpha].
  out.load_bp(bp::kConstantAlpha, 0);
  // GX_SetPixelFmt(GX_PF_RGB8_Z24, GX_ZC_LINEAR), GX_SetZCompLoc(GX_TRUE) [OGC gx.c
  // L4389-4413].
  out.load_bp(bp::kPixelControl, pixel_control(PixelFormat{}));
  // GX_SetFieldMask(GX_ENABLE, GX_ENABLE): odd 0, even 1; GX_SetFieldMode(GX_FALSE, 0) for a
  // progressive mode [OGC gx.c L4428-4440, __GX_InitGX].
  out.load_bp(bp::kFieldMask, 3);
  out.load_bp(bp::kFieldMode, 0);
  // GX_SetFog(GX_FOG_NONE, ...): fog type (bits 21-23 of FOGPARAM3) 0 = off, colour black; the
  // other fog fields act only when fog is on [OGC gx.c GX_SetFog] [DHW BPMemory.h FogParam3].
  out.load_bp(bp::kFogParam3, 0);
  out.load_bp(bp::kFogColor, 0);
  // GX_SetZTexture(GX_ZT_DISABLE, GX_TF_Z8, 0): bias 0, op 2-3 = 0, format 0-1 = 0
  // [OGC gx.c L2777-2788].
  out.load_bp(bp::kZTextureBias, 0);
  out.load_bp(bp::kZTexture, 0);
  // GX_SetNumIndStages(0) (genmode), GX_SetTevDirect on every stage (IND_CMD n = 0), unit
  // scales GX_ITS_1 (0), and the indirect texture mask libogc keeps at 0xff [OGC gx.c
  // GX_SetTevIndirect, GX_SetIndTexCoordScale, GX_Init's tevIndMask].
  for (int st = 0; st < kMaxTevStages; ++st)
    out.load_bp(static_cast<u8>(bp::kIndirectStage0 + st), 0);
  out.load_bp(bp::kIndirectScale0, 0);
  out.load_bp(bp::kIndirectScale1, 0);
  out.load_bp(bp::kIndirectMask, 0xff);
  // __GX_InitRevBits: BP 0x58 = 0x0f [OGC gx.c L238-253].
  out.load_bp(bp::kRevisionBits, 0x0f);
  write_copy_filter(out, EfbCopyState{});  // GX_Init's [OGC gx.c __GX_InitGX L728]
}

void write_copy_clear(CommandStream& out, const Color8& c) {
  out.load_bp(bp::kClearAlphaRed, place(c.a, 8, 8) | place(c.r, 0, 8));
  out.load_bp(bp::kClearGreenBlue, place(c.g, 8, 8) | place(c.b, 0, 8));
  out.load_bp(bp::kClearZ, 0xffffff);
}

namespace {

// The copy with clear as GX_CopyDisp / GX_CopyTex send it: z mode forced to enable + ALWAYS
// (update kept), blend and logic off, z-compare-before-texture off while the copy clears,
// then source, size, stride, destination, the trigger, and the mirror's values restored
// [OGC gx.c L2010-2054, L2056-2097].
void write_clearing_copy(CommandStream& out, FrameSize size, u32 address, u32 stride, u32 trigger,
                         bool restore) {
  const u32 zmode = out.bp[bp::kZMode], cmode0 = out.bp[bp::kBlendMode];
  const u32 pe = out.bp[bp::kPixelControl];
  out.load_bp(bp::kZMode, (zmode & ~0xfu) | 0xf, false);
  out.load_bp(bp::kBlendMode, cmode0 & ~0x3u, false);
  if (pe & 0x40) out.load_bp(bp::kPixelControl, pe & ~0x40u, false);
  // Source origin 0-9 x, 10-19 y; size - 1 likewise [OGC gx.c GX_SetDispCopySrc L2002-2008].
  out.load_bp(bp::kCopySourceTopLeft, 0);
  out.load_bp(bp::kCopySourceSize, place(static_cast<u32>(size.width - 1), 0, 10) |
                                       place(static_cast<u32>(size.height - 1), 10, 10));
  out.load_bp(bp::kCopyStride, stride);
  out.load_bp(bp::kCopyDestination, place(address >> 5, 0, 24));
  out.load_bp(bp::kCopyTrigger, trigger, false);
  if (!restore) return;
  out.load_bp(bp::kZMode, zmode);
  out.load_bp(bp::kBlendMode, cmode0);
  if (pe & 0x40) out.load_bp(bp::kPixelControl, pe);
}

}  // namespace

// GX_SetTexCopyDst(w, h, GX_TF_RGBA8, GX_FALSE) + GX_CopyTex(dest, GX_TRUE): stride = 4x4 tiles
// across x 2 planes (RGBA8 keeps AR and GB in separate 32-byte halves); control: format 6 in
// bits 4-6 (bit 3 its high bit), auto conversion bit 16, clear bit 11, not to the XFB (bit 14
// clear), no gamma, no clamp [OGC gx.c L2105-2124, L2056-2097] [DHW BPMemory.h UPE_Copy].
void write_clearing_texture_copy(CommandStream& out, FrameSize size, u32 address) {
  const u32 stride = static_cast<u32>((size.width + 3) / 4) * 2;
  write_clearing_copy(out, size, address, stride,
                      place(6, 4, 3) | place(1, 11, 1) | place(1, 16, 1), true);
}

// GX_SetDispCopyDst(w, h): stride w / 16 (32-byte lines of YUYV) [OGC gx.c L1996-2000];
// GX_CopyDisp(xfb, GX_TRUE): the display copy control with clear (11) and copy-to-XFB (14)
// [OGC gx.c L2040-2044]. The frame ends at its trigger: Dolphin's FIFO player cuts a frame into
// parts at EFB copies and requires the last command to be one [DHW FifoPlayer.cpp AnalyzeFrames
// "The frame should end with an EFB copy"], so the restores GX_CopyDisp sends after it are left
// to the next frame, which writes every register again.
void write_display_copy(CommandStream& out, FrameSize size, u32 address) {
  const EfbCopyState copy{};  // what the exported program leaves: GX_Init's
  out.load_bp(bp::kCopyYScale, copy.y_scale);
  write_clearing_copy(out, size, address, static_cast<u32>(size.width) >> 4,
                      display_copy_control(copy) | place(1, 11, 1) | place(1, 14, 1), false);
}

}  // namespace lt::gx::fifo
