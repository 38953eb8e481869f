#include "scene/scene_parse.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/fs.h"
#include "scene/object_reader.h"
#include "scene/scene_limits.h"

namespace lt {

namespace {

using json = nlohmann::json;

// One tolerance of the "regress" block: idiff's thresholds, in LSB (255 is the largest error
// there is) and percent of pixels.
ToleranceOverride read_tolerance_override(ObjectReader& r) {
  ToleranceOverride t;
  if (r.has("fail_lsb")) t.fail_lsb = r.number("fail_lsb", {}, 0, 255);
  if (r.has("fail_percent")) t.fail_percent = r.number("fail_percent", {}, 0, 100);
  if (r.has("hard_fail_lsb")) t.hard_fail_lsb = r.number("hard_fail_lsb", {}, 0, 255);
  if (r.has("warn_lsb")) t.warn_lsb = r.number("warn_lsb", {}, 0, 255);
  if (r.has("warn_percent")) t.warn_percent = r.number("warn_percent", {}, 0, 100);
  if (r.has("hard_warn_lsb")) t.hard_warn_lsb = r.number("hard_warn_lsb", {}, 0, 255);
  if (r.has("edge_shift_percent"))
    t.edge_shift_percent = r.number("edge_shift_percent", {}, 0, 100);
  if (r.has("region")) {
    t.region = r.string("region");
    if (t.region != "covered" && t.region != "image")
      r.fail(r.key_path("region"), "must be \"covered\" or \"image\"");
  }
  return t;
}

// The keys of a scene material (scene-format.md): "albedo", "albedo_map" and "translucency",
// read into `mat`, the maps it names into `maps` (read when the scene is loaded, so a typo is
// reported before any file I/O).
// A key that is absent keeps what `mat` holds (a glTF material's override keeps the file's
// albedo); "translucency", when given, is read whole, with the scene's defaults.
void read_material_keys(ObjectReader& m, Material& mat, std::vector<MapReference>& maps,
                        const fs::path& base_dir) {
  mat.albedo = m.vec3("albedo", mat.albedo, 0, kMaxColour);
  if (m.has("albedo_map")) {
    // A picture in sRGB (load/albedo_map.h), multiplying "albedo".
    const std::string texture = m.string("albedo_map");
    refuse_nul(m, "albedo_map", texture);
    maps.push_back(
        {MapReference::Kind::AlbedoMap, base_dir / texture, "rgb", m.key_path("albedo_map")});
  }
  if (m.has("translucency")) {
    ObjectReader t = m.object("translucency");
    Translucency tr;
    tr.power = t.number("power", 1.0, 0, kMaxPower);
    tr.distortion = t.number("distortion", 0.0, -kMaxDistortion, kMaxDistortion);
    tr.ambient = t.number("ambient", 0.0, 0, kMaxColour);
    tr.tint = t.vec3("tint", glm::dvec3(1), 0, kMaxColour);
    tr.normalize_distorted_light = t.boolean("normalize_distorted_light", false);
    if (t.has("thickness")) {
      const json& th = t.get("thickness");
      const std::string kp = t.key_path("thickness");
      if (th.is_object()) {
        // {"texture": "map.png", "channels": "rgb"}
        ObjectReader map = t.object("thickness");
        const std::string texture = map.string("texture");
        refuse_nul(map, "texture", texture);
        const std::string channels = map.string("channels", std::string("rgb"));
        if (!is_thickness_channels(channels)) {
          map.fail(map.key_path("channels"),
                   "must be \"rgb\", \"r\", \"g\", \"b\" or \"a\", not \"" + channels + "\"");
        }
        map.finish();
        tr.thickness_source = ThicknessSource::Texture;
        maps.push_back({MapReference::Kind::ThicknessMap, base_dir / texture, channels,
                        map.key_path("texture")});
      } else if (th.is_string()) {
        if (th.get<std::string>() != "vertex") {
          t.fail(kp, "must be \"vertex\", a number, an rgb triple or {\"texture\": ...}");
        }
        tr.thickness_source = ThicknessSource::Vertex;
      } else if (th.is_number()) {
        // Bounded like the rgb form: 1e300 would make the reference's pixels Inf.
        tr.thickness = glm::dvec3(t.number("thickness", {}, 0, kMaxColour));
      } else {
        tr.thickness = t.vec3_value(th, kp, 0, kMaxColour);
      }
    }
    if (t.has("ramp")) {
      const std::string ramp = t.string("ramp");
      refuse_nul(t, "ramp", ramp);
      maps.push_back({MapReference::Kind::Ramp, base_dir / ramp, "rgb", t.key_path("ramp")});
    }
    t.finish();
    mat.translucency = tr;
  }
}

// A glTF object's "materials": {SELECTOR: {scene material keys}}, into `object`.
void read_material_overrides(ObjectReader& o, const fs::path& base_dir, ObjectDescription& object) {
  const std::string key = o.key_path("materials");
  if (o.has("material"))
    o.fail(key,
           "an object has \"material\" (one for every glTF material) or \"materials\" (per "
           "glTF material), not both");
  const json& overrides = o.get("materials");
  if (!overrides.is_object() || overrides.empty())
    o.fail(key, "expected a non-empty object: glTF material name, \"#N\" or \"*\" -> material");
  object.overrides_json = overrides.dump();
  for (auto it = overrides.begin(); it != overrides.end(); ++it) {
    ObjectReader m(it.value(), key + "." + it.key(), o.file());
    MaterialOverride override{it.key(), key + "." + it.key(), m.has("albedo"), {}, {}};
    read_material_keys(m, override.material, override.maps, base_dir);
    m.finish();
    object.overrides.push_back(std::move(override));
  }
}

void read_image(ObjectReader& top, SceneDescription& scene) {
  ObjectReader img = top.object("image");
  scene.width = img.integer("width", 640, 1, static_cast<int>(kMaxImageSide));
  scene.height = img.integer("height", 480, 1, static_cast<int>(kMaxImageSide));
  scene.background = img.vec3("background", glm::dvec3(0), 0, kMaxColour);
  img.finish();
}

Camera read_camera(ObjectReader& top) {
  ObjectReader cam = top.object("camera");
  Camera c;
  c.eye = cam.vec3("eye", {}, -kMaxCoordinate, kMaxCoordinate);
  c.target = cam.vec3("target", {}, -kMaxCoordinate, kMaxCoordinate);
  c.up = cam.vec3("up", glm::dvec3(0, 1, 0), -kMaxCoordinate, kMaxCoordinate);
  const std::string proj = cam.string("projection", std::string("perspective"));
  if (proj == "perspective") {
    c.projection = Camera::Projection::Perspective;
    c.fov_y_deg = cam.number("fov_y_deg", 40.0, 1e-3, 179.0);
  } else if (proj == "orthographic") {
    c.projection = Camera::Projection::Orthographic;
    c.height = cam.number("height", {}, 0, kMaxCoordinate);
    if (!(c.height > 0)) cam.fail(cam.key_path("height"), "must be > 0");
  } else {
    cam.fail(cam.key_path("projection"), "must be \"perspective\" or \"orthographic\"");
  }
  c.near = cam.number("near", 0.1, -kMaxCoordinate, kMaxCoordinate);
  c.far = cam.number("far", 100.0, -kMaxCoordinate, kMaxCoordinate);
  if (c.projection == Camera::Projection::Perspective && !(c.near > 0)) {
    cam.fail(cam.key_path("near"), "must be > 0 for a perspective camera");
  }
  if (!(c.far > c.near)) cam.fail(cam.key_path("far"), "must be greater than near");
  const glm::dvec3 fwd = c.target - c.eye;
  if (!(glm::length(fwd) > 0)) cam.fail(cam.key_path("target"), "must differ from eye");
  if (!(glm::length(glm::cross(glm::normalize(fwd), c.up)) > 1e-9)) {
    cam.fail(cam.key_path("up"), "must not be parallel to the view direction");
  }
  cam.finish();
  return c;
}

// "materials": an object of named materials.
void read_materials(ObjectReader& top, const fs::path& base_dir, SceneDescription& scene) {
  const json& mats = top.get("materials");
  // Empty only makes sense when every object is a glTF file bringing its own materials: a
  // mesh object's "material" names one of these, and says so when it is not there.
  if (!mats.is_object()) top.fail("materials", "expected an object of named materials");
  if (mats.size() > kMaxMaterials) {
    top.fail("materials", over_limit_message(mats.size(), "materials", kMaxMaterials));
  }
  for (auto it = mats.begin(); it != mats.end(); ++it) {
    ObjectReader m(it.value(), "materials." + it.key(), top.file());
    MaterialDescription mat;
    mat.material.name = it.key();
    read_material_keys(m, mat.material, mat.maps, base_dir);
    m.finish();
    scene.materials.push_back(std::move(mat));
  }
}

Light read_light(ObjectReader& l) {
  Light light;
  const std::string type = l.string("type");
  const double intensity = l.number("intensity", 1.0, 0, kMaxColour);
  light.color = l.vec3("color", glm::dvec3(1), 0, kMaxColour) * intensity;
  light.translucency_scale = l.number("translucency_scale", 1.0, 0, kMaxColour);
  if (type == "directional") {
    light.type = Light::Type::Directional;
    const glm::dvec3 d = l.vec3("direction", {}, -kMaxCoordinate, kMaxCoordinate);
    if (!(glm::length(d) > 0)) l.fail(l.key_path("direction"), "must not be zero");
    light.direction = glm::normalize(d);
  } else if (type == "point") {
    light.type = Light::Type::Point;
    light.position = l.vec3("position", {}, -kMaxCoordinate, kMaxCoordinate);
    if (l.has("attenuation")) {
      ObjectReader a = l.object("attenuation");
      light.kc = a.number("constant", 1.0, 0, kMaxAttenuation);
      light.kl = a.number("linear", 0.0, 0, kMaxAttenuation);
      light.kq = a.number("quadratic", 0.0, 0, kMaxAttenuation);
      a.finish();
      if (!(light.kc + light.kl + light.kq > 0)) {
        l.fail(l.key_path("attenuation"), "constant, linear and quadratic are all 0");
      }
    }
  } else {
    l.fail(l.key_path("type"), "must be \"directional\" or \"point\"");
  }
  l.finish();
  return light;
}

Transform read_transform(ObjectReader& o) {
  Transform transform;
  ObjectReader t = o.object("transform");
  transform.translate = t.vec3("translate", glm::dvec3(0), -kMaxCoordinate, kMaxCoordinate);
  transform.rotate_deg = t.vec3("rotate_deg", glm::dvec3(0), -360000, 360000);
  if (t.has("scale") && t.get("scale").is_number()) {
    const double s = t.number("scale", {}, 0, kMaxScaleFactor);
    if (!(s > 0)) t.fail(t.key_path("scale"), "must be > 0");
    transform.scale = glm::dvec3(s);
  } else {
    // Extension: a per-axis scale [sx, sy, sz] (normals use the inverse transpose).
    transform.scale = t.vec3("scale", glm::dvec3(1), 1 / kMaxScaleFactor, kMaxScaleFactor);
  }
  t.finish();
  return transform;
}

// An object is a mesh file, or the meshes of a glTF file (one node's subtree, or its scene),
// placed by `transform` after the file's own node transforms.
ObjectDescription read_object(ObjectReader& o, const std::string& key_path,
                              const fs::path& base_dir, const SceneDescription& scene) {
  ObjectDescription obj;
  obj.key = key_path;
  const bool gltf_object = o.has("gltf");
  obj.source = gltf_object ? ObjectDescription::Source::Gltf : ObjectDescription::Source::Mesh;
  const std::string key = obj.file_key();
  if (gltf_object && o.has("mesh"))
    o.fail(o.key_path("mesh"), "an object has \"mesh\" or \"gltf\", not both");
  const std::string mesh = o.string(key);
  refuse_nul(o, key, mesh);
  obj.path = base_dir / mesh;
  obj.material = -1;  // a glTF object without one keeps the file's materials
  if (!gltf_object || o.has("material")) {
    const std::string mat = o.string("material");
    auto found = std::find_if(scene.materials.begin(), scene.materials.end(),
                              [&](const MaterialDescription& m) { return m.material.name == mat; });
    if (found == scene.materials.end()) {
      o.fail(o.key_path("material"), "unknown material \"" + mat + "\"");
    }
    obj.material = static_cast<int>(found - scene.materials.begin());
  }
  if (o.has("transform")) obj.transform = read_transform(o);
  if (gltf_object) {
    obj.node = o.string("node", std::string());
    if (o.has("materials")) read_material_overrides(o, base_dir, obj);
  }
  o.finish();
  return obj;
}

void read_regress(ObjectReader& top, SceneDescription& scene) {
  ObjectReader r = top.object("regress");
  scene.regress.every_path = read_tolerance_override(r);
  if (r.has("paths")) {
    const json& paths = r.get("paths");
    if (!paths.is_object()) r.fail("regress.paths", "expected an object of path names");
    for (auto it = paths.begin(); it != paths.end(); ++it) {
      ObjectReader p(it.value(), "regress.paths." + it.key(), top.file());
      scene.regress.per_path[it.key()] = read_tolerance_override(p);
      p.finish();
    }
  }
  r.finish();
}

}  // namespace

SceneDescription parse_scene(const std::string& text, const fs::path& file_for_errors,
                             const fs::path& base_dir) {
  const std::string file = file_for_errors.string();
  const json root = parse_json_input(text, file);
  SceneDescription scene;
  scene.file = file_for_errors;
  ObjectReader top(root, "", file);
  read_image(top, scene);
  scene.camera = read_camera(top);
  scene.ambient_light = top.vec3("ambient_light", glm::dvec3(0), 0, kMaxColour);
  read_materials(top, base_dir, scene);
  if (top.has("lights")) {
    const json& lights = top.get("lights");
    if (!lights.is_array()) top.fail("lights", "expected an array");
    if (lights.size() > kMaxLights) {
      top.fail("lights", over_limit_message(lights.size(), "lights", kMaxLights));
    }
    for (size_t i = 0; i < lights.size(); ++i) {
      ObjectReader l(lights[i], "lights[" + std::to_string(i) + "]", file);
      scene.lights.push_back(read_light(l));
    }
  }
  const json& objs = top.get("objects");
  if (!objs.is_array() || objs.empty()) top.fail("objects", "expected a non-empty array");
  if (objs.size() > kMaxObjects) {
    top.fail("objects", over_limit_message(objs.size(), "objects", kMaxObjects));
  }
  for (size_t i = 0; i < objs.size(); ++i) {
    const std::string kp = "objects[" + std::to_string(i) + "]";
    ObjectReader o(objs[i], kp, file);
    scene.objects.push_back(read_object(o, kp, base_dir, scene));
  }
  if (top.has("regress")) read_regress(top, scene);
  top.finish();
  return scene;
}

SceneDescription parse_scene_file(const fs::path& path) {
  return parse_scene(read_input_file(path, InputKind::Scene), path, path.parent_path());
}

}  // namespace lt
