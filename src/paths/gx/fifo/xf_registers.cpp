#include "paths/gx/fifo/xf_registers.h"

#include <cmath>
#include <vector>

namespace lt::gx::fifo {

namespace {
constexpr float kZMax = 16777215.0f;  // 2^24 - 1 [OGC gx.c GX_SetViewportJitter Zfactor]

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

std::array<u32, 7> projection_words(const Camera& cam, FrameSize size) {
  // The same double-precision matrix gl::SceneGeometry loads with glLoadMatrixf, then float.
  const double aspect = static_cast<double>(size.width) / size.height;
  const double n = cam.near, f = cam.far;
  std::array<float, 6> p{};
  u32 type = 0;  // GX_PERSPECTIVE 0, GX_ORTHOGRAPHIC 1 [OGC gx.h]
  if (cam.projection == Camera::Projection::Perspective) {
    const double t = std::tan(glm::radians(cam.fov_y_deg) / 2);
    p = {static_cast<float>(1 / (aspect * t)),
         0.0f,
         static_cast<float>(1 / t),
         0.0f,
         static_cast<float>(-n / (f - n)),
         static_cast<float>(-f * n / (f - n))};
  } else {
    const double h = cam.height / 2, w = h * aspect;
    p = {static_cast<float>(1 / w),        0.0f,
         static_cast<float>(1 / h),        0.0f,
         static_cast<float>(-1 / (f - n)), static_cast<float>(-f / (f - n))};
    type = 1;
  }
  std::array<u32, 7> out{};
  for (int i = 0; i < 6; ++i) out[static_cast<size_t>(i)] = float_bits(p[static_cast<size_t>(i)]);
  out[6] = type;
  return out;
}

std::array<u32, 6> viewport_words(FrameSize size) {
  const float w = static_cast<float>(size.width), h = static_cast<float>(size.height);
  return {float_bits(w * 0.5f),
          float_bits(-h * 0.5f),
          float_bits(kZMax),
          float_bits(w * 0.5f + static_cast<float>(kScreenOffset)),
          float_bits(h * 0.5f + static_cast<float>(kScreenOffset)),
          float_bits(kZMax)};
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

void write_view_xf(CommandStream& out, const glm::mat3& r, const Camera& camera, FrameSize size) {
  // glm is column-major: row i of the rotation is (r[0][i], r[1][i], r[2][i]).
  std::vector<float> position, normal;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      position.push_back(r[j][i]);
      normal.push_back(r[j][i]);
    }
    position.push_back(0.0f);
  }
  load_floats(out, xf::kPositionMatrices, position);
  load_floats(out, xf::kNormalMatrices, normal);
  const auto vp = viewport_words(size);
  out.load_xf(xf::kViewport, vp);
  const auto pr = projection_words(camera, size);
  out.load_xf(xf::kProjection, pr);
}

void write_gx_init_xf(CommandStream& out) {
  out.load_xf(xf::kError, 0x3f);
  out.load_xf(xf::kDualTexture, 1);
  out.load_xf(xf::kClipDisable, 0);
  load_floats(out, xf::kPostMatrices + 4 * xf::kPostIdentity, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
}

}  // namespace lt::gx::fifo
