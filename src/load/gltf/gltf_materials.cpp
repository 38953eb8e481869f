#include "load/gltf/gltf_materials.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "scene/scene_limits.h"

namespace lt::gltf {

namespace {
using json = nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

glm::dvec3 vec3_of(const std::vector<double>& v) {
  return {v[0], v[1], v[2]};
}

std::string rgb_text(const glm::dvec3& c) {
  return json({c.x, c.y, c.z}).dump();
}

// extras.ltrender: the seed's controls glTF has no word for.
void read_ltrender_extras(const json& extras, const Document& doc, const std::string& ptr,
                          Translucency& tr, Notes& notes) {
  const std::string file = doc.path.string();
  if (!extras.is_object()) doc.fail(ptr, "expected an object");
  for (auto it = extras.begin(); it != extras.end(); ++it) {
    const std::string& k = it.key();
    if (k != "power" && k != "distortion" && k != "normalize_distorted_light" && k != "thickness") {
      doc.fail(ptr + "/" + k,
               "unknown key (power, distortion, normalize_distorted_light, "
               "thickness; scale is a light's)");
    }
  }
  tr.power = bounded_number(extras, "power", tr.power, 0, kMaxPower, file, ptr);
  tr.distortion = bounded_number(extras, "distortion", tr.distortion, -kMaxDistortion,
                                 kMaxDistortion, file, ptr);
  if (extras.contains("normalize_distorted_light")) {
    if (!extras["normalize_distorted_light"].is_boolean())
      doc.fail(ptr + "/normalize_distorted_light", "expected true or false");
    tr.normalize_distorted_light = extras["normalize_distorted_light"].get<bool>();
  }
  if (extras.contains("thickness")) {
    if (extras["thickness"] != "vertex")
      doc.fail(ptr + "/thickness", "must be \"vertex\" (COLOR_0 as thickness)");
    tr.thickness_source = ThicknessSource::Vertex;
  }
  notes.push_back(
      "mapped " + ptr + " -> power " + json(tr.power).dump() + ", distortion " +
      json(tr.distortion).dump() +
      (tr.thickness_source == ThicknessSource::Vertex ? ", thickness from COLOR_0" : ""));
}
}  // namespace

glm::dvec3 volume_transmittance(const glm::dvec3& attenuation_color, double thickness,
                                double attenuation_distance) {
  if (std::isinf(attenuation_distance)) return glm::dvec3(1);
  glm::dvec3 t;
  for (int c = 0; c < 3; ++c)
    t[c] = std::pow(attenuation_color[c], thickness / attenuation_distance);
  return t;
}

Material default_material() {
  Material m;
  m.name = "(glTF default material)";
  return m;
}

GltfMaterial map_material(const Document& doc, int index, Notes& notes) {
  const std::string file = doc.path.string();
  const std::string ptr = "/materials/" + std::to_string(index);
  const json& j = at_pointer(doc.json, ptr);
  GltfMaterial out;
  Material& mat = out.material;
  mat.name = j.value("name", std::string());
  if (mat.name.empty()) mat.name = ptr;

  // Base colour (§3.9.2): the factor is linear, so it is the albedo as it stands; the texture
  // (sRGB, decoded) multiplies it: the albedo map. Alpha is coverage, which the term does not
  // model.
  const json& pbr = j.contains("pbrMetallicRoughness") ? j["pbrMetallicRoughness"] : json::object();
  const std::string pbr_ptr = ptr + "/pbrMetallicRoughness";
  if (pbr.contains("baseColorTexture"))
    out.texture = describe_base_colour_texture(doc, pbr_ptr + "/baseColorTexture", notes);
  const auto base =
      bounded_numbers(pbr, "baseColorFactor", 4, {1, 1, 1, 1}, 0, kMaxColour, file, pbr_ptr);
  mat.albedo = vec3_of(base);
  notes.push_back("mapped " + pbr_ptr + "/baseColorFactor -> albedo " + rgb_text(mat.albedo));
  if (base[3] != 1)
    notes.push_back("ignored " + pbr_ptr + "/baseColorFactor alpha " + json(base[3]).dump() +
                    ": coverage is not modelled");
  note_unmapped_keys(pbr, pbr_ptr, {"baseColorFactor", "baseColorTexture"},
                     "metal/roughness are not part of the term", notes);

  const json& ext = j.contains("extensions") ? j["extensions"] : json::object();
  const json& ltrender =
      j.contains("extras") && j["extras"].is_object() && j["extras"].contains("ltrender")
          ? j["extras"]["ltrender"]
          : json();
  const bool volume = ext.contains("KHR_materials_volume");
  const bool diffuse_transmission = ext.contains("KHR_materials_diffuse_transmission");
  if (volume || diffuse_transmission || !ltrender.is_null()) {
    Translucency tr;
    tr.power = kDefaultPower;
    tr.distortion = kDefaultDistortion;
    if (volume) {
      // KHR_materials_volume: thicknessFactor (default 0) in the mesh's own units,
      // attenuationDistance (default +inf), attenuationColor (default white).
      const json& v = ext["KHR_materials_volume"];
      const std::string vp = ptr + "/extensions/KHR_materials_volume";
      const double thickness = bounded_number(v, "thicknessFactor", 0, 0, kMaxCoordinate, file, vp);
      const double distance = bounded_number(v, "attenuationDistance", kInf, 0, kInf, file, vp);
      if (!(distance > 0)) doc.fail(vp + "/attenuationDistance", "must be > 0");
      const glm::dvec3 colour =
          vec3_of(bounded_numbers(v, "attenuationColor", 3, {1, 1, 1}, 0, 1, file, vp));
      tr.thickness = volume_transmittance(colour, thickness, distance);
      notes.push_back("mapped " + vp + " thicknessFactor " + json(thickness).dump() +
                      ", attenuationColor " + rgb_text(colour) + ", attenuationDistance " +
                      (std::isinf(distance) ? std::string("inf") : json(distance).dump()) +
                      " -> thickness " + rgb_text(tr.thickness) +
                      " (attenuationColor ^ (thickness / attenuationDistance))");
      if (v.contains("thicknessTexture")) {
        notes.push_back("warning " + vp +
                        "/thicknessTexture: thickness maps are not sampled yet, the constant "
                        "thicknessFactor is used");
      }
      note_unmapped_keys(
          v, vp, {"thicknessFactor", "attenuationDistance", "attenuationColor", "thicknessTexture"},
          "not part of the term", notes);
    }
    if (diffuse_transmission) {
      // KHR_materials_diffuse_transmission: how much light crosses the surface diffusely (factor,
      // default 0) and its colour (default white): the term's ambient translucency and tint.
      const json& d = ext["KHR_materials_diffuse_transmission"];
      const std::string dp = ptr + "/extensions/KHR_materials_diffuse_transmission";
      tr.ambient = bounded_number(d, "diffuseTransmissionFactor", 0, 0, 1, file, dp);
      tr.tint = vec3_of(bounded_numbers(d, "diffuseTransmissionColorFactor", 3, {1, 1, 1}, 0,
                                        kMaxColour, file, dp));
      notes.push_back("mapped " + dp + " -> ambient " + json(tr.ambient).dump() + ", tint " +
                      rgb_text(tr.tint));
      note_unmapped_keys(d, dp, {"diffuseTransmissionFactor", "diffuseTransmissionColorFactor"},
                         "textures are not sampled yet: the factors are used", notes);
    }
    if (!ltrender.is_null()) {
      read_ltrender_extras(ltrender, doc, ptr + "/extras/ltrender", tr, notes);
    } else {
      notes.push_back("default " + ptr + ": power " + json(kDefaultPower).dump() + ", distortion " +
                      json(kDefaultDistortion).dump() + " (no extras.ltrender)");
    }
    mat.translucency = tr;
  } else {
    notes.push_back("mapped " + ptr +
                    ": no volume, diffuse transmission or extras.ltrender -> diffuse only");
  }
  note_unmapped_keys(
      j, ptr,
      {"pbrMetallicRoughness", "KHR_materials_volume", "KHR_materials_diffuse_transmission"},
      "not part of the term", notes);
  return out;
}

}  // namespace lt::gltf
