// plan_scene: the gx generator's choices (generator.h has the term each pass computes). Which
// passes a material needs, which scales keep every 8-bit quantity in range, which attributes,
// lights, texgens, textures and stages the scene needs; nothing here writes C or prose.
#include <algorithm>
#include <optional>

#include "core/error.h"
#include "gx/texture_unit.h"
#include "image/image.h"
#include "model/rational_fit.h"
#include "model/translucency.h"
#include "paths/gx/generator.h"
#include "paths/gx/lobe_lut.h"
#include "paths/gx/pass_plan_parts.h"
#include "paths/gx/scene_pass_programs.h"
#include "paths/gx/scene_vertices.h"
#include "paths/gx/thickness_texture.h"

namespace lt::gx {

namespace {

// How far past the silhouette (N.V < 0) a vertex still counts as possibly seen.
constexpr double kBackFacing = 0.2;

// What the lights do at the vertices of one material, in double (the generator's CPU side):
// the largest attenuation, and the largest diffuse sum, to choose the scales.
struct LightStats {
  double max_attenuation = 0;
  double max_diffuse = 0;  // max over vertices of att * max(N.L, 0)
};

// With a declared :light-range=D (gx_variant.h) no vertex is looked at: a point light's
// attenuation at D bounds both figures (N.L <= 1), as the module's ltr_declared_range computes it;
// a directional light's are 1.
LightStats light_stats(const Scene& scene, int material, const Light& light,
                       const std::optional<double>& declared) {
  LightStats st;
  if (declared) {
    const double d = *declared;
    const double den = light.kc + light.kl * d + light.kq * d * d;
    st.max_attenuation = light.type == Light::Type::Point
                             ? 1.0 / std::max(den, model::kMinAttenuationDenominator)
                             : 1.0;
    st.max_diffuse = st.max_attenuation;
    return st;
  }
  for (const SceneObject& o : scene.objects) {
    if (o.material != material) continue;
    for (size_t v = 0; v < o.mesh.positions.size(); ++v) {
      const glm::dvec3& N = o.mesh.normals[v];
      // Only vertices that can be seen choose the scale: a vertex facing away from the eye lies
      // on a back face, hidden behind the front of the mesh, and a scale chosen for it would
      // halve the precision of what is seen (the slack keeps silhouette vertices).
      const glm::dvec3 V = model::view_vector(scene.camera, o.mesh.positions[v] - scene.camera.eye);
      if (glm::dot(N, V) < -kBackFacing) continue;
      const model::LightSample ls = model::sample_light(light, o.mesh.positions[v], N);
      st.max_attenuation = std::max(st.max_attenuation, ls.attenuation);
      st.max_diffuse = std::max(st.max_diffuse, ls.attenuation * std::max(glm::dot(N, ls.L), 0.0));
    }
  }
  return st;
}

// The eye-space position the XF lights from: a point light's own, a directional light's far
// away against its direction.
glm::dvec3 light_position_eye(const SceneView& view, const Light& light) {
  if (light.type == Light::Type::Point) return view.to_eye(light.position);
  return view.view * (-light.direction * kFarAway);
}

// A distance-attenuated light object: colour normalised to 255 at its largest component;
// attenuation k scaled by 1/gain, so the XF computes gain * att * colour. Spot off (a = 1, 0, 0)
// and a finite direction: the object is application memory and a garbage direction can poison
// 0 * x terms (gx-hardware.md §5.2, Dolphin PR#10475).
LightObjectPlan distance_light(const std::string& name, int slot, const glm::dvec3& pos_eye,
                               const glm::dvec3& color, const Light& light, double gain) {
  const double m = max3(color);
  const bool point = light.type == Light::Type::Point;
  LightObjectPlan o;
  o.kind = LightObjectPlan::Kind::Distance;
  o.name = name;
  o.slot = GxConst<NameGroup::Light>::with_value(1 << slot);
  o.position = glm::vec3(pos_eye);
  o.color = rgb8(m > 0 ? color / m : glm::dvec3(0));
  o.direction_arg = {0, 0, -1};
  o.gain = m > 0 && gain > 0 ? gain : 1.0;
  const double kc = point ? light.kc : 1.0, kl = point ? light.kl : 0.0,
               kq = point ? light.kq : 0.0;
  o.k = {static_cast<float>(kc / o.gain), static_cast<float>(kl / o.gain),
         static_cast<float>(kq / o.gain)};
  return o;
}

// The smallest of x1, x2, x4 that holds `magnitude`; 4 where even that is too small (the
// channel then saturates, and the pass says so).
int scale_for(double magnitude) {
  for (int s : {1, 2, 4}) {
    if (magnitude <= s * (1 + 1e-9)) return s;
  }
  return static_cast<int>(kMaxScale);
}

}  // namespace

Color8 rgb8(const glm::dvec3& c) {
  return {to_unorm8(c.r), to_unorm8(c.g), to_unorm8(c.b), 255};
}

TevStagePlan tev_stage(int stage, GxConst<NameGroup::TexCoord> texcoord,
                       GxConst<NameGroup::TexMap> texmap, GxConst<NameGroup::Channel> channel,
                       std::array<GxConst<NameGroup::ColorArg>, 4> in, int scale,
                       std::string what) {
  TevStagePlan s;
  s.stage = GxConst<NameGroup::TevStage>::with_value(stage);
  s.texcoord = texcoord;
  s.texmap = texmap;
  s.channel = channel;
  s.color.in = in;
  s.color.scale = scale == 1   ? GxConst<NameGroup::TevScale>{"GX_CS_SCALE_1"}
                  : scale == 2 ? GxConst<NameGroup::TevScale>{"GX_CS_SCALE_2"}
                               : GxConst<NameGroup::TevScale>{"GX_CS_SCALE_4"};
  s.what = std::move(what);
  return s;
}

// Pass 0 replaces what the EFB holds; later passes add onto it: min(src + dst, 255) per channel
// (ONE, ONE through the f + (f >> 7) factor rule [DSW BlendColor]), with the depth of pass 0
// tested but not rewritten. Every face, as the other paths draw them: the depth test keeps the
// nearest. GX_Init leaves GX_CULL_BACK, which on GX removes the faces GL calls front
// (gx_state.h), so a pass that set nothing would show a GL-wound mesh from the inside.
PixelEnginePlan pixel_engine(int pass) {
  PixelEnginePlan p;
  if (pass == 0) {
    p.what = "Pixel engine: the first pass replaces the EFB colour";
    return p;
  }
  p.blend = {"GX_BM_BLEND"};
  p.dst = {"GX_BL_ONE"};
  p.z_update = {"GX_FALSE"};
  p.what = "Pixel engine: add this light onto the passes before (saturates at 255)";
  return p;
}

PassPlanner::PassPlanner(const Scene& scene, const GxVariant& v)
    : scene_(scene), variant_(v), view_(SceneView::of(scene)) {}

ScenePlan PassPlanner::plan() {
  ScenePlan out;
  const std::vector<std::string> c_names = material_c_names(scene_);
  std::vector<bool> used(scene_.materials.size(), false);
  for (const SceneObject& o : scene_.objects) used[static_cast<size_t>(o.material)] = true;
  for (size_t m = 0; m < scene_.materials.size(); ++m) {
    if (!used[m]) continue;
    MaterialPlan mp;
    mp.material = static_cast<int>(m);
    mp.name = scene_.materials[m].name;
    mp.c_name = c_names[m];
    material_passes(mp);
    out.materials.push_back(std::move(mp));
  }
  // Every pass declares the mesh alike: it is stored once a frame (program_storage.h).
  const VertexDeclarations declared = storage_declarations(scene_, variant_, out);
  for (MaterialPlan& m : out.materials)
    for (PassPlan& p : m.passes) p.vertex.declared = declared;
  return out;
}

void PassPlanner::material_passes(MaterialPlan& mp) {
  light_passes(mp);
  const std::optional<MapTexture> albedo = albedo_texture(mp);
  // The albedo map multiplies every part of each pass's sum (pass_planner_albedo.cpp).
  if (albedo) {
    for (PassPlan& p : mp.passes) add_albedo_stage(p, *albedo);
  }
}

void PassPlanner::light_passes(MaterialPlan& mp) {
  const Material& mat = scene_.materials[static_cast<size_t>(mp.material)];
  if (!mat.translucency || scene_.lights.empty()) {
    // Diffuse only: the XF sums up to 8 lights in one channel, one stage shows it.
    for (size_t first = 0; first < std::max<size_t>(scene_.lights.size(), 1); first += 8)
      mp.passes.push_back(diffuse_pass(mp.material, static_cast<int>(mp.passes.size()), first));
    return;
  }
  const Translucency& tr = *mat.translucency;
  const bool flat_lobe = !tr.ramp && tr.power == 0;
  std::optional<TexturePlan> lut;
  if (variant_.lobe == GxVariant::Lobe::Lut && !flat_lobe) lut = lut_texture(mp);
  std::optional<MapTexture> map;
  if (const std::optional<MapTexels> texels = thickness_map_texels(mat))
    map = map_texture(mp, *texels, kThicknessMapRole);
  for (size_t l = 0; l < scene_.lights.size(); ++l)
    mp.passes.push_back(light_pass(mp.material, l, lut, map ? &*map : nullptr));
}

PassPlan PassPlanner::diffuse_pass(int m, int pass, size_t first_light) {
  const Material& mat = scene_.materials[static_cast<size_t>(m)];
  PassPlan p;
  const size_t last = std::min(scene_.lights.size(), first_light + 8);
  // The largest sum the channel holds before the material multiply.
  double magnitude = pass == 0 ? max3(scene_.ambient_light) : 0.0;
  for (size_t l = first_light; l < last; ++l) {
    const Light& light = scene_.lights[l];
    magnitude +=
        light_stats(scene_, m, light, variant_.light_range).max_diffuse * max3(light.color);
  }
  const int sd = scale_for(magnitude);
  ChannelPlan c;
  for (size_t l = first_light; l < last; ++l) {
    const Light& light = scene_.lights[l];
    const int slot = static_cast<int>(l - first_light);
    p.lights.push_back(distance_light("light" + std::to_string(l), slot,
                                      light_position_eye(view_, light), light.color, light,
                                      max3(light.color) / sd));
    c.lights.bits |= 1 << slot;
  }
  p.channels_what = "COLOR0A0 = albedo x clamp(ambient + sum of lights' diffuse)";
  c.ambient = rgb8(pass == 0 ? scene_.ambient_light / double(sd) : glm::dvec3(0));
  c.material = rgb8(mat.albedo);
  p.channels.push_back(c);
  p.stages.push_back(tev_stage(0, {"GX_TEXCOORDNULL"}, {"GX_TEXMAP_NULL"}, {"GX_COLOR0A0"},
                               {"GX_CC_RASC", "GX_CC_ZERO", "GX_CC_ZERO", "GX_CC_ZERO"}, sd,
                               "Stage 0: out = COLOR0 x " + std::to_string(sd)));
  p.stages.back().frame_scale = TevStagePlan::FrameScale::Diffuse;
  p.pixel = pixel_engine(pass);
  p.figures.diffuse_only = true;
  p.figures.light = first_light;
  p.figures.diffuse_scale = sd;
  p.figures.diffuse_saturates = magnitude > kMaxScale;
  return p;
}

// The scales of one light's pass, and what its term needs (generator.h).
PassChoice PassPlanner::choose(int m, size_t l, const MapTexture* map) const {
  const Material& mat = scene_.materials[static_cast<size_t>(m)];
  const Translucency& tr = *mat.translucency;
  const Light& light = scene_.lights[l];
  const LightStats st = light_stats(scene_, m, light, variant_.light_range);
  PassChoice c;
  c.vertex_t = tr.thickness_source == ThicknessSource::Vertex;
  c.xf = variant_.lobe == GxVariant::Lobe::XfSpec;
  const double s = light.translucency_scale, a = tr.ambient;
  // Constant thickness: the material register holds T normalised to its largest component;
  // vertex thickness: the baked colour as sent, the tint moves into the light colour; a
  // thickness map: a TEV stage multiplies the texel in (GX_TEXMAP1), the material register is
  // white, the tint and the map's scale move into the light colour.
  c.T = map ? glm::dvec3(1) : model::thickness(tr, glm::dvec3(1));
  c.t_max = map ? map->scale : c.vertex_t ? 1.0 : max3(c.T);
  c.trans_color = light.color * mat.albedo * (c.vertex_t || map ? tr.tint : glm::dvec3(1));
  c.s0 = max3(c.trans_color) * (a + s) * c.t_max;  // magnitude of COLOR0 at att = 1
  c.translucent = c.s0 > 0;
  // w = 1 everywhere: no lobe to look up (a ramp is a lobe whatever the power)
  const bool flat = (!tr.ramp && tr.power == 0) || s == 0;
  c.lut = c.translucent && !c.xf && !flat;
  c.uses_map = c.translucent && map;
  c.diffuse_mag = (l == 0 ? max3(scene_.ambient_light) : 0.0) + st.max_diffuse * max3(light.color);
  c.sd = scale_for(c.diffuse_mag);
  c.max_attenuation = st.max_attenuation;
  return c;
}

PassPlan PassPlanner::light_pass(int m, size_t l, const std::optional<TexturePlan>& lut,
                                 const MapTexture* map) {
  const Material& mat = scene_.materials[static_cast<size_t>(m)];
  const Light& light = scene_.lights[l];
  const PassChoice c = choose(m, l, map);
  // t=texgen's and lobe=xf-spec's V and L (object_view.h); a specular light's magnitude is the
  // attenuation at the object's centre (1 but for view=object and a point light).
  const ConstantView cv = constant_view(scene_, variant_, material_centre(scene_, m), light);
  const double trans_mag = (c.xf ? cv.attenuation : c.max_attenuation) * c.s0;
  const int st_scale = std::max(c.sd, scale_for(trans_mag));
  // base=tev: a directional light's attenuation is 1 at every vertex, so its translucency base
  // is one colour per pass, K, which the TEV multiplies in at full 8-bit precision per
  // component; through the XF it is the light's colour normalised to 255 at its largest
  // component (blue 24 on baked_blob) and truncated twice (the sum, then the material multiply),
  // then scaled up to x4 by the TEV (docs/advise.md, "What the gx error is made of").
  std::optional<glm::dvec3> base;
  if (variant_.base_in_tev && c.lut && !c.uses_map && light.type == Light::Type::Directional)
    base = c.trans_color * (mat.translucency->ambient + light.translucency_scale) * c.t_max /
           double(st_scale);
  PassPlan p;
  p.vertex.colour = c.translucent && c.vertex_t;
  p.vertex.t = c.lut && variant_.t == GxVariant::TexCoord::Vertex;
  p.vertex.uv = c.uses_map;
  const glm::dvec3 pos = light_position_eye(view_, light);
  if (c.translucent && c.xf) {
    p.lights.push_back(specular_light(*mat.translucency, light, cv, c.trans_color,
                                      st_scale / (c.s0 * cv.attenuation), p.figures));
  } else if (c.translucent && !base) {
    p.lights.push_back(
        distance_light("trans_light", 0, pos, c.trans_color, light, c.s0 / st_scale));
  }
  p.lights.push_back(
      distance_light("diffuse_light", 1, pos, light.color, light, max3(light.color) / c.sd));
  light_channels(p, c, c.T / c.t_max, map != nullptr, mat.albedo, l == 0, base.has_value());
  if (c.lut) p.texgens.push_back(lut_texgen(*mat.translucency, cv, *lut));
  if (c.uses_map) p.texgens.push_back(map_texgen(*map, c.lut ? 1 : 0, p.vertex.uv_attribute()));
  light_stages(p, c, *mat.translucency, light, st_scale, base);
  p.pixel = pixel_engine(static_cast<int>(l));
  p.figures.light = l;
  p.figures.translucency_scale = st_scale;
  p.figures.diffuse_scale = c.sd;
  p.figures.thickness_scale = c.t_max;
  p.figures.translucency_saturates = trans_mag > kMaxScale;
  p.figures.diffuse_saturates = c.diffuse_mag > kMaxScale;
  return p;
}

// COLOR0A0 carries the translucency base (or nothing), COLOR1A1 the diffuse.
void PassPlanner::light_channels(PassPlan& p, const PassChoice& c, const glm::dvec3& T_norm,
                                 bool map, const glm::dvec3& albedo, bool first_pass,
                                 bool base_in_tev) const {
  ChannelPlan c0;
  if (base_in_tev) {
    // Lighting off: the channel is the material colour as it is, the vertex colour with no
    // multiply and no truncation [DSW TransformColor], or the constant thickness.
    c0.enable = {"GX_DISABLE"};
    if (c.vertex_t) c0.material_source = {"GX_SRC_VTX"};
    c0.diffuse_fn = {"GX_DF_NONE"};
    c0.attenuation_fn = {"GX_AF_NONE"};
    c0.what = "COLOR0A0 = T, unlit: the translucency base is KCOLOR0, in the TEV";
    if (!c.vertex_t) c0.material = rgb8(T_norm);
  } else if (c.translucent) {
    if (c.vertex_t) c0.material_source = {"GX_SRC_VTX"};
    c0.lights = {1, true};
    c0.diffuse_fn = {"GX_DF_NONE"};
    c0.attenuation_fn =
        c.xf ? GxConst<NameGroup::AttnFn>{"GX_AF_SPEC"} : GxConst<NameGroup::AttnFn>{"GX_AF_SPOT"};
    c0.what = c.xf ? "COLOR0A0 = T x clamp(light x albedo x (a + s lobe)): the lobe fitted as "
                     "the XF\nspecular attenuation (x = N.dir, rational in x)"
                   : "COLOR0A0 = T x clamp(att x light x albedo): the translucency base";
    c0.ambient = rgb8(glm::dvec3(0));
    if (!c.vertex_t) c0.material = rgb8(T_norm);
    if (map) c0.material_what = "white: the thickness comes from the map, in the TEV";
  } else {
    c0.enable = {"GX_DISABLE"};
    c0.diffuse_fn = {"GX_DF_NONE"};
    c0.attenuation_fn = {"GX_AF_NONE"};
    c0.what = "COLOR0A0 unused: this light adds no translucency";
  }
  ChannelPlan c1;
  c1.channel = {"GX_COLOR1A1"};
  c1.lights = {2, true};
  c1.what = "COLOR1A1 = albedo x clamp(ambient + att x light x max(N.L, 0)): the diffuse";
  c1.ambient = rgb8(first_pass ? scene_.ambient_light / double(c.sd) : glm::dvec3(0));
  c1.material = rgb8(albedo);
  p.channels = {c0, c1};
}

// Stage 0 (LUT): w = lerp(a', 255, lobe); stage 1 (LUT and map): w x map; then the
// translucency (w or the map times COLOR0, scaled st/sd) and the sum with COLOR1, scaled sd.
void PassPlanner::light_stages(PassPlan& p, const PassChoice& c, const Translucency& tr,
                               const Light& light, int st_scale,
                               const std::optional<glm::dvec3>& base) const {
  const int sd = c.sd;
  int stage = 0;
  const int map_texcoord = c.lut ? 1 : 0;  // the map's texgen follows the LUT's
  const GxConst<NameGroup::TexCoord> map_coord =
      GxConst<NameGroup::TexCoord>::with_value(map_texcoord);
  if (c.lut && base) {
    // w = K (a + s lobe) / (a + s): REG0 = K a / (a + s) from the exact K, each component
    // rounded once.
    const Color8 k0 = rgb8(*base * (tr.ambient / (tr.ambient + light.translucency_scale)));
    const bool any = k0.r > 0 || k0.g > 0 || k0.b > 0;
    if (any) p.tev_register = TevRegisterPlan{{"GX_TEVREG0"}, k0, "REG0 = K a / (a + s)"};
    p.konst_color = KonstColorPlan{{"GX_KCOLOR0"},
                                   rgb8(*base),
                                   "KCOLOR0 = K = light x albedo x tint x (a + s) / " +
                                       std::to_string(st_scale) + ": the translucency base"};
    p.stages.push_back(tev_stage(stage++, {"GX_TEXCOORD0"}, {"GX_TEXMAP0"}, {"GX_COLORNULL"},
                                 {any ? GxConst<NameGroup::ColorArg>{"GX_CC_C0"}
                                      : GxConst<NameGroup::ColorArg>{"GX_CC_ZERO"},
                                  "GX_CC_KONST", "GX_CC_TEXC", "GX_CC_ZERO"},
                                 1, "Stage 0: w = lerp(REG0, K, lobe) = K (a + s lobe) / (a + s)"));
    p.stages.back().konst_color = GxConst<NameGroup::KColorSel>{"GX_TEV_KCSEL_K0"};
  } else if (c.lut) {
    const int a8 = to_unorm8(tr.ambient / (tr.ambient + light.translucency_scale));
    if (a8 > 0)
      p.tev_register = TevRegisterPlan{
          {"GX_TEVREG0"}, Color8{u8(a8), u8(a8), u8(a8), 255}, "REG0 = 255 a / (a + s)"};
    p.stages.push_back(tev_stage(
        stage++, {"GX_TEXCOORD0"}, {"GX_TEXMAP0"}, {"GX_COLORNULL"},
        {a8 ? GxConst<NameGroup::ColorArg>{"GX_CC_C0"} : GxConst<NameGroup::ColorArg>{"GX_CC_ZERO"},
         "GX_CC_ONE", "GX_CC_TEXC", "GX_CC_ZERO"},
        1, "Stage 0: w = lerp(REG0, 1, lobe) = (a + s lobe) / (a + s)"));
    // The map before COLOR0 and its scale: w x map stays below 1, so nothing saturates
    // earlier than the reference's final clamp.
    if (c.uses_map)
      p.stages.push_back(tev_stage(stage++, map_coord, {"GX_TEXMAP1"}, {"GX_COLORNULL"},
                                   {"GX_CC_ZERO", "GX_CC_CPREV", "GX_CC_TEXC", "GX_CC_ZERO"}, 1,
                                   "Stage 1: w = w x thickness (the map in GX_TEXMAP1)"));
  }
  if (c.translucent) {
    const int k = stage++;
    const std::string title = "Stage " + std::to_string(k) + ": trans = ";
    const std::string times = " x " + std::to_string(st_scale / sd);
    if (c.lut) {
      p.stages.push_back(tev_stage(k, {"GX_TEXCOORDNULL"}, {"GX_TEXMAP_NULL"}, {"GX_COLOR0A0"},
                                   {"GX_CC_ZERO", "GX_CC_CPREV", "GX_CC_RASC", "GX_CC_ZERO"},
                                   st_scale / sd, title + "w x COLOR0" + times));
    } else if (c.uses_map) {
      p.stages.push_back(tev_stage(k, map_coord, {"GX_TEXMAP1"}, {"GX_COLOR0A0"},
                                   {"GX_CC_ZERO", "GX_CC_RASC", "GX_CC_TEXC", "GX_CC_ZERO"},
                                   st_scale / sd,
                                   title + "COLOR0 x thickness (the map in GX_TEXMAP1)" + times));
    } else {
      p.stages.push_back(tev_stage(k, {"GX_TEXCOORDNULL"}, {"GX_TEXMAP_NULL"}, {"GX_COLOR0A0"},
                                   {"GX_CC_RASC", "GX_CC_ZERO", "GX_CC_ZERO", "GX_CC_ZERO"},
                                   st_scale / sd, title + "COLOR0" + times));
    }
    p.stages.back().frame_scale = TevStagePlan::FrameScale::Translucency;
  }
  p.stages.push_back(tev_stage(
      stage, {"GX_TEXCOORDNULL"}, {"GX_TEXMAP_NULL"}, {"GX_COLOR1A1"},
      {"GX_CC_RASC", "GX_CC_ZERO", "GX_CC_ZERO",
       c.translucent ? GxConst<NameGroup::ColorArg>{"GX_CC_CPREV"}
                     : GxConst<NameGroup::ColorArg>{"GX_CC_ZERO"}},
      sd, "Stage " + std::to_string(stage) + ": out = (trans + COLOR1) x " + std::to_string(sd)));
  p.stages.back().frame_scale = TevStagePlan::FrameScale::Diffuse;
}

size_t sent_t_light(const MaterialPlan& m, size_t pass) {
  LT_CHECK(pass < m.passes.size() && m.passes[pass].vertex.t, "the pass sends no t");
  LT_CHECK(m.passes[pass].figures.light == pass,
           "pass " + std::to_string(pass) + " of " + m.name + " sends light " +
               std::to_string(m.passes[pass].figures.light) +
               "'s t, which the emulator would take for light " + std::to_string(pass) + "'s");
  return pass;
}

}  // namespace lt::gx
