// The planner's textures: the lobe LUT and the thickness map (u8 arrays at the top of the file,
// texture objects and texgens in each pass), and lobe=xf-spec's fitted specular light.
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "gx/texture_unit.h"
#include "model/rational_fit.h"
#include "model/translucency.h"
#include "paths/gx/lobe_lut.h"
#include "paths/gx/object_view.h"
#include "paths/gx/pass_plan_parts.h"

namespace lt::gx {

namespace {

// lobe=xf-spec: x = max(0, N . u) with u = -+k in eye space (the sign that makes x >= 0 on
// front faces, where N . V >= 0), so t = c0 + sign x with x in [0, |d|]; the curve
// (a + s lobe(sat(t))) / (a + s) is fitted as a rational of x in double. V and L are the
// constant ones (object_view.h).
model::RationalFit lobe_fit(const SceneView& view, const Translucency& tr, const Light& light,
                            const ConstantView& cv, glm::dvec3& dir_eye) {
  const glm::dvec3 V = cv.V, L = cv.L;
  const double c0 = -glm::dot(V, L), d = tr.distortion;
  const double sign = d >= 0 ? -1.0 : 1.0;
  const glm::dvec3 k_eye = view.view * (-d * V);
  dir_eye = d >= 0 ? -k_eye : k_eye;
  const double a = tr.ambient, s = light.translucency_scale, p = tr.power;
  return model::fit_rational22(
      [&](double x) {
        return (a + s * model::lobe(std::clamp(c0 + sign * x, 0.0, 1.0), p)) / (a + s);
      },
      std::abs(d));
}

// How a map's format lays its texels out, for the array's comment (texture_format.h).
std::string tile_order_note(TexFormat format) {
  const TexFormatInfo& f = format_info(format);
  const std::string tiles = std::to_string(f.tile_width) + "x" + std::to_string(f.tile_height) +
                            " tiles of " + std::to_string(f.tile_bytes) + " bytes";
  switch (format) {
    case TexFormat::RGBA8:
      return tiles + ": 16 (a, r) pairs, then 16 (g, b) pairs";
    case TexFormat::RGB565:
      return tiles + ", big-endian r5 g6 b5";
    case TexFormat::RGB5A3:
      return tiles + ", big-endian 1 r5 g5 b5 (opaque)";
    case TexFormat::CMPR:
      return tiles + ", four 4x4 blocks of two RGB565 colours and 2-bit indices";
    case TexFormat::IA8:
      return tiles + ", (alpha, intensity) byte pairs";
    case TexFormat::IA4:
      return tiles + ", alpha in the high nibble, intensity in the low";
    case TexFormat::I4:
      return tiles + ", two texels a byte, the first in the high nibble";
    default:
      return tiles;
  }
}

}  // namespace

// The lobe LUT as a texture of one row in GX tile order (lobe_lut.h): t^p, or the material's
// lobe ramp.
TexturePlan PassPlanner::lut_texture(MaterialPlan& mp) const {
  const Material& mat = scene_.materials[static_cast<size_t>(mp.material)];
  const int w = variant_.lut_size;
  const Translucency& tr = *mat.translucency;
  if (tr.ramp) {
    const std::vector<float>& v = tr.ramp->texture.texels;
    const float top = v.empty() ? 0.0f : *std::max_element(v.begin(), v.end());
    if (top > 1.0f)
      throw InputError(scene_.file.string(), "materials." + mat.name + ".translucency.ramp",
                       "gx: the ramp holds values up to " + note_number(top) +
                           "; the 8-bit lobe LUT holds 0..1");
  }
  const TextureObject lut = lobe_lut(mat, w, variant_.lut_format);
  const bool i8 = lut.format == kTexFormatI8;
  const bool rgba8 = lut.format == kTexFormatRGBA8;
  TexturePlan t;
  t.role = TexturePlan::Role::Lut;
  t.object = "lut";
  t.array = "ltrender_lut_" + mp.c_name;
  t.width = w;
  t.height = 1;
  t.format = GxConst<NameGroup::TexFormat>::with_value(lut.format);
  t.map = {"GX_TEXMAP0"};
  t.bytes = lut.data.size();
  t.what = std::string("The LUT: ") + (t.format.name() + 6) +
           ", linear, clamped (the clamp saturates t per pixel)";
  const std::string what =
      tr.ramp ? "the lobe ramp " + tr.ramp->file.filename().string() + " sampled at t"
              : "lobe(t) = t^" + note_number(tr.power);
  mp.arrays.push_back(
      {t.array, std::vector<u8>(lut.data.begin(), lut.data.end()),
       (tr.ramp ? "Lobe LUT" : "Power LUT") + std::string(" of material ") + mat.name + ": " +
           what + ", " + std::to_string(w) + " texels " + t.format.name() + " in GX tile order (" +
           (i8      ? std::string("8x4 tiles, 32 bytes")
            : rgba8 ? std::string("4x4 tiles, 64 bytes: (a, r) then (g, b) pairs")
                    : tile_order_note(static_cast<TexFormat>(lut.format)) +
                          ", nearest, the intensity also in alpha") +
           ";\nrow 0 of each tile used). Flush it (DCFlushRange) before the GPU reads it."});
  return t;
}

const MapRole kThicknessMapRole{TexturePlan::Role::ThicknessMap,
                                "thickness",
                                "ltrender_thickness_",
                                {"GX_TEXMAP1"},
                                "thickness map",
                                "Thickness map",
                                ".translucency.thickness",
                                "thickness",
                                {"GX_TLUT0"}};
const MapRole kAlbedoMapRole{TexturePlan::Role::AlbedoMap,
                             "albedo",
                             "ltrender_albedo_",
                             {"GX_TEXMAP2"},
                             "albedo map",
                             "Albedo map",
                             ".albedo_map",
                             "albedo (linear: decoded from sRGB by ltrender)",
                             {"GX_TLUT1"}};

// A material's map as `role` says (thickness_texture.h: GX_TEXMAP1's thickness map, GX_TEXMAP2's
// albedo map), one u8 array per material that every pass loads.
MapTexture PassPlanner::map_texture(MaterialPlan& mp, const MapTexels& texels,
                                    const MapRole& role) const {
  const Material& mat = scene_.materials[static_cast<size_t>(mp.material)];
  if (texels.width > kMaxTextureSize || texels.height > kMaxTextureSize)
    throw InputError(scene_.file.string(), "materials." + mat.name + role.key,
                     std::string("gx: the ") + role.what + " is " + std::to_string(texels.width) +
                         "x" + std::to_string(texels.height) +
                         " texels; a GX texture is at most 1024 a side (resize the map)");
  ThicknessTexture tex =
      thickness_texture(texels.width, texels.height, *texels.rgb,
                        map_texture_format(variant_, texels.grey), map_tlut_format(texels.grey));
  const bool mip = variant_.mip != GxVariant::Mip::Off;
  const bool power_of_two =
      (texels.width & (texels.width - 1)) == 0 && (texels.height & (texels.height - 1)) == 0;
  if ((mip || variant_.map_repeat) && !power_of_two)
    throw InputError(scene_.file.string(), "materials." + mat.name + role.key,
                     std::string("gx: the ") + role.what + " is " + std::to_string(texels.width) +
                         "x" + std::to_string(texels.height) + " texels; " +
                         (mip ? ":mip=" : ":wrap=repeat") +
                         " needs sides that are powers of two (the console halves and masks "
                         "them; resize the map)");
  if (mip)
    add_mip_levels(tex, *texels.rgb, full_mip_levels(texels.width, texels.height),
                   map_tlut_format(texels.grey));
  const TextureObject& o = tex.texture;
  MapTexture m;
  m.scale = tex.scale;
  TexturePlan& t = m.texture;
  t.role = role.role;
  t.object = role.object;
  t.array = role.array_prefix + mp.c_name;
  t.width = o.width;
  t.height = o.height;
  t.format = GxConst<NameGroup::TexFormat>::with_value(o.format);
  t.map = role.map;
  t.bytes = o.data.size();
  if (variant_.map_repeat) t.wrap_s = t.wrap_t = {"GX_REPEAT"};
  t.what = std::string("The ") + role.what + ": " + t.format.name() + ", linear, " +
           (variant_.map_repeat ? "repeated" : "clamped");
  if (mip) {
    TexturePlan::Mip m_plan;
    m_plan.levels = o.levels;
    if (variant_.mip == GxVariant::Mip::Near) m_plan.min_filter = {"GX_NEAR_MIP_NEAR"};
    m_plan.max_lod = static_cast<float>(o.levels - 1);
    m_plan.bias = static_cast<float>(variant_.mip_bias);
    m_plan.edge_lod = !variant_.mip_diagonal;
    t.mip = m_plan;
    t.what += ", " + std::to_string(o.levels) + " mip levels (" + m_plan.min_filter.name() + ")";
  }
  mp.arrays.push_back(
      {t.array, std::vector<u8>(o.data.begin(), o.data.end()),
       std::string(role.title) + " of material " + mat.name + ": " + std::to_string(o.width) + "x" +
           std::to_string(o.height) + " texels " + t.format.name() +
           (mip ? " and its " + std::to_string(o.levels - 1) +
                      " smaller mip levels after it (2x2 box filter)"
                : std::string()) +
           " in GX tile order (" + tile_order_note(static_cast<TexFormat>(o.format)) +
           "),\nrows from the image's bottom row up (v = 0 first), so the identity texgen's "
           "t = v reads the\ntexel a GL path samples at (u, v); a converter that stores the "
           "top row first needs\nt = 1 - v (a texture matrix with row 1 = (0, -1, 0, 1)). A "
           "texel of 255 is " +
           std::string(role.unit_meaning) + " " + note_number(tex.scale) +
           ". Flush it (DCFlushRange)\nbefore the GPU reads it."});
  if (!o.tlut.empty()) {
    // The palette (gx/palette.h): big-endian entries of the TLUT format, loaded into the role's
    // TLUT region (gx/tmem.h) before the texture.
    const auto format = GxConst<NameGroup::TlutFormat>::with_value(o.tlut_format);
    t.tlut = TexturePlan::Tlut{std::string(role.object) + "_tlut", t.array + "_tlut", format,
                               static_cast<int>(o.tlut.size() / 2), role.tlut};
    mp.arrays.push_back(
        {t.tlut->array, o.tlut,
         std::string(role.title) + " palette of material " + mat.name + ": " +
             std::to_string(t.tlut->entries) + " entries " + format.name() +
             " (big-endian), median cut of the map's texels;\nloaded with GX_LoadTlut into " +
             role.tlut.name() + ". Flush it (DCFlushRange) before the GPU reads it."});
  }
  return m;
}

// t = c0 + k . N, affine in the normal when V and L are constant (the refusal rule, or
// view=object: object_view.h): c0 = -V.L, k = -d V. t=vertex sends t itself as GX_VA_TEX0; t=texgen
// computes it from the raw normal. Either way the texture matrix folds in the LUT's texel-centre
// remap s = t (W-1)/W + 0.5/W (model/power_lut.h, gx-hardware.md §3.4).
TexGenPlan PassPlanner::lut_texgen(const Translucency& tr, const ConstantView& cv,
                                   const TexturePlan& lut) const {
  const bool vertex = variant_.t == GxVariant::TexCoord::Vertex;
  const double n = variant_.lut_size, scale = (n - 1) / n, offset = 0.5 / n;
  std::array<double, 12> m{};
  if (vertex) {
    m[0] = scale;  // row 0 . (s, t, 1, 1): the TEX0 source form AB11 [OGC gx.c L2690]
    m[3] = offset;
  } else {
    // The raw normal is the mesh's world-space normal as sent (objects are pre-transformed),
    // so k stays in world space.
    const glm::dvec3 V = cv.V, L = cv.L;
    const glm::dvec3 k = -tr.distortion * V;
    const double c0 = -glm::dot(V, L);
    for (int c = 0; c < 3; ++c) m[static_cast<size_t>(c)] = k[c] * scale;
    m[3] = c0 * scale + offset;  // row 0 . (nx, ny, nz, 1): the NRM source form ABC1
  }
  TexGenPlan g;
  g.source = vertex ? GxConst<NameGroup::TexGenSource>{"GX_TG_TEX0"}
                    : GxConst<NameGroup::TexGenSource>{"GX_TG_NRM"};
  g.matrix = {"GX_TEXMTX0"};
  TexMatrixPlan mtx{"lut_matrix", {"GX_TEXMTX0"}, {}, ""};
  for (size_t i = 0; i < m.size(); ++i) mtx.values[i] = static_cast<float>(m[i]);
  mtx.what = vertex ? "Texgen: s = t (W-1)/W + 0.5/W from the CPU's t in GX_VA_TEX0"
             : variant_.view_object
                 ? "Texgen: s = (c0 + k . N) (W-1)/W + 0.5/W from the raw normal, V and L taken "
                   "at the object's centre"
                 : "Texgen: s = (c0 + k . N) (W-1)/W + 0.5/W from the raw normal";
  g.matrix_values = mtx;
  g.texture = lut;
  return g;
}

// A map's texgen: (s, t) = the mesh's UV through GX_IDENTITY (the map is stored bottom row first,
// thickness_texture.h, so t = v needs no flip), fetched from the map's GX_TEXMAP, linear and
// clamped as the reference's CLAMP_TO_EDGE bilinear (an albedo map: its sampler's wrap).
TexGenPlan PassPlanner::map_texgen(const MapTexture& map, int texcoord, int uv_attribute) {
  TexGenPlan g;
  g.coord = GxConst<NameGroup::TexCoord>::with_value(texcoord);
  g.source = GxConst<NameGroup::TexGenSource>::with_value(
      GxConst<NameGroup::TexGenSource>{"GX_TG_TEX0"}.value() + uv_attribute);
  g.matrix = {"GX_IDENTITY"};
  g.texture = map.texture;
  g.what =
      "Texgen: (s, t) = (u, v) of the mesh, as sent in GX_VA_TEX" + std::to_string(uv_attribute);
  return g;
}

// The specular light: its position far along V (so N . l >= 0 on front faces and the XF's
// condition passes), the direction slot u, and the fit's coefficients with the numerator
// scaled by the channel's magnitude (with view=object, times a point light's attenuation at the
// object's centre: a specular light has no distance attenuation).
LightObjectPlan PassPlanner::specular_light(const Translucency& tr, const Light& light,
                                            const ConstantView& cv, const glm::dvec3& color,
                                            double inv_gain, PassFigures& figures) const {
  glm::dvec3 dir_eye(0);
  const model::RationalFit fit = lobe_fit(view_, tr, light, cv, dir_eye);
  figures.fit_error = fit.max_error;
  const model::Rational22& r = fit.r;
  const double m = max3(color);
  const double g = m > 0 ? 1.0 / inv_gain : 0.0;
  const glm::dvec3 V_eye = view_.view * cv.V;
  LightObjectPlan o;
  o.kind = LightObjectPlan::Kind::SpecularFit;
  o.name = "trans_light";
  o.slot = {"GX_LIGHT0"};
  o.position = glm::vec3(V_eye * kFarAway);
  o.color = rgb8(m > 0 ? color / m : glm::dvec3(0));
  // GX_InitLightDir stores the negated direction: pass -u so the slot holds u.
  o.direction_arg = glm::vec3(-dir_eye);
  for (size_t i = 0; i < 3; ++i) {
    o.a[i] = static_cast<float>(r.a[i] * g);
    o.k[i] = static_cast<float>(r.k[i]);
  }
  o.gain = g;
  return o;
}

}  // namespace lt::gx
