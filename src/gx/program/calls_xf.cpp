// The XF calls: colour channels, light objects and texture coordinate generation.
#include <numbers>

#include "gx/program/machine.h"

namespace lt::gx::interp {

namespace {

// GX_SetChanAmbColor / GX_SetChanMatColor: GX_COLORn writes rgb, GX_ALPHAn alpha, GX_COLORnAn
// all four [OGC gx.c GX_SetChanAmbColor].
void set_channel_color(std::array<Color8, kMaxChannels>& regs, Machine& m) {
  const long long channel = m.i(0);
  const Color8 c = m.color(1);
  Color8& reg = regs[static_cast<size_t>(channel_index(channel))];
  if (channel != 2 && channel != 3) reg.r = c.r, reg.g = c.g, reg.b = c.b;
  if (channel >= 2) reg.a = c.a;
}

// GX_InitLightSpot's coefficients, in float as libogc computes them [OGC gx.c L4808-4862].
void init_light_spot(LightObject& l, float cut_off, long long fn) {
  if (cut_off < 0.0f || cut_off > 90.0f) fn = 0;
  const float r = cut_off * static_cast<float>(std::numbers::pi) / 180.0f;
  const float cr = std::cos(r);
  float a0 = 1, a1 = 0, a2 = 0;
  switch (fn) {
    case 1:  // FLAT
      a0 = -1000.0f * cr, a1 = 1000.0f, a2 = 0.0f;
      break;
    case 2:  // COS
      a0 = -cr / (1.0f - cr), a1 = 1.0f / (1.0f - cr), a2 = 0.0f;
      break;
    case 3:  // COS2
      a0 = 0.0f, a1 = -cr / (1.0f - cr), a2 = 1.0f / (1.0f - cr);
      break;
    case 4: {  // SHARP
      const float d = (1.0f - cr) * (1.0f - cr);
      a0 = cr * (cr - 2.0f), a1 = 2.0f / d, a2 = -1.0f / d;
      break;
    }
    case 5: {  // RING1
      const float d = (1.0f - cr) * (1.0f - cr);
      a0 = -4.0f * cr / d, a1 = 4.0f * (1.0f + cr) / d, a2 = -4.0f / d;
      break;
    }
    case 6: {  // RING2
      const float d = (1.0f - cr) * (1.0f - cr);
      a0 = 1.0f - 2.0f * cr * cr / d, a1 = 4.0f * cr / d, a2 = -2.0f / d;
      break;
    }
    default:
      break;
  }
  // cut_off = 0 with COS divides by zero in libogc too; keep the object finite for XF.
  if (!std::isfinite(a0) || !std::isfinite(a1) || !std::isfinite(a2)) a0 = 1, a1 = 0, a2 = 0;
  l.a = {a0, a1, a2};
}

// GX_InitLightDistAttn [OGC gx.c L4695-4730], in float.
void init_light_dist_attn(LightObject& l, float ref_dist, float ref_brite, long long fn) {
  if (ref_dist < 0.0f || ref_brite < 0.0f || ref_brite >= 1.0f) fn = 0;
  float k1 = 0, k2 = 0;
  if (fn == 1) k1 = (1.0f - ref_brite) / (ref_brite * ref_dist);
  if (fn == 2) {
    k1 = 0.5f * (1.0f - ref_brite) / (ref_brite * ref_dist);
    k2 = 0.5f * (1.0f - ref_brite) / (ref_brite * ref_dist * ref_dist);
  }
  if (fn == 3) k2 = (1.0f - ref_brite) / (ref_brite * ref_dist * ref_dist);
  if (!std::isfinite(k1) || !std::isfinite(k2)) k1 = 0, k2 = 0;  // ref_brite = 0: libogc's 1/0
  l.k = {1.0f, k1, k2};
}
// libogc's "large number" for specular lights' positions [OGC gx.c L23-25: -1.0e18f on Wii].
constexpr float kLargeNumber = -1.0e18f;

}  // namespace

void add_xf_calls(CallTable& table) {
  using K = ParamKind;
  using G = NameGroup;
  const Param light_p = of(K::LightRef);
  const Param channel_p = integer(G::Channel, 0, 5);
  table.insert({
      // --- XF: colour channels and lights [OGC gx.h L1873-1899, L3011, L4684-4959] ---
      // The counts (channels, texgens, TEV stages) take any u8, as C does: a count over the
      // hardware's limit is the budget's finding (exit 1, naming the limit), not a syntax error.
      {"GX_SetNumChans",
       {{integer(G::Number, 0, 255)}, [](Machine& m) { m.state.lighting.num_channels = m.u(0); }}},
      {"GX_SetChanCtrl",
       {{channel_p, integer(G::Bool, 0, 1), integer(G::ColorSource, 0, 1),
         integer(G::ColorSource, 0, 1), integer(G::Light, 0, 255), integer(G::DiffuseFn, 0, 2),
         integer(G::AttnFn, 0, 2)},
        [](Machine& m) {
          ChannelControl c;
          c.lighting = m.b(1);
          c.ambient_source = m.u(2);
          c.material_source = m.u(3);
          c.light_mask = m.u(4);
          // GX_AF_SPEC forces GX_DF_NONE [OGC gx.c L2195].
          c.diffuse_fn = m.i(6) == 0 ? 0 : m.u(5);
          c.attenuation_fn = m.u(6);
          const long long ch = m.i(0);
          auto& ctl = m.state.lighting.control;
          // GX_COLORnAn programs the colour and the alpha control together [OGC gx.c L2202].
          if (ch == 0 || ch == 4) ctl[0] = c;
          if (ch == 1 || ch == 5) ctl[1] = c;
          if (ch == 2 || ch == 4) ctl[2] = c;
          if (ch == 3 || ch == 5) ctl[3] = c;
        }}},
      {"GX_SetChanAmbColor",
       {{channel_p, of(K::Color)},
        [](Machine& m) { set_channel_color(m.state.lighting.ambient, m); }}},
      {"GX_SetChanMatColor",
       {{channel_p, of(K::Color)},
        [](Machine& m) { set_channel_color(m.state.lighting.material, m); }}},
      {"GX_InitLightPos",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) {
          m.light(0).position = {m.f(1), m.f(2), m.f(3)};
        }}},
      {"GX_InitLightColor",
       {{light_p, of(K::Color)}, [](Machine& m) { m.light(0).color = m.color(1); }}},
      // GX_InitLightDir stores the negated direction [OGC gx.c L4686-4693].
      {"GX_InitLightDir",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) {
          m.light(0).direction = {-m.f(1), -m.f(2), -m.f(3)};
        }}},
      {"GX_InitLightSpot",
       {{light_p, f32(), integer(G::SpotFn, 0, 6)},
        [](Machine& m) { init_light_spot(m.light(0), m.f(1), m.i(2)); }}},
      {"GX_InitLightAttn",
       {{light_p, f32(), f32(), f32(), f32(), f32(), f32()},
        [](Machine& m) {
          m.light(0).a = {m.f(1), m.f(2), m.f(3)};
          m.light(0).k = {m.f(4), m.f(5), m.f(6)};
        }}},
      {"GX_InitLightAttnA",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) {
          m.light(0).a = {m.f(1), m.f(2), m.f(3)};
        }}},
      {"GX_InitLightAttnK",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) {
          m.light(0).k = {m.f(1), m.f(2), m.f(3)};
        }}},
      {"GX_InitLightDistAttn",
       {{light_p, f32(), f32(), integer(G::DistFn, 0, 3)},
        [](Machine& m) { init_light_dist_attn(m.light(0), m.f(1), m.f(2), m.i(3)); }}},
      // The macro GX_InitLightShininess(l, s) = GX_InitLightAttn(l, 0, 0, 1, s/2, 0, 1 - s/2)
      // [OGC gx.h L5319-5322].
      {"GX_InitLightShininess",
       {{light_p, f32()},
        [](Machine& m) {
          const float s = m.f(1);
          m.light(0).a = {0, 0, 1};
          m.light(0).k = {s / 2, 0, 1 - s / 2};
        }}},
      // GX_InitSpecularDir: half-angle of the direction and the view (0,0,1), normalised; the
      // position at -LARGE * direction [OGC gx.c L4779-4806].
      {"GX_InitSpecularDir",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) {
          const float nx = m.f(1), ny = m.f(2), nz = m.f(3);
          float hx = -nx, hy = -ny, hz = -nz + 1.0f;
          float mag = hx * hx + hy * hy + hz * hz;
          if (mag != 0.0f) mag = 1.0f / std::sqrt(mag);
          m.light(0).direction = {hx * mag, hy * mag, hz * mag};
          m.light(0).position = {nx * kLargeNumber, ny * kLargeNumber, nz * kLargeNumber};
        }}},
      // GX_InitSpecularDirHA stores the half-angle as given [OGC gx.c L4762-4777].
      {"GX_InitSpecularDirHA",
       {{light_p, f32(), f32(), f32(), f32(), f32(), f32()},
        [](Machine& m) {
          m.light(0).position = {m.f(1) * kLargeNumber, m.f(2) * kLargeNumber,
                                 m.f(3) * kLargeNumber};
          m.light(0).direction = {m.f(4), m.f(5), m.f(6)};
        }}},
      {"GX_LoadLightObj",
       {{light_p, integer(G::Light, 1, 128)},
        [](Machine& m) {
          const long long id = m.i(1);
          if ((id & (id - 1)) != 0) m.fail_arg(1, "one light (GX_LIGHT0..7), not a mask");
          int n = 0;
          while ((1LL << n) != id) ++n;
          m.state.lighting.lights[static_cast<size_t>(n)] = m.light(0);
        }}},
      // --- XF: texture coordinate generation [OGC gx.h L2503, L2692, L2726] ---
      {"GX_SetNumTexGens",
       {{integer(G::Number, 0, 255)}, [](Machine& m) { m.state.texgen.num_texgens = m.u(0); }}},
      {"GX_SetTexCoordGen",
       {{integer(G::TexCoord, 0, 7), integer(G::TexGenType, 0, 1), integer(G::TexGenSource, 0, 20),
         integer(G::TexMtx, 30, 60)},
        [](Machine& m) {
          const long long src = m.i(2);
          if (src == 2 || src == 3 || src > 11)
            m.fail_arg(2, "texgen source " + m.text(2) +
                              " is not modelled (GX_TG_POS, GX_TG_NRM, GX_TG_TEX0..7 are)");
          if (m.i(3) % 3 != 0) m.fail_arg(3, "not a texture matrix (GX_TEXMTX0..9, GX_IDENTITY)");
          m.state.texgen.texgens[m.u(0)] = TexGen{m.u(1), static_cast<u8>(src), m.u(3)};
        }}},
      {"GX_LoadTexMtxImm",
       {{of(K::MtxName), integer(G::TexMtx, 30, 60), integer(G::MtxType, 0, 1)},
        [](Machine& m) {
          if (m.i(1) % 3 != 0) m.fail_arg(1, "not a texture matrix (GX_TEXMTX0..9, GX_IDENTITY)");
          TexMatrix& dst = m.state.texgen.matrices[static_cast<size_t>(m.i(1) / 3)];
          const TexMatrix& src = m.mtx(0);
          // GX_MTX2x4 writes two rows, GX_MTX3x4 three [OGC gx.c L2902-2918].
          const size_t rows = m.i(2) == 1 ? 2 : 3;
          for (size_t r = 0; r < rows; ++r) dst[r] = src[r];
        }}},
  });
}

}  // namespace lt::gx::interp
