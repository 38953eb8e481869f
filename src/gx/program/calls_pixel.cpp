// The pixel engine, texture object, vertex format and cache calls.
#include <algorithm>
#include <optional>
#include <tuple>

#include "gx/program/machine.h"
#include "gx/program/vertex_declarations.h"
#include "gx/texture_format.h"
#include "gx/texture_lod.h"
#include "gx/tmem.h"

namespace lt::gx::interp {

namespace {

// GX_InitTexObj's and GX_InitTexObjCI's shared arguments 0..7 (object, image, width, height,
// format, wraps, mipmap) into the object, the image checked to hold the format's tiles. With
// mipmap GX_TRUE the image holds as many levels as its bytes take (mip_chain_bytes), each half
// the size of the one before: the size must be a power of two (the console halves the size
// registers, and Dolphin's level addressing [DSW TextureSampler.cpp SampleMip] rounds no level
// to whole tiles but the first: both agree only there); GX_LoadTexObj then checks the levels
// against the LOD range.
void init_texture_object(Machine& m) {
  TexObject& t = m.tex(0);
  t.array = m.name(1);
  t.texture = TextureObject{};
  t.texture.width = static_cast<int>(m.i(2));
  t.texture.height = static_cast<int>(m.i(3));
  t.texture.format = m.u(4);
  t.texture.wrap_s = m.u(5);
  t.texture.wrap_t = m.u(6);
  t.texture.linear = true;  // linear mag (and min without mipmaps) [OGC gx.c L3236-3247]
  t.initialised = true;
  t.tlut_name = -1;
  const size_t need = tiled_size(t.texture.format, t.texture.width, t.texture.height);
  if (m.bytes(1).size() < need)
    m.fail_arg(1, m.name(1) + " holds " + std::to_string(m.bytes(1).size()) +
                      " bytes, the texture needs " + std::to_string(need));
  if (!m.b(7)) return;
  const int w = t.texture.width, h = t.texture.height;
  if ((w & (w - 1)) != 0 || (h & (h - 1)) != 0)
    m.fail_arg(2, "a mipmapped texture's size must be a power of two, found " + std::to_string(w) +
                      "x" + std::to_string(h));
  const auto format = static_cast<TexFormat>(t.texture.format);
  t.texture.lod = mipmapped_texture_lod(is_indexed(format));
  int levels = 1;
  while (levels < full_mip_levels(w, h) &&
         mip_chain_bytes(format, w, h, levels + 1) <= m.bytes(1).size())
    ++levels;
  t.texture.levels = levels;
}

// The LOD range a loaded texture's sampler can reach must lie in its image's levels (on the
// console a LOD past them reads whatever memory follows).
void check_lod_levels(const Machine& m, const TexObject& t) {
  if (!t.texture.lod) return;
  const int reach = reachable_levels(*t.texture.lod);
  if (reach <= t.texture.levels) return;
  const auto levels_of = [](u8 lod) {  // u4.4: whole levels and sixteenths
    return std::to_string(lod >> 4) + ((lod & 15) ? " " + std::to_string(lod & 15) + "/16" : "");
  };
  m.fail_arg(0, m.name(0) + "'s LOD range (min " + levels_of(t.texture.lod->min_lod) + ", max " +
                    levels_of(t.texture.lod->max_lod) + ") reads " + std::to_string(reach) +
                    " levels, " + t.array + " holds " + std::to_string(t.texture.levels) + " (" +
                    std::to_string(m.bytes_of(t.array).size()) + " bytes)");
}

// GX_REPEAT on a side that is not a power of two: the texture unit wraps a coordinate by masking
// it with the size minus one [DSW TextureSampler.cpp WrapCoord, quoting YAGCD], which repeats
// only a power of two (W = 3 reads texels 0, 0, 2, 2, ...), so the picture would not be the
// repeated image the program asks for (issue 47 "Bad input"). Checked at the load: the wrap can
// change after GX_InitTexObj (GX_InitTexObjWrapMode) and TPL_GetTexture takes the TPL's.
void check_repeat_sizes(const Machine& m, const TexObject& t) {
  constexpr u8 kRepeat = 1;  // GX_REPEAT
  for (const auto& [wrap, size, axis] : {std::tuple{t.texture.wrap_s, t.texture.width, "s"},
                                         std::tuple{t.texture.wrap_t, t.texture.height, "t"}}) {
    if (wrap == kRepeat && (size & (size - 1)) != 0)
      m.fail_arg(0, m.name(0) + " repeats in " + axis + " (GX_REPEAT) over " +
                        std::to_string(size) + " texels of " + t.array +
                        ": repeat needs a power of two (the console masks the coordinate "
                        "with the size minus one)");
  }
}

// The LOD fields a single-field setter writes into: the object's own, or, for an object that
// has none yet (no mipmaps, min filter = mag filter), GX_InitTexObj's, whose min filter is the
// mag filter (linear unless GX_InitTexObjFilterMode made both GX_NEAR).
TextureLod& lod_fields(TextureObject& t) {
  if (!t.lod) {
    t.lod = TextureLod{};
    t.lod->min_filter = t.linear ? 4 : 0;
  }
  return *t.lod;
}

// libogc's single-field LOD setters, each one field of GX_InitTexObjLOD's with its conversion
// [OGC gx.c L3361-3407]: GX_InitTexObjMinLOD and MaxLOD clamp to 0..10 and store 16 * lod
// (TX_SETMODE1), LODBias clamps to -4 (4.0 as 3.99) and stores 32 * bias, BiasClamp, EdgeLOD
// (stored inverted: the register's bit is "diagonal") and MaxAniso one bit field each of
// TX_SETMODE0. Each takes its field from libogc_texture_lod, the conversion GX_InitTexObjLOD's
// reading shares, so the two cannot disagree.
void add_lod_field_calls(CallTable& table) {
  using K = ParamKind;
  using G = NameGroup;
  const Param tex_p = of(K::TexRef);
  // GX_InitTexObjLOD's conversions of (minlod, maxlod, lodbias, biasclamp, edgelod, maxaniso).
  const auto conversion = [](float minlod, float maxlod, float bias, bool biasclamp, bool edgelod,
                             int aniso) {
    return libogc_texture_lod(0, minlod, maxlod, bias, biasclamp, edgelod, aniso);
  };
  table.insert({
      {"GX_InitTexObjMinLOD",
       {{tex_p, f32()},
        [conversion](Machine& m) {
          lod_fields(m.tex(0).texture).min_lod = conversion(m.f(1), 0, 0, false, true, 0).min_lod;
        }}},
      {"GX_InitTexObjMaxLOD",
       {{tex_p, f32()},
        [conversion](Machine& m) {
          lod_fields(m.tex(0).texture).max_lod = conversion(0, m.f(1), 0, false, true, 0).max_lod;
        }}},
      {"GX_InitTexObjLODBias",
       {{tex_p, f32()},
        [conversion](Machine& m) {
          lod_fields(m.tex(0).texture).bias = conversion(0, 0, m.f(1), false, true, 0).bias;
        }}},
      {"GX_InitTexObjBiasClamp",
       {{tex_p, integer(G::Bool, 0, 1)},
        [conversion](Machine& m) {
          lod_fields(m.tex(0).texture).bias_clamp = conversion(0, 0, 0, m.b(1), true, 0).bias_clamp;
        }}},
      {"GX_InitTexObjEdgeLOD",
       {{tex_p, integer(G::Bool, 0, 1)},
        [conversion](Machine& m) {
          lod_fields(m.tex(0).texture).diagonal = conversion(0, 0, 0, false, m.b(1), 0).diagonal;
        }}},
      {"GX_InitTexObjMaxAniso",
       {{tex_p, integer(G::Anisotropy, 0, 2)},
        [conversion](Machine& m) {
          lod_fields(m.tex(0).texture).max_aniso =
              conversion(0, 0, 0, false, true, static_cast<int>(m.i(1))).max_aniso;
        }}},
  });
}

// The largest palette index a colour-indexed image's bytes hold (padding texels included: the
// sampler can fetch them at the edges): CI4 a nibble, CI8 a byte, CI14X2 a big-endian u16's low
// 14 bits [DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel, case CI14X2 `& 0x3FFF`].
int largest_index(TexFormat format, const std::vector<u8>& bytes, size_t size) {
  int top = 0;
  for (size_t i = 0; i < size; ++i) {
    if (format == TexFormat::CI4) {
      top = std::max({top, bytes[i] >> 4, bytes[i] & 0xf});
    } else if (format == TexFormat::CI8) {
      top = std::max(top, static_cast<int>(bytes[i]));
    } else if (i % 2 == 0) {
      top = std::max(top, ((bytes[i] << 8) | bytes[i + 1]) & 0x3fff);
    }
  }
  return top;
}

}  // namespace

void add_pixel_calls(CallTable& table) {
  add_lod_field_calls(table);
  using K = ParamKind;
  using G = NameGroup;
  const Param tex_p = of(K::TexRef);
  table.insert({
      // --- Pixel engine [OGC gx.h L2810, L2882, L3106] ---
      {"GX_SetAlphaCompare",
       {{integer(G::Compare, 0, 7), integer(G::Number, 0, 255), integer(G::AlphaOp, 0, 3),
         integer(G::Compare, 0, 7), integer(G::Number, 0, 255)},
        [](Machine& m) {
          m.state.alpha_compare = {m.u(0), m.u(1), m.u(2), m.u(3), m.u(4)};
        }}},
      {"GX_SetBlendMode",
       {{integer(G::BlendMode, 0, 3), integer(G::BlendFactor, 0, 7), integer(G::BlendFactor, 0, 7),
         integer(G::LogicOp, 0, 15)},
        [](Machine& m) {
          m.state.blend = {m.u(0), m.u(1), m.u(2), m.u(3)};
        }}},
      // The colour formats Dolphin's software renderer stores (efb.h); the others keep no colour
      // (Z24) or are the YUV copies' formats, which the emulator does not model.
      {"GX_SetPixelFmt",
       {{integer(G::PixelFormat, 0, 7), integer(G::ZFormat, 0, 3)},
        [](Machine& m) {
          if (m.u(0) > kPixelRgb565Z16)
            m.fail_arg(0,
                       "pixel format not modelled (GX_PF_RGB8_Z24, GX_PF_RGBA6_Z24 and "
                       "GX_PF_RGB565_Z16 are)");
          m.state.pixel_format = {m.u(0), m.u(1)};
        }}},
      {"GX_SetDither", {{integer(G::Bool, 0, 1)}, [](Machine& m) { m.state.dither = m.b(0); }}},
      // Every mode is modelled: the rasteriser culls as the setup unit does (gx_state.h).
      {"GX_SetCullMode",
       {{integer(G::CullMode, 0, 3)},
        [](Machine& m) {
          m.state.cull_mode = m.u(0);
          m.state.cull_mode_line = m.line();  // named when the mode culls a whole pass
        }}},
      // Visibility comes from one depth buffer shared by every pass (the first pass's depth, as
      // an EQUAL/LEQUAL test without update gives on hardware), so only those modes are modelled.
      {"GX_SetZMode",
       {{integer(G::Bool, 0, 1), integer(G::Compare, 0, 7), integer(G::Bool, 0, 1)},
        [](Machine& m) {
          if (!m.b(0) || (m.i(1) != 1 && m.i(1) != 2 && m.i(1) != 3))
            m.fail_call(
                "only an enabled depth test with GX_LESS, GX_EQUAL or GX_LEQUAL is "
                "modelled (passes resolve visibility on one shared depth buffer)");
          m.state.z = {m.b(0), m.u(1), m.b(2)};
        }}},
      // --- Textures [OGC gx.h L4174-4459] ---
      {"GX_InitTexObj",
       {{tex_p, of(K::ArrayName), integer(G::Number, 1, 1024), integer(G::Number, 1, 1024),
         integer(G::TexFormat, 0, 14), integer(G::TexWrap, 0, 2), integer(G::TexWrap, 0, 2),
         integer(G::Bool, 0, 1)},
        [](Machine& m) {
          // Every direct format is decoded (texture_decoder.h); a colour-indexed one is
          // GX_InitTexObjCI's, with its TLUT.
          const std::optional<TexFormat> format = tex_format_from_number(static_cast<int>(m.u(4)));
          if (!format)
            m.fail_arg(4,
                       "texture format not modelled (GX_TF_I4, GX_TF_I8, GX_TF_IA4, GX_TF_IA8, "
                       "GX_TF_RGB565, GX_TF_RGB5A3, GX_TF_RGBA8 and GX_TF_CMPR are)");
          if (is_indexed(*format))
            m.fail_arg(4, "a colour-indexed format needs GX_InitTexObjCI (and its TLUT)");
          init_texture_object(m);
        }}},
      // A colour-indexed texture [OGC gx.c GX_InitTexObjCI L3301-3308]: GX_InitTexObj's
      // arguments and the TLUT (GX_TLUT0..GX_BIGTLUT3) whose palette it reads when loaded.
      {"GX_InitTexObjCI",
       {{tex_p, of(K::ArrayName), integer(G::Number, 1, 1024), integer(G::Number, 1, 1024),
         integer(G::TexFormat, 0, 14), integer(G::TexWrap, 0, 2), integer(G::TexWrap, 0, 2),
         integer(G::Bool, 0, 1), integer(G::TlutName, 0, kTlutNames - 1)},
        [](Machine& m) {
          const std::optional<TexFormat> format = tex_format_from_number(static_cast<int>(m.u(4)));
          if (!format || !is_indexed(*format))
            m.fail_arg(4, "GX_InitTexObjCI takes GX_TF_CI4, GX_TF_CI8 or GX_TF_CI14");
          init_texture_object(m);
          m.tex(0).tlut_name = static_cast<int>(m.i(8));
        }}},
      // GX_InitTlutObj(obj, lut, fmt, entries) [OGC gx.c L3421-3431]: the palette array (2 bytes
      // an entry, big-endian) and its format.
      {"GX_InitTlutObj",
       {{of(K::TlutRef), of(K::ArrayName), integer(G::TlutFormat, 0, 2),
         integer(G::Number, 1, 16384)},
        [](Machine& m) {
          const size_t need = static_cast<size_t>(m.i(3)) * 2;
          if (m.bytes(1).size() < need)
            m.fail_arg(1, m.name(1) + " holds " + std::to_string(m.bytes(1).size()) + " bytes, " +
                              std::to_string(m.i(3)) + " TLUT entries need " +
                              std::to_string(need));
          m.tlut(0) = {m.name(1), m.u(2), static_cast<int>(m.i(3)), true};
        }}},
      // GX_LoadTlut(obj, name) [OGC gx.c L3648-3663]: the palette into the named TLUT region
      // (gx/tmem.h tlut_region), which holds 256 entries (GX_TLUT0..15) or 1,024 (GX_BIGTLUT*).
      {"GX_LoadTlut",
       {{of(K::TlutRef), integer(G::TlutName, 0, kTlutNames - 1)},
        [](Machine& m) {
          const TlutObject& t = m.tlut(0);
          if (!t.initialised) m.fail_arg(0, m.name(0) + " was never given to GX_InitTlutObj");
          const TlutRegion region = tlut_region(static_cast<int>(m.i(1)));
          if (t.entries > region.entries)
            m.fail_arg(1, m.text(1) + " holds " + std::to_string(region.entries) +
                              " entries, the TLUT has " + std::to_string(t.entries));
          const std::vector<u8>& src = m.bytes_of(t.array);
          m.loaded_tluts[static_cast<int>(m.i(1))] = {
              std::vector<u8>(src.begin(), src.begin() + t.entries * 2), t.format};
        }}},
      {"GX_InitTexObjWrapMode",
       {{tex_p, integer(G::TexWrap, 0, 2), integer(G::TexWrap, 0, 2)},
        [](Machine& m) {
          m.tex(0).texture.wrap_s = m.u(1);
          m.tex(0).texture.wrap_t = m.u(2);
        }}},
      // GX_InitTexObjFilterMode [OGC gx.c L3358-3364]: the min filter (through _gx2HWFiltConv)
      // and the mag filter, the other LOD fields kept.
      {"GX_InitTexObjFilterMode",
       {{tex_p, integer(G::TexFilter, 0, 5), integer(G::TexFilter, 0, 1)},
        [](Machine& m) {
          TextureObject& t = m.tex(0).texture;
          const TextureLod filters =
              libogc_texture_lod(static_cast<int>(m.i(1)), 0, 0, 0, false, true, 0);
          const bool mag_linear = m.i(2) == 1;
          if (!t.lod && filters.min_filter == (mag_linear ? 4 : 0)) {
            t.linear = mag_linear;  // min = mag without mipmaps: no LOD fields needed
            return;
          }
          if (!t.lod) t.lod = TextureLod{};
          t.lod->min_filter = filters.min_filter;
          t.linear = mag_linear;
        }}},
      // GX_InitTexObjLOD [OGC gx.c L3310-3334] (texture_lod.h libogc_texture_lod).
      {"GX_InitTexObjLOD",
       {{tex_p, integer(G::TexFilter, 0, 5), integer(G::TexFilter, 0, 1), f32(), f32(), f32(),
         integer(G::Bool, 0, 1), integer(G::Bool, 0, 1), integer(G::Anisotropy, 0, 2)},
        [](Machine& m) {
          TextureObject& t = m.tex(0).texture;
          t.lod = libogc_texture_lod(static_cast<int>(m.i(1)), m.f(3), m.f(4), m.f(5), m.b(6),
                                     m.b(7), static_cast<int>(m.i(8)));
          t.linear = m.i(2) == 1;
        }}},
      {"GX_LoadTexObj",
       {{tex_p, integer(G::TexMap, 0, 7)},
        [](Machine& m) {
          TexObject& t = m.tex(0);
          if (!t.initialised) m.fail_arg(0, m.name(0) + " was never given to GX_InitTexObj");
          check_lod_levels(m, t);
          check_repeat_sizes(m, t);
          TextureObject loaded = t.texture;
          const size_t image_bytes = mip_chain_bytes(static_cast<TexFormat>(loaded.format),
                                                     loaded.width, loaded.height, loaded.levels);
          if (t.tlut_name >= 0) {
            // The palette loaded in the texture's TLUT region now (TMEM holds it from then on).
            const auto tlut = m.loaded_tluts.find(t.tlut_name);
            if (tlut == m.loaded_tluts.end())
              m.fail_arg(0, m.name(0) + "'s TLUT " + std::to_string(t.tlut_name) +
                                " was never loaded (GX_LoadTlut)");
            const int top = largest_index(static_cast<TexFormat>(loaded.format),
                                          m.bytes_of(t.array), image_bytes);
            if (static_cast<size_t>(top) * 2 >= tlut->second.bytes.size())
              m.fail_arg(0, t.array + " holds palette index " + std::to_string(top) + ", TLUT " +
                                std::to_string(t.tlut_name) + " has " +
                                std::to_string(tlut->second.bytes.size() / 2) + " entries");
            loaded.tlut = tlut->second.bytes;
            loaded.tlut_format = tlut->second.format;
            loaded.tlut_offset = static_cast<u16>(tlut_tmem_offset(tlut_region(t.tlut_name)));
          }
          const std::vector<u8>& src = m.bytes_of(t.array);
          loaded.data.assign(src.begin(), src.begin() + static_cast<std::ptrdiff_t>(image_bytes));
          m.state.textures[m.u(1)] = std::move(loaded);
        }}},
      // Cache maintenance: the emulator's memory is always coherent, so these change nothing;
      // they are accepted because code for the console must call them (gx-hardware.md §3.4).
      {"GX_InvalidateTexAll", {{}, [](Machine&) {}}},
      {"DCFlushRange", {{of(K::ArrayName), integer(G::Number, 0, 1 << 24)}, [](Machine&) {}}},
      // --- Vertex format [OGC gx.h L1781, L1955, L1985] ---
      {"GX_ClearVtxDesc", {{}, [](Machine& m) { clear_vertex_inputs(m); }}},
      // Every input a stored mesh has: GX_DIRECT, or GX_INDEX8 / GX_INDEX16 for every attribute
      // alike (the :draw= axis's indexed draws give each attribute the index its array needs:
      // paths/gx/program_storage.h).
      {"GX_SetVtxDesc",
       {{integer(G::VtxAttr, 9, kVaNbt), integer(G::VtxAttrType, 0, 3)},
        [](Machine& m) { set_vertex_input(m); }}},
      // GX_SetArray(attr, array, stride) [OGC gx.h L1929]: the array holds the scene's mesh as
      // stored; its stride is checked against the declared storage (paths/gx/program_storage.h).
      {"GX_SetArray",
       {{integer(G::VtxAttr, 9, kVaNbt), of(K::MeshArray), integer(G::Number, 0, kMaxArrayStride)},
        [](Machine& m) { set_vertex_array(m); }}},
      {"GX_SetVtxAttrFmt",
       {{integer(G::VtxFmt, 0, 7), integer(G::VtxAttr, 9, kVaNbt), integer(G::CompCount, 0, 2),
         integer(G::CompType, 0, 5), integer(G::Number, 0, 31)},
        [](Machine& m) { set_vertex_attribute_format(m); }}},
  });
}

}  // namespace lt::gx::interp
