#include "paths/gx/generator.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.h"
#include "image/image.h"
#include "model/rational_fit.h"
#include "model/translucency.h"
#include "paths/gx/lobe_lut.h"
#include "paths/gx/program/gx_names.h"
#include "paths/gx/program/pass_programs.h"
#include "paths/gx/texture_unit.h"
#include "paths/gx/thickness_texture.h"

namespace lt::gx {

SceneView SceneView::of(const Scene& scene) {
  SceneView v;
  v.eye = scene.camera.eye;
  // The same view as gl::SceneGeometry, so every path sees one camera.
  v.view = glm::dmat3(scene.camera.view_from_origin());
  return v;
}

namespace {

// A directional light is a point light this far away in eye space: libogc's own "large number"
// for lights at infinity [OGC gx.c L23-25, GX_InitSpecularDir], small enough that |v|^2 (1e36)
// stays finite in float.
constexpr double kFarAway = 1.0e18;

// How far past the silhouette (N.V < 0) a vertex still counts as possibly seen.
constexpr double kBackFacing = 0.2;

// The TEV and XF scales: x1, x2, x4 (GX_CS_SCALE_*). Magnitudes up to 4 are exact.
constexpr double kMaxScale = 4;

Arg gx(const std::string& name) {
  const GxName* n = find_gx_name(name);
  LT_CHECK(n != nullptr, "generator uses an unknown GX name " + name);
  return Arg::integer(n->name, n->value);
}
Arg gx(const std::string& prefix, int index) {
  return gx(prefix + std::to_string(index));
}
Arg num(double v) {
  return Arg::f32(static_cast<float>(v));
}
Arg lit(long long v) {
  return Arg::literal(v);
}
Arg rgb(const glm::dvec3& c, double alpha = 1.0) {
  return Arg::rgba({to_unorm8(c.r), to_unorm8(c.g), to_unorm8(c.b), to_unorm8(alpha)});
}

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double max3(const glm::dvec3& v) {
  return std::max({v.r, v.g, v.b});
}

// The smallest of x1, x2, x4 that holds `magnitude`; 4 where even that is too small (the
// channel then saturates, and the pass says so).
int scale_for(double magnitude) {
  for (int s : {1, 2, 4}) {
    if (magnitude <= s * (1 + 1e-9)) return s;
  }
  return static_cast<int>(kMaxScale);
}
const char* scale_name(int s) {
  return s == 1 ? "GX_CS_SCALE_1" : s == 2 ? "GX_CS_SCALE_2" : "GX_CS_SCALE_4";
}

// One program being written: statements in order, with comments for the porter.
class Writer {
 public:
  void call(const std::string& f, std::vector<Arg> args, const std::string& comment = "") {
    body.push_back(Statement::of(Call(f, std::move(args)), comment));
  }
  void declare(Declaration::Type t, const std::string& name, std::vector<double> values = {},
               const std::string& comment = "") {
    Declaration d;
    d.type = t;
    d.name = name;
    d.values = std::move(values);
    body.push_back(Statement::of(std::move(d), comment));
  }
  std::vector<Statement> body;
};

// What the lights do at the vertices of one material, in double (the generator's CPU side):
// the largest attenuation, and the largest diffuse sum, to choose the scales.
struct LightStats {
  double max_attenuation = 0;
  double max_diffuse = 0;  // max over vertices of att * max(N.L, 0)
};

LightStats light_stats(const Scene& scene, int material, const Light& light) {
  LightStats st;
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

// A light object: colour normalised to 255 at its largest component; attenuation k scaled by
// 1/gain, so the XF computes gain * att * colour. Spot off (a = 1, 0, 0) and a finite direction:
// the object is application memory and a garbage direction can poison 0 * x terms
// (gx-hardware.md §5.2, Dolphin PR#10475).
void light_object(Writer& w, const std::string& name, const glm::dvec3& pos_eye,
                  const glm::dvec3& color, const Light& light, double gain, const char* slot) {
  const double m = max3(color);
  const glm::dvec3 c = m > 0 ? color / m : glm::dvec3(0);
  const double g = m > 0 && gain > 0 ? gain : 1.0;
  const double kc = light.type == Light::Type::Point ? light.kc : 1.0;
  const double kl = light.type == Light::Type::Point ? light.kl : 0.0;
  const double kq = light.type == Light::Type::Point ? light.kq : 0.0;
  w.declare(Declaration::Type::LightObj, name);
  w.call("GX_InitLightPos",
         {Arg::address_of(name), num(pos_eye.x), num(pos_eye.y), num(pos_eye.z)});
  w.call("GX_InitLightColor", {Arg::address_of(name), rgb(c)});
  w.call("GX_InitLightDir", {Arg::address_of(name), num(0), num(0), num(-1)});
  w.call("GX_InitLightSpot", {Arg::address_of(name), num(90), gx("GX_SP_OFF")});
  w.call("GX_InitLightAttnK", {Arg::address_of(name), num(kc / g), num(kl / g), num(kq / g)},
         "k = (kc, kl, kq) / " + fmt(g) + ": XF attenuation = " + fmt(g) +
             " x att, the light's magnitude");
  w.call("GX_LoadLightObj", {Arg::address_of(name), gx(slot)});
}

// The UV of a thickness map rides in the texture coordinate after t (GX_VA_TEX1 when t is sent,
// else GX_VA_TEX0): the XF is told only how many texture coordinates arrive (program_check.h),
// so they are declared without a gap.
int uv_attribute(bool texcoord) {
  return texcoord ? 1 : 0;
}

void vertex_format(Writer& w, bool colour, bool texcoord, bool uv = false) {
  w.call("GX_ClearVtxDesc", {},
         uv ? "Vertex format: position and normal (and t) as sent, and the mesh's UV for the "
              "thickness map"
            : "Vertex format: position and normal (and the baked thickness colour / t) as sent");
  w.call("GX_SetVtxDesc", {gx("GX_VA_POS"), gx("GX_DIRECT")});
  w.call("GX_SetVtxDesc", {gx("GX_VA_NRM"), gx("GX_DIRECT")});
  if (colour) w.call("GX_SetVtxDesc", {gx("GX_VA_CLR0"), gx("GX_DIRECT")});
  if (texcoord) w.call("GX_SetVtxDesc", {gx("GX_VA_TEX0"), gx("GX_DIRECT")});
  const Arg uv_va = gx("GX_VA_TEX", uv_attribute(texcoord));
  if (uv) w.call("GX_SetVtxDesc", {uv_va, gx("GX_DIRECT")});
  w.call("GX_SetVtxAttrFmt",
         {gx("GX_VTXFMT0"), gx("GX_VA_POS"), gx("GX_POS_XYZ"), gx("GX_F32"), lit(0)});
  w.call("GX_SetVtxAttrFmt",
         {gx("GX_VTXFMT0"), gx("GX_VA_NRM"), gx("GX_NRM_XYZ"), gx("GX_F32"), lit(0)});
  if (colour)
    w.call("GX_SetVtxAttrFmt",
           {gx("GX_VTXFMT0"), gx("GX_VA_CLR0"), gx("GX_CLR_RGBA"), gx("GX_RGBA8"), lit(0)});
  if (texcoord)
    w.call("GX_SetVtxAttrFmt",
           {gx("GX_VTXFMT0"), gx("GX_VA_TEX0"), gx("GX_TEX_S"), gx("GX_F32"), lit(0)});
  if (uv)
    w.call("GX_SetVtxAttrFmt", {gx("GX_VTXFMT0"), uv_va, gx("GX_TEX_ST"), gx("GX_F32"), lit(0)});
}

// Pass 0 replaces what the EFB holds; later passes add onto it: min(src + dst, 255) per channel
// (ONE, ONE through the f + (f >> 7) factor rule [DSW BlendColor]), with the depth of pass 0
// tested but not rewritten.
void pixel_engine(Writer& w, int pass) {
  if (pass == 0) {
    w.call("GX_SetBlendMode",
           {gx("GX_BM_NONE"), gx("GX_BL_ONE"), gx("GX_BL_ZERO"), gx("GX_LO_CLEAR")},
           "Pixel engine: the first pass replaces the EFB colour");
    w.call("GX_SetZMode", {gx("GX_TRUE"), gx("GX_LEQUAL"), gx("GX_TRUE")});
  } else {
    w.call("GX_SetBlendMode",
           {gx("GX_BM_BLEND"), gx("GX_BL_ONE"), gx("GX_BL_ONE"), gx("GX_LO_CLEAR")},
           "Pixel engine: add this light onto the passes before (saturates at 255)");
    w.call("GX_SetZMode", {gx("GX_TRUE"), gx("GX_LEQUAL"), gx("GX_FALSE")});
  }
  w.call("GX_SetAlphaCompare",
         {gx("GX_ALWAYS"), lit(0), gx("GX_AOP_AND"), gx("GX_ALWAYS"), lit(0)});
  // Every face, as the other paths draw them: the depth test keeps the nearest. GX_Init leaves
  // GX_CULL_BACK, which on GX removes the faces GL calls front (gx_state.h), so a pass that
  // set nothing would show a GL-wound mesh from the inside.
  w.call("GX_SetCullMode", {gx("GX_CULL_NONE")},
         "Draw both sides (GX_Init's GX_CULL_BACK would cull the faces wound counter-clockwise)");
}

// Colour in/op of one stage, and an alpha of 255 (KASEL 1): the EFB keeps no alpha (RGB8_Z24).
void tev_stage(Writer& w, int stage, const std::string& texcoord, const std::string& texmap,
               const std::string& channel, std::array<const char*, 4> in, int scale,
               const std::string& comment) {
  const Arg s = gx("GX_TEVSTAGE", stage);
  w.call("GX_SetTevOrder", {s, gx(texcoord), gx(texmap), gx(channel)}, comment);
  w.call("GX_SetTevColorIn", {s, gx(in[0]), gx(in[1]), gx(in[2]), gx(in[3])});
  w.call("GX_SetTevColorOp", {s, gx("GX_TEV_ADD"), gx("GX_TB_ZERO"), gx(scale_name(scale)),
                              gx("GX_TRUE"), gx("GX_TEVPREV")});
  w.call("GX_SetTevAlphaIn",
         {s, gx("GX_CA_ZERO"), gx("GX_CA_ZERO"), gx("GX_CA_ZERO"), gx("GX_CA_KONST")});
  w.call("GX_SetTevKAlphaSel", {s, gx("GX_TEV_KASEL_1")});
  w.call("GX_SetTevAlphaOp", {s, gx("GX_TEV_ADD"), gx("GX_TB_ZERO"), gx("GX_CS_SCALE_1"),
                              gx("GX_TRUE"), gx("GX_TEVPREV")});
}

struct PassPlan {
  std::vector<Statement> body;
  std::string note;
};

// A material's lobe LUT as the program holds it: the u8 array (empty: no LUT) and its format.
struct LutArray {
  std::string name;
  const char* format = "GX_TF_I8";
};

// A material's thickness map as the program holds it: the u8 array and the texture it makes.
struct MapArray {
  std::string name;
  ThicknessTexture texture;
};

class Generator {
 public:
  Generator(const Scene& scene, const GxVariant& v)
      : scene_(scene), variant_(v), view_(SceneView::of(scene)) {}

  GeneratedPrograms run() {
    GeneratedPrograms out;
    std::set<std::string> ids;
    std::vector<bool> used(scene_.materials.size(), false);
    for (const SceneObject& o : scene_.objects) used[static_cast<size_t>(o.material)] = true;
    for (size_t m = 0; m < scene_.materials.size(); ++m) {
      if (!used[m]) continue;
      const Material& mat = scene_.materials[m];
      if (!ids.insert(c_identifier(mat.name)).second)
        throw InputError(scene_.file.string(), "materials." + mat.name,
                         "gx: two materials share the C name " + c_identifier(mat.name));
      std::vector<PassPlan> passes = material_passes(static_cast<int>(m), out.file);
      for (size_t p = 0; p < passes.size(); ++p) {
        Function f;
        f.name = pass_function_name(mat.name, static_cast<int>(p));
        f.comment = "Material " + mat.name + ", pass " + std::to_string(p) + ": " + passes[p].note;
        f.body = std::move(passes[p].body);
        out.notes[f.name] = passes[p].note;
        out.file.functions.push_back(std::move(f));
      }
    }
    return out;
  }

 private:
  std::vector<PassPlan> material_passes(int m, ProgramFile& file) {
    const Material& mat = scene_.materials[static_cast<size_t>(m)];
    std::vector<PassPlan> out;
    if (!mat.translucency || scene_.lights.empty()) {
      // Diffuse only: the XF sums up to 8 lights in one channel, one stage shows it.
      for (size_t first = 0; first < std::max<size_t>(scene_.lights.size(), 1); first += 8)
        out.push_back(diffuse_pass(m, static_cast<int>(out.size()), first));
      return out;
    }
    const Translucency& tr = *mat.translucency;
    const bool flat_lobe = !tr.ramp && tr.power == 0;
    LutArray lut;
    if (variant_.lobe == GxVariant::Lobe::Lut && !flat_lobe) lut = lut_array(mat, file);
    std::optional<MapArray> map;
    if (const std::optional<MapTexels> texels = thickness_map_texels(mat))
      map = map_array(mat, *texels, file);
    for (size_t l = 0; l < scene_.lights.size(); ++l)
      out.push_back(light_pass(m, l, lut, map ? &*map : nullptr));
    return out;
  }

  // The thickness map as GX_TEXMAP1's texture (thickness_texture.h), one u8 array per material
  // that every pass loads.
  MapArray map_array(const Material& mat, const MapTexels& texels, ProgramFile& file) {
    if (texels.width > kMaxTextureSize || texels.height > kMaxTextureSize)
      throw InputError(scene_.file.string(), "materials." + mat.name + ".translucency.thickness",
                       "gx: the thickness map is " + std::to_string(texels.width) + "x" +
                           std::to_string(texels.height) +
                           " texels; a GX texture is at most 1024 a side (resize the map)");
    MapArray a;
    a.texture = thickness_texture(texels.width, texels.height, *texels.rgb, texels.grey,
                                  variant_.map_rgb565);
    a.name = "ltrender_thickness_" + c_identifier(mat.name);
    const TextureObject& t = a.texture.texture;
    Declaration d;
    d.type = Declaration::Type::ByteArray;
    d.name = a.name;
    d.values.assign(t.data.begin(), t.data.end());
    const bool i8 = t.format == kTexFormatI8, rgba8 = t.format == kTexFormatRGBA8;
    file.top_level.push_back(Statement::of(
        d, "Thickness map of material " + mat.name + ": " + std::to_string(t.width) + "x" +
               std::to_string(t.height) + " texels " + a.texture.format_name +
               " in GX tile order (" +
               (i8      ? "8x4 tiles of 32 bytes"
                : rgba8 ? "4x4 tiles of 64 bytes: 16 (a, r) pairs, then 16 (g, b) pairs"
                        : "4x4 tiles of 32 bytes, big-endian r5 g6 b5") +
               "),\nrows from the image's bottom row up (v = 0 first), so the identity texgen's "
               "t = v reads the\ntexel a GL path samples at (u, v); a converter that stores the "
               "top row first needs\nt = 1 - v (a texture matrix with row 1 = (0, -1, 0, 1)). A "
               "texel of 255 is thickness " +
               fmt(a.texture.scale) + ". Flush it (DCFlushRange)\nbefore the GPU reads it."));
    return a;
  }

  // The lobe LUT as a texture of one row in GX tile order (lobe_lut.h): t^p, or the material's
  // lobe ramp.
  LutArray lut_array(const Material& mat, ProgramFile& file) {
    const int w = variant_.lut_size;
    const Translucency& tr = *mat.translucency;
    if (tr.ramp) {
      const std::vector<float>& v = tr.ramp->texture.texels;
      const float top = v.empty() ? 0.0f : *std::max_element(v.begin(), v.end());
      if (top > 1.0f)
        throw InputError(
            scene_.file.string(), "materials." + mat.name + ".translucency.ramp",
            "gx: the ramp holds values up to " + fmt(top) + "; the 8-bit lobe LUT holds 0..1");
    }
    const TextureObject lut = lobe_lut(mat, w);
    LutArray a;
    a.name = "ltrender_lut_" + c_identifier(mat.name);
    a.format = lut.format == kTexFormatI8 ? "GX_TF_I8" : "GX_TF_RGBA8";
    Declaration d;
    d.type = Declaration::Type::ByteArray;
    d.name = a.name;
    d.values.assign(lut.data.begin(), lut.data.end());
    const std::string what =
        tr.ramp ? "the lobe ramp " + tr.ramp->file.filename().string() + " sampled at t"
                : "lobe(t) = t^" + fmt(tr.power);
    file.top_level.push_back(Statement::of(
        d, (tr.ramp ? "Lobe LUT" : "Power LUT") + std::string(" of material ") + mat.name + ": " +
               what + ", " + std::to_string(w) + " texels " + a.format + " in GX tile order (" +
               (lut.format == kTexFormatI8 ? "8x4 tiles, 32 bytes"
                                           : "4x4 tiles, 64 bytes: (a, r) then (g, b) pairs") +
               ";\nrow 0 of each tile used). Flush it (DCFlushRange) before the GPU reads it."));
    return a;
  }

  PassPlan diffuse_pass(int m, int pass, size_t first_light) {
    const Material& mat = scene_.materials[static_cast<size_t>(m)];
    Writer w;
    vertex_format(w, false, false);
    const size_t last = std::min(scene_.lights.size(), first_light + 8);
    // The largest sum the channel holds before the material multiply.
    double magnitude = pass == 0 ? max3(scene_.ambient_light) : 0.0;
    for (size_t l = first_light; l < last; ++l) {
      const Light& light = scene_.lights[l];
      magnitude += light_stats(scene_, m, light).max_diffuse * max3(light.color);
    }
    const int sd = scale_for(magnitude);
    int mask = 0;
    for (size_t l = first_light; l < last; ++l) {
      const Light& light = scene_.lights[l];
      const std::string name = "light" + std::to_string(l);
      const int slot = static_cast<int>(l - first_light);
      light_object(w, name, light_position_eye(view_, light), light.color, light,
                   max3(light.color) / sd, ("GX_LIGHT" + std::to_string(slot)).c_str());
      mask |= 1 << slot;
    }
    w.call("GX_SetNumChans", {lit(1)},
           "COLOR0A0 = albedo x clamp(ambient + sum of lights' diffuse)");
    Arg lights = lit(mask);
    if (mask == 0) lights = gx("GX_LIGHTNULL");
    w.call("GX_SetChanCtrl", {gx("GX_COLOR0A0"), gx("GX_ENABLE"), gx("GX_SRC_REG"),
                              gx("GX_SRC_REG"), lights, gx("GX_DF_CLAMP"), gx("GX_AF_SPOT")});
    w.call("GX_SetChanAmbColor",
           {gx("GX_COLOR0A0"), rgb(pass == 0 ? scene_.ambient_light / double(sd) : glm::dvec3(0))});
    w.call("GX_SetChanMatColor", {gx("GX_COLOR0A0"), rgb(mat.albedo)});
    w.call("GX_SetNumTexGens", {lit(0)});
    w.call("GX_SetNumTevStages", {lit(1)});
    tev_stage(w, 0, "GX_TEXCOORDNULL", "GX_TEXMAP_NULL", "GX_COLOR0A0",
              {"GX_CC_RASC", "GX_CC_ZERO", "GX_CC_ZERO", "GX_CC_ZERO"}, sd,
              "Stage 0: out = COLOR0 x " + std::to_string(sd));
    pixel_engine(w, pass);
    std::string note = "diffuse only, 1 stage, scale x" + std::to_string(sd);
    if (magnitude > kMaxScale) note += "; diffuse over x4 saturates";
    return {std::move(w.body), note};
  }

  PassPlan light_pass(int m, size_t l, const LutArray& lut_array, const MapArray* map) {
    const Material& mat = scene_.materials[static_cast<size_t>(m)];
    const Translucency& tr = *mat.translucency;
    const Light& light = scene_.lights[l];
    const int pass = static_cast<int>(l);
    const LightStats st = light_stats(scene_, m, light);
    const bool vertex_t = tr.thickness_source == ThicknessSource::Vertex;
    const bool xf = variant_.lobe == GxVariant::Lobe::XfSpec;
    const double s = light.translucency_scale, a = tr.ambient;
    // Constant thickness: the material register holds T normalised to its largest component;
    // vertex thickness: the baked colour as sent, the tint moves into the light colour; a
    // thickness map: a TEV stage multiplies the texel in (GX_TEXMAP1), the material register is
    // white, the tint and the map's scale move into the light colour.
    const glm::dvec3 T = map ? glm::dvec3(1) : model::thickness(tr, glm::dvec3(1));
    const double t_max = map ? map->texture.scale : vertex_t ? 1.0 : max3(T);
    const glm::dvec3 trans_color =
        light.color * mat.albedo * (vertex_t || map ? tr.tint : glm::dvec3(1));
    const double s0 = max3(trans_color) * (a + s) * t_max;  // magnitude of COLOR0 at att = 1
    const bool translucent = s0 > 0;
    // w = 1 everywhere: no lobe to look up (a ramp is a lobe whatever the power)
    const bool flat = (!tr.ramp && tr.power == 0) || s == 0;
    const bool lut = translucent && !xf && !flat;
    const bool uses_map = translucent && map;

    const double diffuse_mag =
        (pass == 0 ? max3(scene_.ambient_light) : 0.0) + st.max_diffuse * max3(light.color);
    const int sd = scale_for(diffuse_mag);
    const double trans_mag = (xf ? 1.0 : st.max_attenuation) * s0;
    const int st_scale = std::max(sd, scale_for(trans_mag));

    Writer w;
    const bool t_attribute = lut && variant_.t == GxVariant::TexCoord::Vertex;
    vertex_format(w, translucent && vertex_t, t_attribute, uses_map);
    const glm::dvec3 pos = light_position_eye(view_, light);
    model::RationalFit fit;
    glm::dvec3 spec_dir(0);
    if (translucent && xf) {
      fit = lobe_fit(tr, light, spec_dir);
      xf_spec_light(w, trans_color, st_scale / s0, fit.r, spec_dir);
    } else if (translucent) {
      light_object(w, "trans_light", pos, trans_color, light, s0 / st_scale, "GX_LIGHT0");
    }
    light_object(w, "diffuse_light", pos, light.color, light, max3(light.color) / sd, "GX_LIGHT1");

    w.call("GX_SetNumChans", {lit(2)});
    if (translucent) {
      w.call("GX_SetChanCtrl",
             {gx("GX_COLOR0A0"), gx("GX_ENABLE"), gx("GX_SRC_REG"),
              gx(vertex_t ? "GX_SRC_VTX" : "GX_SRC_REG"), gx("GX_LIGHT0"), gx("GX_DF_NONE"),
              gx(xf ? "GX_AF_SPEC" : "GX_AF_SPOT")},
             xf ? "COLOR0A0 = T x clamp(light x albedo x (a + s lobe)): the lobe fitted as the XF\n"
                  "specular attenuation (x = N.dir, rational in x)"
                : "COLOR0A0 = T x clamp(att x light x albedo): the translucency base");
      w.call("GX_SetChanAmbColor", {gx("GX_COLOR0A0"), rgb(glm::dvec3(0))});
      if (!vertex_t)
        w.call("GX_SetChanMatColor", {gx("GX_COLOR0A0"), rgb(T / t_max)},
               map ? "white: the thickness comes from the map, in the TEV" : "");
    } else {
      w.call("GX_SetChanCtrl",
             {gx("GX_COLOR0A0"), gx("GX_DISABLE"), gx("GX_SRC_REG"), gx("GX_SRC_REG"),
              gx("GX_LIGHTNULL"), gx("GX_DF_NONE"), gx("GX_AF_NONE")},
             "COLOR0A0 unused: this light adds no translucency");
    }
    w.call("GX_SetChanCtrl",
           {gx("GX_COLOR1A1"), gx("GX_ENABLE"), gx("GX_SRC_REG"), gx("GX_SRC_REG"), gx("GX_LIGHT1"),
            gx("GX_DF_CLAMP"), gx("GX_AF_SPOT")},
           "COLOR1A1 = albedo x clamp(ambient + att x light x max(N.L, 0)): the diffuse");
    w.call("GX_SetChanAmbColor",
           {gx("GX_COLOR1A1"), rgb(pass == 0 ? scene_.ambient_light / double(sd) : glm::dvec3(0))});
    w.call("GX_SetChanMatColor", {gx("GX_COLOR1A1"), rgb(mat.albedo)});

    int stage = 0;
    std::ostringstream note;
    const int map_texcoord = lut ? 1 : 0;  // the map's texgen follows the LUT's
    const int texgens = (lut ? 1 : 0) + (uses_map ? 1 : 0);
    if (lut) {
      texture_coordinates(w, tr, light, texgens);
      w.declare(Declaration::Type::TexObj, "lut");
      w.call("GX_InitTexObj",
             {Arg::address_of("lut"), Arg::identifier(lut_array.name), lit(variant_.lut_size),
              lit(1), gx(lut_array.format), gx("GX_CLAMP"), gx("GX_CLAMP"), gx("GX_FALSE")},
             std::string("The LUT: ") + (lut_array.format + 6) +
                 ", linear, clamped (the clamp saturates t per pixel)");
      w.call("GX_LoadTexObj", {Arg::address_of("lut"), gx("GX_TEXMAP0")});
    } else {
      w.call("GX_SetNumTexGens", {lit(texgens)});
    }
    if (uses_map) map_texture(w, *map, map_texcoord, uv_attribute(t_attribute));
    const int stages = (lut ? 1 : 0) + (lut && uses_map ? 1 : 0) + (translucent ? 1 : 0) + 1;
    w.call("GX_SetNumTevStages", {lit(stages)});
    if (lut) {
      const int a8 = to_unorm8(a / (a + s));
      if (a8 > 0)
        w.call("GX_SetTevColor", {gx("GX_TEVREG0"), Arg::rgba({a8, a8, a8, 255})},
               "REG0 = 255 a / (a + s)");
      tev_stage(w, stage++, "GX_TEXCOORD0", "GX_TEXMAP0", "GX_COLORNULL",
                {a8 ? "GX_CC_C0" : "GX_CC_ZERO", "GX_CC_ONE", "GX_CC_TEXC", "GX_CC_ZERO"}, 1,
                "Stage 0: w = lerp(REG0, 1, lobe) = (a + s lobe) / (a + s)");
      // The map before COLOR0 and its scale: w x map stays below 1, so nothing saturates
      // earlier than the reference's final clamp.
      if (uses_map)
        tev_stage(w, stage++, "GX_TEXCOORD" + std::to_string(map_texcoord), "GX_TEXMAP1",
                  "GX_COLORNULL", {"GX_CC_ZERO", "GX_CC_CPREV", "GX_CC_TEXC", "GX_CC_ZERO"}, 1,
                  "Stage 1: w = w x thickness (the map in GX_TEXMAP1)");
    }
    if (translucent) {
      const int k = stage++;
      const std::string title = "Stage " + std::to_string(k) + ": trans = ";
      const std::string times = " x " + std::to_string(st_scale / sd);
      if (lut) {
        tev_stage(w, k, "GX_TEXCOORDNULL", "GX_TEXMAP_NULL", "GX_COLOR0A0",
                  {"GX_CC_ZERO", "GX_CC_CPREV", "GX_CC_RASC", "GX_CC_ZERO"}, st_scale / sd,
                  title + "w x COLOR0" + times);
      } else if (uses_map) {
        tev_stage(w, k, "GX_TEXCOORD" + std::to_string(map_texcoord), "GX_TEXMAP1", "GX_COLOR0A0",
                  {"GX_CC_ZERO", "GX_CC_RASC", "GX_CC_TEXC", "GX_CC_ZERO"}, st_scale / sd,
                  title + "COLOR0 x thickness (the map in GX_TEXMAP1)" + times);
      } else {
        tev_stage(w, k, "GX_TEXCOORDNULL", "GX_TEXMAP_NULL", "GX_COLOR0A0",
                  {"GX_CC_RASC", "GX_CC_ZERO", "GX_CC_ZERO", "GX_CC_ZERO"}, st_scale / sd,
                  title + "COLOR0" + times);
      }
    }
    tev_stage(
        w, stage, "GX_TEXCOORDNULL", "GX_TEXMAP_NULL", "GX_COLOR1A1",
        {"GX_CC_RASC", "GX_CC_ZERO", "GX_CC_ZERO", translucent ? "GX_CC_CPREV" : "GX_CC_ZERO"}, sd,
        "Stage " + std::to_string(stage) + ": out = (trans + COLOR1) x " + std::to_string(sd));
    pixel_engine(w, pass);

    note << "light " << l << ", " << stages << (stages == 1 ? " stage" : " stages")
         << (lut ? ", 1 texture (LUT " + std::to_string(variant_.lut_size) + " texels)" : "")
         << (uses_map ? std::string(lut ? " + " : ", 1 texture (") + "thickness map " +
                            std::to_string(map->texture.texture.width) + "x" +
                            std::to_string(map->texture.texture.height) + " " +
                            map->texture.format_name + ", " +
                            std::to_string(map->texture.texture.data.size()) + " bytes" +
                            (lut ? "" : ")")
                      : "")
         << ", scales: translucency x" << st_scale << ", diffuse x" << sd;
    if (xf && translucent) note << ", lobe fit max error " << fmt(fit.max_error) << " of (a+s)";
    if (trans_mag > kMaxScale) note << "; translucency over x4 saturates";
    if (diffuse_mag > kMaxScale) note << "; diffuse over x4 saturates";
    return {std::move(w.body), note.str()};
  }

  // t = c0 + k . N, affine in the normal when V and L are constant (the refusal rule): c0 =
  // -V.L, k = -d V. t=vertex sends t itself as GX_VA_TEX0; t=texgen computes it from the raw
  // normal. Either way the texture matrix folds in the LUT's texel-centre remap
  // s = t (W-1)/W + 0.5/W (model/power_lut.h, gx-hardware.md §3.4).
  void texture_coordinates(Writer& w, const Translucency& tr, const Light& light, int texgens) {
    const double n = variant_.lut_size, scale = (n - 1) / n, offset = 0.5 / n;
    std::vector<double> m(12, 0.0);
    if (variant_.t == GxVariant::TexCoord::Vertex) {
      m[0] = scale;  // row 0 . (s, t, 1, 1): the TEX0 source form AB11 [OGC gx.c L2690]
      m[3] = offset;
    } else {
      // The raw normal is the mesh's world-space normal as sent (objects are pre-transformed),
      // so k stays in world space.
      const glm::dvec3 V = -scene_.camera.forward(), L = -light.direction;
      const glm::dvec3 k = -tr.distortion * V;
      const double c0 = -glm::dot(V, L);
      for (int c = 0; c < 3; ++c) m[static_cast<size_t>(c)] = k[c] * scale;
      m[3] = c0 * scale + offset;  // row 0 . (nx, ny, nz, 1): the NRM source form ABC1
    }
    w.declare(Declaration::Type::Mtx, "lut_matrix", m,
              variant_.t == GxVariant::TexCoord::Vertex
                  ? "Texgen: s = t (W-1)/W + 0.5/W from the CPU's t in GX_VA_TEX0"
                  : "Texgen: s = (c0 + k . N) (W-1)/W + 0.5/W from the raw normal");
    w.call("GX_LoadTexMtxImm", {Arg::identifier("lut_matrix"), gx("GX_TEXMTX0"), gx("GX_MTX2x4")});
    w.call("GX_SetNumTexGens", {lit(texgens)});
    w.call("GX_SetTexCoordGen",
           {gx("GX_TEXCOORD0"), gx("GX_TG_MTX2x4"),
            gx(variant_.t == GxVariant::TexCoord::Vertex ? "GX_TG_TEX0" : "GX_TG_NRM"),
            gx("GX_TEXMTX0")});
  }

  // The thickness map's texgen and texture: (s, t) = the mesh's UV through GX_IDENTITY (the map is
  // stored bottom row first, thickness_texture.h, so t = v needs no flip), fetched from
  // GX_TEXMAP1, linear and clamped as the reference's CLAMP_TO_EDGE bilinear.
  void map_texture(Writer& w, const MapArray& map, int texcoord, int uv_attr) {
    w.call("GX_SetTexCoordGen",
           {gx("GX_TEXCOORD", texcoord), gx("GX_TG_MTX2x4"), gx("GX_TG_TEX", uv_attr),
            gx("GX_IDENTITY")},
           "Texgen: (s, t) = (u, v) of the mesh, as sent in GX_VA_TEX" + std::to_string(uv_attr));
    const TextureObject& t = map.texture.texture;
    w.declare(Declaration::Type::TexObj, "thickness");
    w.call("GX_InitTexObj",
           {Arg::address_of("thickness"), Arg::identifier(map.name), lit(t.width), lit(t.height),
            gx(map.texture.format_name), gx("GX_CLAMP"), gx("GX_CLAMP"), gx("GX_FALSE")},
           std::string("The thickness map: ") + map.texture.format_name + ", linear, clamped");
    w.call("GX_LoadTexObj", {Arg::address_of("thickness"), gx("GX_TEXMAP1")});
  }

  // lobe=xf-spec: x = max(0, N . u) with u = -+k in eye space (the sign that makes x >= 0 on
  // front faces, where N . V >= 0), so t = c0 + sign x with x in [0, |d|]; the curve
  // (a + s lobe(sat(t))) / (a + s) is fitted as a rational of x in double.
  model::RationalFit lobe_fit(const Translucency& tr, const Light& light, glm::dvec3& dir_eye) {
    const glm::dvec3 V = -scene_.camera.forward(), L = -light.direction;
    const double c0 = -glm::dot(V, L), d = tr.distortion;
    const double sign = d >= 0 ? -1.0 : 1.0;
    const glm::dvec3 k_eye = view_.view * (-d * V);
    dir_eye = d >= 0 ? -k_eye : k_eye;
    const double a = tr.ambient, s = light.translucency_scale, p = tr.power;
    return model::fit_rational22(
        [&](double x) {
          return (a + s * model::lobe(std::clamp(c0 + sign * x, 0.0, 1.0), p)) / (a + s);
        },
        std::abs(d));
  }

  // The specular light: its position far along V (so N . l >= 0 on front faces and the XF's
  // condition passes), the direction slot u, and the fit's coefficients with the numerator
  // scaled by the channel's magnitude.
  void xf_spec_light(Writer& w, const glm::dvec3& color, double inv_gain,
                     const model::Rational22& r, const glm::dvec3& dir_eye) {
    const double m = max3(color);
    const double g = m > 0 ? 1.0 / inv_gain : 0.0;
    const glm::dvec3 V_eye = view_.view * -scene_.camera.forward();
    const glm::dvec3 pos = V_eye * kFarAway;
    const std::string name = "trans_light";
    w.declare(Declaration::Type::LightObj, name);
    w.call("GX_InitLightPos", {Arg::address_of(name), num(pos.x), num(pos.y), num(pos.z)});
    w.call("GX_InitLightColor", {Arg::address_of(name), rgb(m > 0 ? color / m : glm::dvec3(0))});
    // GX_InitLightDir stores the negated direction: pass -u so the slot holds u.
    w.call("GX_InitLightDir",
           {Arg::address_of(name), num(-dir_eye.x), num(-dir_eye.y), num(-dir_eye.z)});
    w.call("GX_InitLightAttn",
           {Arg::address_of(name), num(r.a[0] * g), num(r.a[1] * g), num(r.a[2] * g), num(r.k[0]),
            num(r.k[1]), num(r.k[2])},
           "A(x) = (a0 + a1 x + a2 x^2) / (k0 + k1 x + k2 x^2), fitted to the lobe");
    w.call("GX_LoadLightObj", {Arg::address_of(name), gx("GX_LIGHT0")});
  }

  const Scene& scene_;
  GxVariant variant_;
  SceneView view_;
};

}  // namespace

GeneratedPrograms generate_programs(const Scene& scene, const GxVariant& variant) {
  const std::string why = refusal(scene, variant);
  if (!why.empty()) throw InputError("--variant", to_string(variant), "gx: " + why);
  return Generator(scene, variant).run();
}

}  // namespace lt::gx
