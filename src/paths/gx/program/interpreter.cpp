#include "paths/gx/program/interpreter.h"

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "paths/gx/program/gx_names.h"

namespace lt::gx {

namespace {

// What a parameter of a libogc prototype takes.
enum class ParamKind { Int, F32, Color, ColorS10, LightRef, TexRef, MtxName, ArrayName };

struct Param {
  ParamKind kind;
  NameGroup group = NameGroup::Bool;  // Int: the GX_* names it accepts
  long long min = 0, max = 0;         // Int: the valid values
};

Param integer(NameGroup g, long long lo, long long hi) {
  return {ParamKind::Int, g, lo, hi};
}
Param f32() {
  return {ParamKind::F32};
}
Param of(ParamKind k) {
  return {k};
}

// libogc's software light object [OGC gx.c struct __gx_litobj]: what the GX_InitLight* helpers
// write, copied into XF by GX_LoadLightObj.
using LightObject = XfLight;

// libogc's texture object: GX_InitTexObj's arguments; the image is the named u8 array.
struct TexObject {
  TextureObject texture;
  std::string array;
  bool initialised = false;
};

// One run: the state, the program's variables, and the call being executed (for messages).
class Machine {
 public:
  explicit Machine(const std::string& file) : file_(file) {}

  void run(const std::vector<Statement>& block) {
    for (const Statement& s : block) {
      if (s.kind == Statement::Kind::Declaration) {
        declare(s.declaration);
      } else {
        execute(s.call);
      }
    }
  }

  GxState state;

  // Accessors for handlers: argument k of the current call, already checked against its kind.
  long long i(size_t k) const { return call_->args[k].value; }
  u8 u(size_t k) const { return static_cast<u8>(call_->args[k].value); }
  bool b(size_t k) const { return call_->args[k].value != 0; }
  float f(size_t k) const { return static_cast<float>(call_->args[k].number); }
  Color8 color(size_t k) const {
    const auto& c = call_->args[k].color;
    return {static_cast<u8>(c[0]), static_cast<u8>(c[1]), static_cast<u8>(c[2]),
            static_cast<u8>(c[3])};
  }
  ColorS10 color_s10(size_t k) const {
    const auto& c = call_->args[k].color;
    return {static_cast<s16>(c[0]), static_cast<s16>(c[1]), static_cast<s16>(c[2]),
            static_cast<s16>(c[3])};
  }
  LightObject& light(size_t k) { return lights_.at(call_->args[k].name); }
  TexObject& tex(size_t k) { return textures_.at(call_->args[k].name); }
  const TexMatrix& mtx(size_t k) const { return matrices_.at(call_->args[k].name); }
  const std::vector<u8>& bytes(size_t k) const { return arrays_.at(call_->args[k].name); }
  const std::string& name(size_t k) const { return call_->args[k].name; }
  const std::string& text(size_t k) const { return call_->args[k].text; }
  const std::vector<u8>& bytes_of(const std::string& array) const { return arrays_.at(array); }

  [[noreturn]] void fail_arg(size_t k, const std::string& what) const {
    fail(call_->args[k].pos, call_->function + " argument " + std::to_string(k + 1) + ": " + what);
  }
  [[noreturn]] void fail_call(const std::string& what) const {
    fail(call_->pos, call_->function + ": " + what);
  }

 private:
  [[noreturn]] void fail(const SourcePos& p, const std::string& what) const {
    throw InputError(file_, std::to_string(p.line) + ":" + std::to_string(p.column), what);
  }

  void declare(const Declaration& d) {
    if (lights_.count(d.name) || textures_.count(d.name) || matrices_.count(d.name) ||
        arrays_.count(d.name))
      fail(d.pos, "redefinition of " + d.name);
    switch (d.type) {
      case Declaration::Type::LightObj:
        lights_[d.name] = LightObject{};
        break;
      case Declaration::Type::TexObj:
        textures_[d.name] = TexObject{};
        break;
      case Declaration::Type::Mtx: {
        TexMatrix m{};
        for (size_t r = 0; r < 3; ++r)
          for (size_t c = 0; c < 4; ++c) m[r][c] = static_cast<float>(d.values[r * 4 + c]);
        matrices_[d.name] = m;
        break;
      }
      case Declaration::Type::ByteArray: {
        std::vector<u8> v;
        for (double x : d.values) v.push_back(static_cast<u8>(x));
        arrays_[d.name] = std::move(v);
        break;
      }
    }
  }

  void execute(const Call& c);

  void check_arg(size_t k, const Param& p) const {
    const Arg& a = call_->args[k];
    auto wrong = [&](const std::string& expected) {
      fail_arg(k, "expected " + expected + ", found '" + a.text + "'");
    };
    switch (p.kind) {
      case ParamKind::Int: {
        if (a.kind != Arg::Kind::Integer) wrong(describe(p.group));
        // Every GX_* name in the expression must be of the parameter's group.
        std::istringstream parts(a.text);
        for (std::string w; parts >> w;) {
          if (w == "|" || w.rfind("GX_", 0) != 0) continue;
          const GxName* n = find_gx_name(w);
          if (n && n->group != p.group)
            fail_arg(k, w + " is " + describe(n->group) + ", expected " + describe(p.group));
        }
        if (a.value < p.min || a.value > p.max)
          fail_arg(k, "value out of range: " + a.text + " (" + std::to_string(p.min) + ".." +
                          std::to_string(p.max) + ")");
        break;
      }
      case ParamKind::F32:
        if (a.kind != Arg::Kind::Number && a.kind != Arg::Kind::Integer) wrong("a number");
        if (!std::isfinite(static_cast<float>(a.number)))
          fail_arg(k, "number out of float range: " + a.text);
        break;
      case ParamKind::Color:
      case ParamKind::ColorS10: {
        const bool s10 = p.kind == ParamKind::ColorS10;
        if (a.kind != (s10 ? Arg::Kind::ColorS10 : Arg::Kind::Color))
          wrong(s10 ? "a (GXColorS10){r, g, b, a}" : "a (GXColor){r, g, b, a}");
        const long long lo = s10 ? -1024 : 0, hi = s10 ? 1023 : 255;
        for (long long v : a.color) {
          if (v < lo || v > hi)
            fail_arg(k, "colour component out of range: " + std::to_string(v) + " (" +
                            std::to_string(lo) + ".." + std::to_string(hi) + ")");
        }
        break;
      }
      case ParamKind::LightRef:
        if (a.kind != Arg::Kind::AddressOf || !lights_.count(a.name))
          wrong("&name of a declared GXLightObj");
        break;
      case ParamKind::TexRef:
        if (a.kind != Arg::Kind::AddressOf || !textures_.count(a.name))
          wrong("&name of a declared GXTexObj");
        break;
      case ParamKind::MtxName:
        if (a.kind != Arg::Kind::Identifier || !matrices_.count(a.name))
          wrong("the name of a declared Mtx");
        break;
      case ParamKind::ArrayName:
        if (a.kind != Arg::Kind::Identifier || !arrays_.count(a.name))
          wrong("the name of a declared u8 array");
        break;
    }
  }

  const std::string& file_;
  const Call* call_ = nullptr;
  std::map<std::string, LightObject> lights_;
  std::map<std::string, TexObject> textures_;
  std::map<std::string, TexMatrix> matrices_;
  std::map<std::string, std::vector<u8>> arrays_;
};

using Handler = std::function<void(Machine&)>;
struct CallInfo {
  std::vector<Param> params;
  Handler apply;
};

// Index of a colour channel argument: GX_COLOR0, GX_ALPHA0, GX_COLOR0A0 -> 0; the *1 -> 1.
int channel_index(long long channel) {
  return (channel == 1 || channel == 3 || channel == 5) ? 1 : 0;
}

// GX_SetChanAmbColor / GX_SetChanMatColor: GX_COLORn writes rgb, GX_ALPHAn alpha, GX_COLORnAn
// all four [OGC gx.c GX_SetChanAmbColor].
void set_channel_color(Color8& reg, long long channel, const Color8& c) {
  if (channel != 2 && channel != 3) reg.r = c.r, reg.g = c.g, reg.b = c.b;
  if (channel >= 2) reg.a = c.a;
}

TevStage& stage(Machine& m, size_t k) {
  return m.state.tev.stages[m.u(k)];
}

// GX_SetTevColorOp / GX_SetTevAlphaOp: a compare op (8..15) writes bias 3, scale bits
// (op >> 1) & 3 and op bit op & 1; bias and scale arguments are then ignored [OGC gx.c L3893].
void set_op(TevCombiner& c, Machine& m) {
  const long long op = m.i(1);
  if (op >= 8) {
    c.bias = 3;
    c.scale = static_cast<u8>((op >> 1) & 3);
    c.op = static_cast<u8>(op & 1);
  } else {
    if (m.i(2) == 3) m.fail_arg(2, "bias 3 selects a compare stage: pass a GX_TEV_COMP_* op");
    c.bias = m.u(2);
    c.scale = m.u(3);
    c.op = static_cast<u8>(op);
  }
  c.clamp = m.b(4);
  c.dest = m.u(5);
}

// libogc's GX_SetTevOp presets [OGC gx.c L3835-3869]: stage 0 reads the rasterised colour,
// later stages the previous stage's result.
void tev_preset(Machine& m) {
  TevStage& s = stage(m, 0);
  const bool first = m.i(0) == 0;
  const u8 c = first ? 10 : 0, a = first ? 5 : 0;  // RASC / CPREV, RASA / APREV
  constexpr u8 kZero = 15, kTexC = 8, kTexA = 9, kOne = 12, aZero = 7, aTexA = 4, aRasA = 5;
  switch (m.i(1)) {
    case 0:  // MODULATE
      s.color = {kZero, kTexC, c, kZero};
      s.alpha = {aZero, aTexA, a, aZero};
      break;
    case 1:  // DECAL
      s.color = {c, kTexC, kTexA, kZero};
      s.alpha = {aZero, aZero, aZero, a};
      break;
    case 2:  // BLEND
      s.color = {c, kOne, kTexC, kZero};
      s.alpha = {aZero, aTexA, a, aRasA};
      break;
    case 3:  // REPLACE
      s.color = {kZero, kZero, kZero, kTexC};
      s.alpha = {aZero, aZero, aZero, aTexA};
      break;
    default:  // PASSCLR
      s.color = {kZero, kZero, kZero, c};
      s.alpha = {aZero, aZero, aZero, a};
      break;
  }
  for (TevCombiner* comb : {&s.color, &s.alpha}) {
    comb->bias = 0;
    comb->op = 0;
    comb->scale = 0;
    comb->clamp = true;
    comb->dest = 0;
  }
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

const std::map<std::string, CallInfo>& calls() {
  using K = ParamKind;
  using G = NameGroup;
  const Param stage_p = integer(G::TevStage, 0, 15);
  const Param light_p = of(K::LightRef);
  const Param tex_p = of(K::TexRef);
  const Param channel_p = integer(G::Channel, 0, 5);
  static const std::map<std::string, CallInfo> table = {
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
        [](Machine& m) {
          set_channel_color(m.state.lighting.ambient[static_cast<size_t>(channel_index(m.i(0)))],
                            m.i(0), m.color(1));
        }}},
      {"GX_SetChanMatColor",
       {{channel_p, of(K::Color)},
        [](Machine& m) {
          set_channel_color(m.state.lighting.material[static_cast<size_t>(channel_index(m.i(0)))],
                            m.i(0), m.color(1));
        }}},
      {"GX_InitLightPos",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) { m.light(0).position = {m.f(1), m.f(2), m.f(3)}; }}},
      {"GX_InitLightColor",
       {{light_p, of(K::Color)}, [](Machine& m) { m.light(0).color = m.color(1); }}},
      // GX_InitLightDir stores the negated direction [OGC gx.c L4686-4693].
      {"GX_InitLightDir",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) { m.light(0).direction = {-m.f(1), -m.f(2), -m.f(3)}; }}},
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
        [](Machine& m) { m.light(0).a = {m.f(1), m.f(2), m.f(3)}; }}},
      {"GX_InitLightAttnK",
       {{light_p, f32(), f32(), f32()},
        [](Machine& m) { m.light(0).k = {m.f(1), m.f(2), m.f(3)}; }}},
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
      // --- TEV [OGC gx.h L2559-3227] ---
      {"GX_SetNumTevStages",
       {{integer(G::Number, 1, 255)}, [](Machine& m) { m.state.tev.num_stages = m.u(0); }}},
      {"GX_SetTevOrder",
       {{stage_p, integer(G::TexCoord, 0, 255), integer(G::TexMap, 0, 0x1ff),
         integer(G::Channel, 0, 255)},
        [](Machine& m) {
          TevStage& s = stage(m, 0);
          const long long tc = m.i(1), map = m.i(2), ch = m.i(3);
          if (tc > 7 && tc != 0xff) m.fail_arg(1, "not a texture coordinate");
          if ((map & 0xff) > 7 && (map & 0xff) != 0xff) m.fail_arg(2, "not a texture map");
          s.texcoord = static_cast<u8>(tc);
          // GX_TEXMAP_NULL or the GX_TEXMAP_DISABLE bit turn the fetch off [OGC gx.c
          // GX_SetTevOrder].
          s.texmap = (map == 0xff || (map & 0x100)) ? kTexMapNull : static_cast<u8>(map);
          // The colour id: COLOR0 / ALPHA0 / COLOR0A0 rasterise channel 0, the *1 channel 1,
          // COLORZERO and COLORNULL read zero [OGC gx.c L100 _gxtevcolid].
          if (ch == 7 || ch == 8) m.fail_arg(3, "bump alpha is not modelled");
          if (ch > 8 && ch != 0xff) m.fail_arg(3, "not a colour channel");
          s.channel = ch == 6 || ch == 0xff ? static_cast<u8>(ch) : channel_index(ch) ? 5 : 4;
        }}},
      {"GX_SetTevColorIn",
       {{stage_p, integer(G::ColorArg, 0, 15), integer(G::ColorArg, 0, 15),
         integer(G::ColorArg, 0, 15), integer(G::ColorArg, 0, 15)},
        [](Machine& m) {
          TevCombiner& c = stage(m, 0).color;
          c.a = m.u(1), c.b = m.u(2), c.c = m.u(3), c.d = m.u(4);
        }}},
      {"GX_SetTevAlphaIn",
       {{stage_p, integer(G::AlphaArg, 0, 7), integer(G::AlphaArg, 0, 7),
         integer(G::AlphaArg, 0, 7), integer(G::AlphaArg, 0, 7)},
        [](Machine& m) {
          TevCombiner& c = stage(m, 0).alpha;
          c.a = m.u(1), c.b = m.u(2), c.c = m.u(3), c.d = m.u(4);
        }}},
      {"GX_SetTevColorOp",
       {{stage_p, integer(G::TevOp, 0, 15), integer(G::TevBias, 0, 3), integer(G::TevScale, 0, 3),
         integer(G::Bool, 0, 1), integer(G::TevReg, 0, 3)},
        [](Machine& m) {
          if (m.i(1) > 1 && m.i(1) < 8) m.fail_arg(1, "not a TEV operation");
          set_op(stage(m, 0).color, m);
        }}},
      {"GX_SetTevAlphaOp",
       {{stage_p, integer(G::TevOp, 0, 15), integer(G::TevBias, 0, 3), integer(G::TevScale, 0, 3),
         integer(G::Bool, 0, 1), integer(G::TevReg, 0, 3)},
        [](Machine& m) {
          if (m.i(1) > 1 && m.i(1) < 8) m.fail_arg(1, "not a TEV operation");
          set_op(stage(m, 0).alpha, m);
        }}},
      // GX_SetTevColor writes 0..255 into the 11-bit register fields [OGC gx.c L3775-3788].
      {"GX_SetTevColor",
       {{integer(G::TevReg, 0, 3), of(K::Color)},
        [](Machine& m) {
          const Color8 c = m.color(1);
          m.state.tev.registers[m.u(0)] = {c.r, c.g, c.b, c.a};
        }}},
      {"GX_SetTevColorS10",
       {{integer(G::TevReg, 0, 3), of(K::ColorS10)},
        [](Machine& m) { m.state.tev.registers[m.u(0)] = m.color_s10(1); }}},
      {"GX_SetTevKColor",
       {{integer(G::KColor, 0, 3), of(K::Color)},
        [](Machine& m) { m.state.tev.konst[m.u(0)] = m.color(1); }}},
      {"GX_SetTevKColorSel",
       {{stage_p, integer(G::KColorSel, 0, 31)},
        [](Machine& m) { stage(m, 0).konst_color_sel = m.u(1); }}},
      {"GX_SetTevKAlphaSel",
       {{stage_p, integer(G::KAlphaSel, 0, 31)},
        [](Machine& m) { stage(m, 0).konst_alpha_sel = m.u(1); }}},
      {"GX_SetTevOp", {{stage_p, integer(G::TevMode, 0, 4)}, tev_preset}},
      {"GX_SetTevSwapMode",
       {{stage_p, integer(G::Swap, 0, 3), integer(G::Swap, 0, 3)},
        [](Machine& m) {
          stage(m, 0).ras_swap = m.u(1);
          stage(m, 0).tex_swap = m.u(2);
        }}},
      {"GX_SetTevSwapModeTable",
       {{integer(G::Swap, 0, 3), integer(G::ColorComponent, 0, 3),
         integer(G::ColorComponent, 0, 3), integer(G::ColorComponent, 0, 3),
         integer(G::ColorComponent, 0, 3)},
        [](Machine& m) {
          m.state.tev.swap_tables[m.u(0)] = {m.u(1), m.u(2), m.u(3), m.u(4)};
        }}},
      // Indirect texturing is never enabled in this emulator, so "direct" is the state it
      // already models: the call is accepted because exported code sets it explicitly.
      {"GX_SetTevDirect", {{stage_p}, [](Machine&) {}}},
      // --- Pixel engine [OGC gx.h L2810, L2882, L3106] ---
      {"GX_SetAlphaCompare",
       {{integer(G::Compare, 0, 7), integer(G::Number, 0, 255), integer(G::AlphaOp, 0, 3),
         integer(G::Compare, 0, 7), integer(G::Number, 0, 255)},
        [](Machine& m) { m.state.alpha_compare = {m.u(0), m.u(1), m.u(2), m.u(3), m.u(4)}; }}},
      {"GX_SetBlendMode",
       {{integer(G::BlendMode, 0, 3), integer(G::BlendFactor, 0, 7),
         integer(G::BlendFactor, 0, 7), integer(G::LogicOp, 0, 15)},
        [](Machine& m) { m.state.blend = {m.u(0), m.u(1), m.u(2), m.u(3)}; }}},
      // Visibility comes from one depth buffer shared by every pass (the first pass's depth, as
      // an EQUAL/LEQUAL test without update gives on hardware), so only those modes are modelled.
      {"GX_SetZMode",
       {{integer(G::Bool, 0, 1), integer(G::Compare, 0, 7), integer(G::Bool, 0, 1)},
        [](Machine& m) {
          if (!m.b(0) || (m.i(1) != 1 && m.i(1) != 2 && m.i(1) != 3))
            m.fail_call("only an enabled depth test with GX_LESS, GX_EQUAL or GX_LEQUAL is "
                        "modelled (passes resolve visibility on one shared depth buffer)");
          m.state.z = {m.b(0), m.u(1), m.b(2)};
        }}},
      // --- Textures [OGC gx.h L4174-4459] ---
      {"GX_InitTexObj",
       {{tex_p, of(K::ArrayName), integer(G::Number, 1, 1024), integer(G::Number, 1, 1024),
         integer(G::TexFormat, 0, 14), integer(G::TexWrap, 0, 2), integer(G::TexWrap, 0, 2),
         integer(G::Bool, 0, 1)},
        [](Machine& m) {
          if (m.i(4) != 1 && m.i(4) != 3)
            m.fail_arg(5, "texture format not modelled (GX_TF_I8 and GX_TF_IA8 are)");
          if (m.b(7)) m.fail_arg(8, "mipmapping is not modelled (pass GX_FALSE)");
          TexObject& t = m.tex(0);
          t.array = m.name(1);
          t.texture.width = static_cast<int>(m.i(2));
          t.texture.height = static_cast<int>(m.i(3));
          t.texture.format = m.u(4);
          t.texture.wrap_s = m.u(5);
          t.texture.wrap_t = m.u(6);
          t.texture.linear = true;  // mipmap GX_FALSE: linear min and mag [OGC gx.c L3236]
          t.initialised = true;
          const size_t need = tiled_size(t.texture.format, t.texture.width, t.texture.height);
          if (m.bytes(1).size() < need)
            m.fail_arg(1, m.name(1) + " holds " + std::to_string(m.bytes(1).size()) +
                              " bytes, the texture needs " + std::to_string(need));
        }}},
      {"GX_InitTexObjWrapMode",
       {{tex_p, integer(G::TexWrap, 0, 2), integer(G::TexWrap, 0, 2)},
        [](Machine& m) {
          m.tex(0).texture.wrap_s = m.u(1);
          m.tex(0).texture.wrap_t = m.u(2);
        }}},
      {"GX_InitTexObjFilterMode",
       {{tex_p, integer(G::TexFilter, 0, 5), integer(G::TexFilter, 0, 1)},
        [](Machine& m) {
          // Without mipmaps the sampler never minifies differently from magnifying a LUT here.
          if (m.i(1) != m.i(2))
            m.fail_call("different min and mag filters are not modelled (no mipmaps)");
          m.tex(0).texture.linear = m.i(2) == 1;
        }}},
      {"GX_LoadTexObj",
       {{tex_p, integer(G::TexMap, 0, 7)},
        [](Machine& m) {
          TexObject& t = m.tex(0);
          if (!t.initialised) m.fail_arg(0, m.name(0) + " was never given to GX_InitTexObj");
          TextureObject loaded = t.texture;
          const std::vector<u8>& src = m.bytes_of(t.array);
          loaded.data.assign(src.begin(), src.begin() + static_cast<std::ptrdiff_t>(tiled_size(
                                                            loaded.format, loaded.width,
                                                            loaded.height)));
          m.state.textures[m.u(1)] = std::move(loaded);
        }}},
      // Cache maintenance: the emulator's memory is always coherent, so these change nothing;
      // they are accepted because code for the console must call them (gx-hardware.md §3.4).
      {"GX_InvalidateTexAll", {{}, [](Machine&) {}}},
      {"DCFlushRange", {{of(K::ArrayName), integer(G::Number, 0, 1 << 24)}, [](Machine&) {}}},
      // --- Vertex format [OGC gx.h L1781, L1955, L1985] ---
      {"GX_ClearVtxDesc", {{}, [](Machine& m) { m.state.vertex = VertexDescriptor{}; }}},
      {"GX_SetVtxDesc",
       {{integer(G::VtxAttr, 9, 20), integer(G::VtxAttrType, 0, 3)},
        [](Machine& m) {
          if (m.i(1) > 1)
            m.fail_arg(1, "indexed vertex data is not modelled (the scene sends GX_DIRECT)");
          if (m.i(0) == kVaClr1) m.fail_arg(0, "the scene has one vertex colour (GX_VA_CLR0)");
          if (m.i(0) > kVaTex0) m.fail_arg(0, "the scene sends one texture coordinate (GX_VA_TEX0)");
          m.state.vertex.type[m.u(0)] = m.u(1);
        }}},
      {"GX_SetVtxAttrFmt",
       {{integer(G::VtxFmt, 0, 7), integer(G::VtxAttr, 9, 20), integer(G::CompCount, 0, 2),
         integer(G::CompType, 0, 5), integer(G::Number, 0, 31)},
        [](Machine& m) {
          // The emulator feeds what the scene has, in one format: check that the program
          // declares that format, so exported code matches what was emulated.
          const long long attr = m.i(1), cnt = m.i(2), type = m.i(3);
          const bool ok = (attr == kVaPos && cnt == 1 && type == 4) ||
                          (attr == kVaNrm && cnt == 0 && type == 4) ||
                          (attr == kVaClr0 && (type == 5 || type == 1)) ||
                          (attr == kVaTex0 && type == 4);
          if (!ok)
            m.fail_call("the scene sends positions and normals as GX_F32 XYZ, colours as "
                        "GX_RGBA8/GX_RGB8 and texture coordinates as GX_F32");
        }}},
  };
  return table;
}

void Machine::execute(const Call& c) {
  call_ = &c;
  const auto& table = calls();
  const auto it = table.find(c.function);
  if (it == table.end()) {
    static const std::map<std::string, std::string> not_modelled = {
        {"GX_LoadPosMtxImm", "matrices come from the scene's camera"},
        {"GX_LoadNrmMtxImm", "matrices come from the scene's camera"},
        {"GX_SetCurrentMtx", "matrices come from the scene's camera"},
        {"GX_Begin", "geometry comes from the scene"},
        {"GX_SetCullMode", "culling is not modelled (every face is drawn, as the other paths do)"},
    };
    const auto nm = not_modelled.find(c.function);
    if (nm != not_modelled.end()) fail(c.pos, c.function + ": not modelled: " + nm->second);
    fail(c.pos, c.function.rfind("GX_", 0) == 0
                    ? c.function + ": not modelled by the emulator (see `ltrender render --help`)"
                    : "unknown call " + c.function);
  }
  const CallInfo& info = it->second;
  if (c.args.size() != info.params.size())
    fail(c.pos, c.function + ": expected " + std::to_string(info.params.size()) +
                    " arguments, found " + std::to_string(c.args.size()));
  for (size_t k = 0; k < c.args.size(); ++k) check_arg(k, info.params[k]);
  info.apply(*this);
}

}  // namespace

GxState run_program(const std::string& file,
                    const std::vector<const std::vector<Statement>*>& blocks) {
  Machine m(file);
  for (const auto* block : blocks) m.run(*block);
  return m.state;
}

std::vector<std::string> modelled_calls() {
  std::vector<std::string> out;
  for (const auto& [name, info] : calls()) out.push_back(name);
  return out;
}

}  // namespace lt::gx
