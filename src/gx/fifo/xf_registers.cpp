#include "gx/fifo/xf_registers.h"

#include <cmath>
#include <vector>

#include "gx/transform_unit.h"

namespace lt::gx::fifo {

namespace {
void load_floats(CommandStream& out, u32 address, const std::vector<float>& values) {
  std::vector<u32> words;
  for (float v : values) words.push_back(float_bits(v));
  out.load_xf(address, words);
}

std::vector<float> rows(const TexMatrix& m, int count) {
  std::vector<float> out;
  for (int r = 0; r < count; ++r)
    for (float v : m[static_cast<size_t>(r)]) out.push_back(v);
  return out;
}

// A GXColor as XF holds it: r << 24 | g << 16 | b << 8 | a [OGC gx.c GX_SetChanAmbColor].
u32 color_word(const Color8& c) {
  return place(c.r, 24, 8) | place(c.g, 16, 8) | place(c.b, 8, 8) | place(c.a, 0, 8);
}

// GX_LoadLightObj's 16 words [OGC gx.c L4587-4641]: 3 unused, colour, a0..a2, k0..k2,
// position, direction [DHW XFMemory.h Light].
std::array<u32, 16> light_words(const XfLight& l) {
  const float v[12] = {l.a[0],       l.a[1],        l.a[2],        l.k[0],
                       l.k[1],       l.k[2],        l.position.x,  l.position.y,
                       l.position.z, l.direction.x, l.direction.y, l.direction.z};
  std::array<u32, 16> w{};
  w[3] = color_word(l.color);
  for (int i = 0; i < 12; ++i) w[static_cast<size_t>(4 + i)] = float_bits(v[i]);
  return w;
}
}  // namespace

u32 channel_control(const ChannelControl& c) {
  return place(c.material_source, 0, 1) | place(c.lighting, 1, 1) | place(c.light_mask, 2, 4) |
         place(c.ambient_source, 6, 1) |
         place(c.attenuation_fn == kAttnSpec ? 0 : c.diffuse_fn, 7, 2) |
         place(c.attenuation_fn != kAttnNone, 9, 1) | place(c.attenuation_fn != kAttnSpec, 10, 1) |
         place(static_cast<u32>(c.light_mask) >> 4, 11, 4);
}

u32 texgen_word(const TexGen& t) {
  constexpr u8 kMtx3x4 = 0, kSourcePosition = 0, kSourceNormal = 1;  // GX_TG_* [OGC gx.h]
  const bool row_xyz = t.source == kSourcePosition || t.source == kSourceNormal;
  const u32 row = t.source == kSourcePosition ? 0u : t.source == kSourceNormal ? 1u : t.source + 1u;
  return place(t.type == kMtx3x4, 1, 1) | place(row_xyz, 2, 1) | place(row, 7, 5);
}

std::array<u32, 7> projection_words(const ViewTransform& t) {
  std::array<u32, 7> out{};
  for (size_t i = 0; i < 6; ++i) out[i] = float_bits(t.projection[i]);
  out[6] = t.orthographic ? 1 : 0;  // GX_PERSPECTIVE 0, GX_ORTHOGRAPHIC 1 [OGC gx.h]
  return out;
}

std::array<u32, 6> viewport_words(FrameSize size) {
  const Viewport v = frame_viewport(size);
  return {float_bits(v.wd),     float_bits(v.ht),     float_bits(v.z_range),
          float_bits(v.x_orig), float_bits(v.y_orig), float_bits(v.far_z)};
}

void write_pass_xf(CommandStream& out, const GxState& s) {
  const XfLightingState& l = s.lighting;
  out.load_xf(xf::kNumChannels, static_cast<u32>(l.num_channels));
  for (u32 c = 0; c < kMaxChannels; ++c) {
    out.load_xf(xf::kAmbient0 + c, color_word(l.ambient[c]));
    out.load_xf(xf::kMaterial0 + c, color_word(l.material[c]));
  }
  // COLOR0, COLOR1, ALPHA0, ALPHA1 at 0x100e..0x1011 [OGC gx.c __GX_SetChanCntrl L1009-1022].
  for (u32 c = 0; c < 4; ++c) out.load_xf(xf::kChannelControl0 + c, channel_control(l.control[c]));
  for (u32 i = 0; i < kMaxLights; ++i) {
    const auto w = light_words(l.lights[i]);
    out.load_xf(xf::kLights + xf::kLightWords * i, w);
  }
  const XfTexGenState& t = s.texgen;
  out.load_xf(xf::kNumTexGens, static_cast<u32>(t.num_texgens));
  // Each texgen and its post-transform row: GX_SetTexCoordGen's GX_DTTIDENTITY, no normalise
  // (normalise 8, post matrix 0-5) [OGC gx.c L2743-2745] [DHW XFMemory.h PostMtxInfo].
  for (u32 g = 0; g < kMaxTexGens; ++g) {
    out.load_xf(xf::kTexGen0 + g, texgen_word(t.texgens[g]));
    out.load_xf(xf::kPostMatrixInfo0 + g, xf::kPostIdentity);
  }
  // Texture matrices GX_TEXMTX0..9 and GX_IDENTITY (ids 30..60), all three rows.
  for (u32 id = 30; id <= 60; id += 3) load_floats(out, 4 * id, rows(t.matrices[id / 3], 3));
}

void write_matrices_xf(CommandStream& out, const std::array<float, 12>& position,
                       const std::array<float, 9>& normal) {
  // GX_LoadPosMtxImm's 3x4 rows and GX_LoadNrmMtxImm's 3x3 [OGC gx.c GX_LoadPosMtxImm,
  // GX_LoadNrmMtxImm].
  load_floats(out, xf::kPositionMatrices, std::vector<float>(position.begin(), position.end()));
  load_floats(out, xf::kNormalMatrices, std::vector<float>(normal.begin(), normal.end()));
}

void write_view_xf(CommandStream& out, const ViewTransform& t, FrameSize size) {
  // The position and normal matrices are the same rotation.
  std::array<float, 9> normal{};
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j) normal[3 * i + j] = t.position[4 * i + j];
  write_matrices_xf(out, t.position, normal);
  out.load_xf(xf::kViewport, viewport_words(size));
  out.load_xf(xf::kProjection, projection_words(t));
}

void write_gx_init_xf(CommandStream& out) {
  out.load_xf(xf::kError, 0x3f);
  out.load_xf(xf::kDualTexture, 1);
  out.load_xf(xf::kClipDisable, 0);
  load_floats(out, xf::kPostMatrices + 4 * xf::kPostIdentity, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
}

}  // namespace lt::gx::fifo
