#include "paths/gx/program_check.h"

#include "core/error.h"

namespace lt::gx {

void check_renderable(const PassProgram& p, const std::string& file, bool has_lut_fallback,
                      bool has_uvs) {
  const GxState& st = p.state;
  auto fail = [&](const std::string& what) { throw InputError(file, p.name, what); };
  // A program that declares no vertex format gets the whole stream (gx.md §1's example has
  // none); one that declares it must declare what it reads.
  const bool declared = st.vertex.count() > 0;
  auto sent = [&](int attribute) { return !declared || st.vertex.has(attribute); };
  if (declared && !st.vertex.has(kVaPos)) fail("the vertex format has no GX_VA_POS");
  // Over the hardware's counts the console would wrap the register field; `ltrender budget`
  // reports these as over the wii-tev profile.
  if (st.tev.num_stages > kMaxTevStages)
    fail(std::to_string(st.tev.num_stages) + " TEV stages: the hardware has 16");
  if (st.lighting.num_channels > kMaxChannels)
    fail(std::to_string(st.lighting.num_channels) + " colour channels: the hardware has 2");
  if (st.texgen.num_texgens > kMaxTexGens)
    fail(std::to_string(st.texgen.num_texgens) + " texgens: the hardware has 8");
  // The XF is told only how many texture coordinates a vertex brings (libogc's __GX_XfVtxSpecs
  // writes their count to XF 0x1008 [OGC gx.c]), not which: a GX_VA_TEXn above a gap would
  // arrive as a lower one. Rather than guess the console's reading, a gap is refused.
  if (declared) {
    for (int n = 1; n < kMaxTexGens; ++n) {
      if (st.vertex.has(kVaTex0 + n) && !st.vertex.has(kVaTex0 + n - 1))
        fail("the vertex format has GX_VA_TEX" + std::to_string(n) + " but no GX_VA_TEX" +
             std::to_string(n - 1) +
             ": the XF receives texture coordinates by count, declare them from GX_VA_TEX0 up");
    }
  }
  for (int g = 0; g < st.texgen.num_texgens; ++g) {
    const TexGen& t = st.texgen.texgens[static_cast<size_t>(g)];
    const std::string which = "texgen GX_TEXCOORD" + std::to_string(g);
    if (t.source == 1 && !sent(kVaNrm))
      fail(which + " reads the normal, but the vertex format has no GX_VA_NRM");
    if (t.source < 4) continue;
    const int n = t.source - 4;  // GX_TG_TEXn
    const std::string attribute = "GX_VA_TEX" + std::to_string(n);
    if (!sent(kVaTex0 + n))
      fail(which + " reads GX_TG_TEX" + std::to_string(n) + ", but the vertex format has no " +
           attribute);
    if (st.texcoord_formats.is_uv(n) && !has_uvs)
      fail(which + " reads the mesh's UVs (" + attribute +
           " as GX_TEX_ST), but a mesh of this material has none");
  }
  for (int c = 0; c < st.lighting.num_channels; ++c) {
    for (int part : {c, c + 2}) {  // colour and alpha control of channel c
      const ChannelControl& ctl = st.lighting.control[static_cast<size_t>(part)];
      const bool reads_vertex =
          ctl.material_source == 1 || (ctl.lighting && ctl.ambient_source == 1);
      if (!reads_vertex) continue;
      // The scene's one vertex colour may go in GX_VA_CLR0, GX_VA_CLR1 or both (stored alike).
      // A colour sent alone feeds channel 0, and channel 1 then gets no vertex colour [DSW
      // SWVertexLoader.cpp ParseColorAttributes: "If only one of the color attributes is
      // enabled, it is directed to color 0"].
      // (A program that declares no format gets CLR0 alone: cp_registers.h sent_attributes.)
      if (c == 1 && !(st.vertex.has(kVaClr0) && st.vertex.has(kVaClr1)))
        fail(
            "channel GX_COLOR1A1 reads a vertex colour, but the vertex format sends one colour, "
            "which feeds GX_COLOR0A0: send GX_VA_CLR1 beside GX_VA_CLR0");
      if (!sent(kVaClr0) && !sent(kVaClr1))
        fail(
            "channel GX_COLOR0A0 reads a vertex colour, but the vertex format has no GX_VA_CLR0 "
            "or GX_VA_CLR1");
    }
    const ChannelControl& ctl = st.lighting.control[static_cast<size_t>(c)];
    if (ctl.lighting && ctl.light_mask && !sent(kVaNrm) &&
        (ctl.diffuse_fn != 0 || ctl.attenuation_fn == 0))
      fail("lighting needs the normal, but the vertex format has no GX_VA_NRM");
  }
  for (int s = 0; s < st.tev.num_stages; ++s) {
    const u8 map = st.tev.stages[static_cast<size_t>(s)].texmap;
    if (map == kTexMapNull || st.textures[map] || (map == 0 && has_lut_fallback)) continue;
    fail("TEV stage " + std::to_string(s) + " fetches GX_TEXMAP" + std::to_string(map) +
         ", which holds no texture (GX_TEXMAP0 holds the material's LUT unless the program loads "
         "one)");
  }
}

}  // namespace lt::gx
