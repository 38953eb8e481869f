// The planner's pieces, shared by its files (pass_planner.cpp: passes, lights, channels,
// stages; pass_planner_textures.cpp: the LUT, the thickness map, their texgens and the xf-spec
// fit; pass_planner_albedo.cpp: the albedo map and its stage). Internal to the generator.
#pragma once

#include <algorithm>
#include <optional>
#include <string>

#include "paths/gx/generator.h"
#include "paths/gx/object_view.h"
#include "paths/gx/pass_plan.h"
#include "paths/gx/thickness_texture.h"

namespace lt::gx {

// The TEV and XF scales: x1, x2, x4 (GX_CS_SCALE_*). Magnitudes up to 4 are exact.
inline constexpr double kMaxScale = 4;

// A directional light is a point light this far away in eye space: libogc's own "large number"
// for lights at infinity [OGC gx.c L23-25, GX_InitSpecularDir], small enough that |v|^2 (1e36)
// stays finite in float.
inline constexpr double kFarAway = 1.0e18;

inline double max3(const glm::dvec3& v) {
  return std::max({v.r, v.g, v.b});
}

// A colour as the 8-bit GXColor a call passes, alpha 255.
Color8 rgb8(const glm::dvec3& c);
// One stage's order and colour inputs, scaled x1, x2 or x4; the rest as pass_plan.h's defaults.
TevStagePlan tev_stage(int stage, GxConst<NameGroup::TexCoord> texcoord,
                       GxConst<NameGroup::TexMap> texmap, GxConst<NameGroup::Channel> channel,
                       std::array<GxConst<NameGroup::ColorArg>, 4> in, int scale, std::string what);
PixelEnginePlan pixel_engine(int pass);

// A material's thickness map as GX_TEXMAP1's texture (or its albedo map as GX_TEXMAP2's), and
// the value a texel of 255 means.
struct MapTexture {
  TexturePlan texture;
  double scale = 1;
};

// Which map a MapTexture is: its role, names, slot and the scene key its errors name.
struct MapRole {
  TexturePlan::Role role;
  const char* object;                 // the GXTexObj
  const char* array_prefix;           // the u8 array's name before the material's C name
  GxConst<NameGroup::TexMap> map;     // the GX_TEXMAP it is loaded into
  const char* what;                   // "thickness map", in errors and comments
  const char* title;                  // "Thickness map", starting the array's comment
  const char* key;                    // after "materials.<name>" in errors
  const char* unit_meaning;           // what a texel of 255 is (times the scale)
  GxConst<NameGroup::TlutName> tlut;  // the TLUT a colour-indexed map's palette is loaded into
};
extern const MapRole kThicknessMapRole, kAlbedoMapRole;

// What one light's pass needs and the scales chosen for it (generator.h's term).
struct PassChoice {
  bool vertex_t = false;  // the thickness is the baked vertex colour
  bool xf = false;        // lobe=xf-spec
  glm::dvec3 T{1};        // the constant thickness (white with a map)
  double t_max = 1;       // its largest component (the map's scale, 1 for vertex colours)
  glm::dvec3 trans_color{0};
  double s0 = 0;  // magnitude of COLOR0 at att = 1
  bool translucent = false, lut = false, uses_map = false;
  double diffuse_mag = 0, max_attenuation = 0;
  int sd = 1;  // the diffuse scale
};

class PassPlanner {
 public:
  PassPlanner(const Scene& scene, const GxVariant& v);
  ScenePlan plan();

 private:
  void material_passes(MaterialPlan& mp);
  void light_passes(MaterialPlan& mp);  // the passes of the term, before the albedo map
  PassPlan diffuse_pass(int m, int pass, size_t first_light);
  PassChoice choose(int m, size_t l, const MapTexture* map) const;
  PassPlan light_pass(int m, size_t l, const std::optional<TexturePlan>& lut,
                      const MapTexture* map);
  void light_channels(PassPlan& p, const PassChoice& c, const glm::dvec3& T_norm, bool map,
                      const glm::dvec3& albedo, bool first_pass, bool base_in_tev) const;
  // `base`: base=tev's konst colour K (the translucency base over the pass's scale), exact.
  void light_stages(PassPlan& p, const PassChoice& c, const Translucency& tr, const Light& light,
                    int st_scale, const std::optional<glm::dvec3>& base) const;
  // pass_planner_textures.cpp
  TexturePlan lut_texture(MaterialPlan& mp) const;
  MapTexture map_texture(MaterialPlan& mp, const MapTexels& texels, const MapRole& role) const;
  // pass_planner_albedo.cpp
  std::optional<MapTexture> albedo_texture(MaterialPlan& mp) const;
  static void add_albedo_stage(PassPlan& p, const MapTexture& albedo);
  TexGenPlan lut_texgen(const Translucency& tr, const ConstantView& cv,
                        const TexturePlan& lut) const;
  static TexGenPlan map_texgen(const MapTexture& map, int texcoord, int uv_attribute);
  LightObjectPlan specular_light(const Translucency& tr, const Light& light, const ConstantView& cv,
                                 const glm::dvec3& color, double inv_gain,
                                 PassFigures& figures) const;

  const Scene& scene_;
  GxVariant variant_;
  SceneView view_;
};

}  // namespace lt::gx
