#include "scene/scene.h"

#include <cmath>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <new>
#include <nlohmann/json.hpp>
#include <set>

#include "core/error.h"
#include "core/fs.h"
#include "mesh/mesh_io.h"
#include "scene/albedo_map.h"
#include "scene/default_lights.h"
#include "scene/gltf/gltf_document.h"
#include "scene/gltf/gltf_scene.h"
#include "scene/scene_limits.h"

namespace lt {

glm::dmat4 Camera::view_from_origin() const {
  return glm::lookAt(glm::dvec3(0), forward(), up);
}

namespace {

using json = nlohmann::json;

// Strict reading of one JSON object: every key is either taken or reported as unknown, so a
// typo never silently renders something else (scene-format.md).
class ObjectReader {
 public:
  ObjectReader(const json& j, std::string path, const std::string& file)
      : j_(j), path_(std::move(path)), file_(file) {
    if (!j_.is_object()) fail(path_, "expected an object");
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_, key.empty() ? "(top level)" : key, what);
  }
  const std::string& file() const { return file_; }
  std::string key_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }
  bool has(const std::string& key) const { return j_.contains(key); }
  const json& get(const std::string& key) {
    used_.insert(key);
    if (!j_.contains(key)) fail(key_path(key), "missing required key");
    return j_.at(key);
  }

  double number(const std::string& key, std::optional<double> def = {}, double lo = -INFINITY,
                double hi = INFINITY) {
    if (!has(key)) {
      if (!def) fail(key_path(key), "missing required key");
      used_.insert(key);
      return *def;
    }
    const json& v = get(key);
    if (!v.is_number()) fail(key_path(key), "expected a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(key_path(key), "must be finite");
    if (d < lo || d > hi) {
      fail(key_path(key), "out of range: " + v.dump() + " (allowed " + range(lo, hi) + ")");
    }
    return d;
  }
  int integer(const std::string& key, int def, int lo, int hi) {
    if (!has(key)) {
      used_.insert(key);
      return def;
    }
    const json& v = get(key);
    if (!v.is_number_integer()) fail(key_path(key), "expected an integer");
    const auto i = v.get<long long>();
    if (i < lo || i > hi) {
      fail(key_path(key), "out of range: " + v.dump() + " (allowed " + range(lo, hi) + ")");
    }
    return static_cast<int>(i);
  }
  glm::dvec3 vec3(const std::string& key, std::optional<glm::dvec3> def = {}, double lo = -INFINITY,
                  double hi = INFINITY) {
    if (!has(key)) {
      if (!def) fail(key_path(key), "missing required key");
      used_.insert(key);
      return *def;
    }
    return vec3_value(get(key), key_path(key), lo, hi);
  }
  glm::dvec3 vec3_value(const json& v, const std::string& kp, double lo, double hi) const {
    if (!v.is_array() || v.size() != 3) fail(kp, "expected an array of 3 numbers");
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number()) fail(kp, "expected an array of 3 numbers");
      r[i] = v[i].get<double>();
      if (!std::isfinite(r[i])) fail(kp, "must be finite");
      if (r[i] < lo || r[i] > hi) {
        fail(kp, "component out of range: " + v[i].dump() + " (allowed " + range(lo, hi) + ")");
      }
    }
    return r;
  }
  std::string string(const std::string& key, std::optional<std::string> def = {}) {
    if (!has(key)) {
      if (!def) fail(key_path(key), "missing required key");
      used_.insert(key);
      return *def;
    }
    const json& v = get(key);
    if (!v.is_string()) fail(key_path(key), "expected a string");
    return v.get<std::string>();
  }
  bool boolean(const std::string& key, bool def) {
    if (!has(key)) {
      used_.insert(key);
      return def;
    }
    const json& v = get(key);
    if (!v.is_boolean()) fail(key_path(key), "expected true or false");
    return v.get<bool>();
  }
  ObjectReader object(const std::string& key) {
    return ObjectReader(get(key), key_path(key), file_);
  }

  // Call after reading: any key not taken is a typo or an unsupported feature.
  void finish() const {
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      if (!used_.count(it.key())) fail(key_path(it.key()), "unknown key");
    }
  }

 private:
  static std::string range(double lo, double hi) {
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on chained operator+ here.
    auto s = [](double v) {
      if (v == INFINITY) return std::string("inf");
      if (v == -INFINITY) return std::string("-inf");
      return json(v).dump();
    };
    std::string r = "[";
    r.append(s(lo)).append(", ").append(s(hi)).append("]");
    return r;
  }

  const json& j_;
  std::string path_;
  const std::string& file_;
  std::set<std::string> used_;
};

// JSON may hold "\u0000", the file system cannot: every system call would stop at the NUL (and
// read another file), and so would the printed message.
void refuse_nul(const ObjectReader& r, const std::string& key, const std::string& file_name) {
  if (file_name.find('\0') == std::string::npos) return;
  std::string shown;
  for (char c : file_name) shown += c == '\0' ? std::string("\\u0000") : std::string(1, c);
  r.fail(r.key_path(key), "a path cannot contain a NUL byte: \"" + shown + "\"");
}

// JSON syntax errors carry a byte offset; users want a line.
int line_of_offset(const std::string& text, size_t offset) {
  int line = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

}  // namespace

std::string over_limit_message(std::size_t count, const char* noun, std::size_t limit) {
  return std::to_string(count) + " " + noun + ", more than the limit of " + std::to_string(limit);
}

void check_vertex_thickness(const TriangleMesh& mesh, const std::string& file,
                            const std::string& where, const std::string& mesh_name) {
  for (size_t v = 0; v < mesh.colors.size(); ++v) {
    for (int c = 0; c < 3; ++c) {
      const double x = mesh.colors[v][c];
      if (x >= 0 && x <= kMaxColour) continue;
      std::string what = "vertex ";
      what.append(std::to_string(v))
          .append(" of ")
          .append(mesh_name)
          .append(" has colour component ")
          .append(json(x).dump())
          .append(", out of range for \"thickness\": \"vertex\" (allowed [")
          .append(json(0.0).dump())
          .append(", ")
          .append(json(kMaxColour).dump())
          .append("])");
      throw InputError(file, where, what);
    }
  }
}

bool samples_uvs(const Material& material) {
  return material.albedo_map || (material.translucency && material.translucency->thickness_source ==
                                                              ThicknessSource::Texture);
}

void check_uvs_for_material(const TriangleMesh& mesh, const Material& material,
                            const std::string& file, const std::string& where,
                            const std::string& mesh_name) {
  if (!samples_uvs(material) || !mesh.uvs.empty()) return;
  const bool thickness = material.translucency && material.translucency->thickness_map;
  throw InputError(
      file, where,
      "material \"" + material.name + "\" samples the " +
          (thickness ? "thickness map " + material.translucency->thickness_map->file.string()
                     : "albedo map " + material.albedo_map->file.string()) +
          " but " + mesh_name + " has no texture coordinates (UVs)");
}

namespace {

// One tolerance of the "regress" block: idiff's thresholds, in LSB (255 is the largest error
// there is) and percent of pixels.
ToleranceOverride read_tolerance_override(ObjectReader& r) {
  ToleranceOverride t;
  if (r.has("fail_lsb")) t.fail_lsb = r.number("fail_lsb", {}, 0, 255);
  if (r.has("fail_percent")) t.fail_percent = r.number("fail_percent", {}, 0, 100);
  if (r.has("hard_fail_lsb")) t.hard_fail_lsb = r.number("hard_fail_lsb", {}, 0, 255);
  if (r.has("region")) {
    t.region = r.string("region");
    if (t.region != "covered" && t.region != "image")
      r.fail(r.key_path("region"), "must be \"covered\" or \"image\"");
  }
  return t;
}

// An albedo map, thickness map or ramp named by a material, read once the JSON is read (a typo
// is reported before any file I/O); `material` is the material it belongs to (a scene's, or a
// glTF object's override, which live in different lists).
struct TextureLoad {
  enum class Kind { ThicknessMap, Ramp, AlbedoMap };
  std::function<Material&()> material;
  Kind kind;
  fs::path file;
  std::string channels, key;
};

// The keys of a scene material (scene-format.md): "albedo", "albedo_map" and "translucency",
// read into `mat`.
// A key that is absent keeps what `mat` holds (a glTF material's override keeps the file's
// albedo); "translucency", when given, is read whole, with the scene's defaults.
// `target` finds `mat` again once its list is complete, for the maps loaded after the JSON.
void read_material_keys(ObjectReader& m, Material& mat, const fs::path& base_dir,
                        std::vector<TextureLoad>& texture_loads,
                        const std::function<Material&()>& target) {
  mat.albedo = m.vec3("albedo", mat.albedo, 0, kMaxColour);
  if (m.has("albedo_map")) {
    // A picture in sRGB (scene/albedo_map.h), multiplying "albedo".
    const std::string texture = m.string("albedo_map");
    refuse_nul(m, "albedo_map", texture);
    texture_loads.push_back({target, TextureLoad::Kind::AlbedoMap, base_dir / texture, "rgb",
                             m.key_path("albedo_map")});
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
        // {"texture": "map.png", "channels": "rgb"}: loaded once the JSON is read.
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
        texture_loads.push_back({target, TextureLoad::Kind::ThicknessMap, base_dir / texture,
                                 channels, map.key_path("texture")});
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
      texture_loads.push_back(
          {target, TextureLoad::Kind::Ramp, base_dir / ramp, "rgb", t.key_path("ramp")});
    }
    t.finish();
    mat.translucency = tr;
  }
}

// A glTF object's "materials": {SELECTOR: {scene material keys}}, into the last of `objects`.
void read_material_overrides(ObjectReader& o, const fs::path& base_dir,
                             std::vector<TextureLoad>& texture_loads,
                             std::vector<gltf::ObjectImport>& objects) {
  const std::string key = o.key_path("materials");
  if (o.has("material"))
    o.fail(key,
           "an object has \"material\" (one for every glTF material) or \"materials\" (per "
           "glTF material), not both");
  const json& overrides = o.get("materials");
  if (!overrides.is_object() || overrides.empty())
    o.fail(key, "expected a non-empty object: glTF material name, \"#N\" or \"*\" -> material");
  const std::size_t object = objects.size() - 1;
  objects[object].overrides_json = overrides.dump();
  for (auto it = overrides.begin(); it != overrides.end(); ++it) {
    ObjectReader m(it.value(), key + "." + it.key(), o.file());
    gltf::MaterialOverride override{it.key(), key + "." + it.key(), m.has("albedo"), {}};
    const std::size_t index = objects[object].overrides.size();
    read_material_keys(m, override.material, base_dir, texture_loads,
                       [&objects, object, index]() -> Material& {
                         return objects[object].overrides[index].material;
                       });
    m.finish();
    objects[object].overrides.push_back(std::move(override));
  }
}

}  // namespace

glm::dmat4 Transform::matrix() const {
  glm::dmat4 m(1.0);
  m = glm::translate(m, translate);
  m = glm::rotate(m, glm::radians(rotate_deg.z), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotate_deg.y), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotate_deg.x), glm::dvec3(1, 0, 0));
  m = glm::scale(m, scale);
  return m;
}

Scene parse_scene(const std::string& text, const fs::path& file_for_errors,
                  const fs::path& base_dir) {
  const std::string file = file_for_errors.string();
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    std::string msg = e.what();
    // nlohmann's message is "[json.exception.parse_error.101] parse error at line L, column C: ..."
    const auto pos = msg.find("parse error");
    throw InputError(file, std::to_string(line_of_offset(text, e.byte)),
                     "invalid JSON: " + (pos == std::string::npos ? msg : msg.substr(pos)));
  } catch (const json::exception& e) {
    // e.g. "[json.exception.out_of_range.406] number overflow parsing '1e400'": no position.
    std::string msg = e.what();
    const auto pos = msg.find("] ");
    throw InputError(file, "",
                     "invalid JSON: " + (pos == std::string::npos ? msg : msg.substr(pos + 2)));
  }

  Scene scene;
  scene.file = file_for_errors;
  ObjectReader top(root, "", file);

  {
    ObjectReader img = top.object("image");
    scene.width = img.integer("width", 640, 1, static_cast<int>(kMaxImageSide));
    scene.height = img.integer("height", 480, 1, static_cast<int>(kMaxImageSide));
    scene.background = img.vec3("background", glm::dvec3(0), 0, kMaxColour);
    img.finish();
  }
  {
    ObjectReader cam = top.object("camera");
    Camera& c = scene.camera;
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
  }
  scene.ambient_light = top.vec3("ambient_light", glm::dvec3(0), 0, kMaxColour);

  // Materials: an object of named materials.
  std::vector<std::string> material_names;
  std::vector<TextureLoad> texture_loads;
  {
    const json& mats = top.get("materials");
    // Empty only makes sense when every object is a glTF file bringing its own materials: a
    // mesh object's "material" names one of these, and says so when it is not there.
    if (!mats.is_object()) top.fail("materials", "expected an object of named materials");
    if (mats.size() > kMaxMaterials) {
      top.fail("materials", over_limit_message(mats.size(), "materials", kMaxMaterials));
    }
    for (auto it = mats.begin(); it != mats.end(); ++it) {
      ObjectReader m(it.value(), "materials." + it.key(), file);
      Material mat;
      mat.name = it.key();
      const std::size_t index = scene.materials.size();
      read_material_keys(m, mat, base_dir, texture_loads,
                         [&scene, index]() -> Material& { return scene.materials[index]; });
      m.finish();
      material_names.push_back(mat.name);
      scene.materials.push_back(std::move(mat));
    }
  }

  if (top.has("lights")) {
    const json& lights = top.get("lights");
    if (!lights.is_array()) top.fail("lights", "expected an array");
    if (lights.size() > kMaxLights) {
      top.fail("lights", over_limit_message(lights.size(), "lights", kMaxLights));
    }
    for (size_t i = 0; i < lights.size(); ++i) {
      ObjectReader l(lights[i], "lights[" + std::to_string(i) + "]", file);
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
      scene.lights.push_back(light);
    }
  }

  std::vector<gltf::ObjectImport> gltf_objects;
  {
    const json& objs = top.get("objects");
    if (!objs.is_array() || objs.empty()) top.fail("objects", "expected a non-empty array");
    if (objs.size() > kMaxObjects) {
      top.fail("objects", over_limit_message(objs.size(), "objects", kMaxObjects));
    }
    for (size_t i = 0; i < objs.size(); ++i) {
      const std::string kp = "objects[" + std::to_string(i) + "]";
      ObjectReader o(objs[i], kp, file);
      SceneObject obj;
      // An object is a mesh file, or the meshes of a glTF file (one node's subtree, or its
      // scene), placed by `transform` after the file's own node transforms.
      const bool gltf_object = o.has("gltf");
      const std::string key = gltf_object ? "gltf" : "mesh";
      if (gltf_object && o.has("mesh"))
        o.fail(o.key_path("mesh"), "an object has \"mesh\" or \"gltf\", not both");
      const std::string mesh = o.string(key);
      // JSON may hold "\u0000", the file system cannot: every system call would stop at the NUL
      // (and read another file), and so would the printed message.
      refuse_nul(o, key, mesh);
      obj.mesh_path = base_dir / mesh;
      // A missing mesh, or one that is no file to read (a directory, a FIFO), is the scene's
      // mistake: name the scene's key. Errors inside a mesh name the mesh file and line instead
      // (read_mesh).
      std::error_code ec;
      if (!fs::exists(obj.mesh_path, ec)) {
        o.fail(o.key_path(key), key + " file not found: " + obj.mesh_path.string());
      }
      try {
        check_input_file(obj.mesh_path, gltf_object ? InputKind::Gltf : InputKind::Mesh);
      } catch (const InputError& e) {
        o.fail(o.key_path(key), key + " file " + obj.mesh_path.string() + " " + e.what_only());
      }
      int material = -1;  // a glTF object without one keeps the file's materials
      if (!gltf_object || o.has("material")) {
        const std::string mat = o.string("material");
        auto found = std::find(material_names.begin(), material_names.end(), mat);
        if (found == material_names.end()) {
          o.fail(o.key_path("material"), "unknown material \"" + mat + "\"");
        }
        material = static_cast<int>(found - material_names.begin());
      }
      obj.material = std::max(material, 0);
      if (o.has("transform")) {
        ObjectReader t = o.object("transform");
        obj.transform.translate =
            t.vec3("translate", glm::dvec3(0), -kMaxCoordinate, kMaxCoordinate);
        obj.transform.rotate_deg = t.vec3("rotate_deg", glm::dvec3(0), -360000, 360000);
        if (t.has("scale") && t.get("scale").is_number()) {
          const double s = t.number("scale", {}, 0, kMaxScaleFactor);
          if (!(s > 0)) t.fail(t.key_path("scale"), "must be > 0");
          obj.transform.scale = glm::dvec3(s);
        } else {
          // Extension: a per-axis scale [sx, sy, sz] (normals use the inverse transpose).
          obj.transform.scale =
              t.vec3("scale", glm::dvec3(1), 1 / kMaxScaleFactor, kMaxScaleFactor);
        }
        t.finish();
      }
      if (gltf_object) {
        gltf_objects.push_back(
            {kp, obj.mesh_path, o.string("node", std::string()), material, obj.transform.matrix()});
        if (o.has("materials")) read_material_overrides(o, base_dir, texture_loads, gltf_objects);
        o.finish();
        continue;
      }
      o.finish();
      scene.objects.push_back(std::move(obj));
    }
  }
  if (top.has("regress")) {
    ObjectReader r = top.object("regress");
    scene.regress.every_path = read_tolerance_override(r);
    if (r.has("paths")) {
      const json& paths = r.get("paths");
      if (!paths.is_object()) r.fail("regress.paths", "expected an object of path names");
      for (auto it = paths.begin(); it != paths.end(); ++it) {
        ObjectReader p(it.value(), "regress.paths." + it.key(), file);
        scene.regress.per_path[it.key()] = read_tolerance_override(p);
        p.finish();
      }
    }
    r.finish();
  }
  top.finish();

  // Textures and meshes last, so a typo in the JSON is reported before any file I/O.
  for (const TextureLoad& l : texture_loads) {
    Material& m = l.material();
    switch (l.kind) {
      case TextureLoad::Kind::AlbedoMap:
        m.albedo_map = load_albedo_map(l.file, file, l.key);
        break;
      case TextureLoad::Kind::Ramp:
        m.translucency->ramp = load_lobe_ramp(l.file, file, l.key);
        break;
      case TextureLoad::Kind::ThicknessMap:
        m.translucency->thickness_map = load_thickness_map(l.file, l.channels, file, l.key);
        break;
    }
  }
  std::size_t scene_vertices = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    SceneObject& obj = scene.objects[i];
    const Material& mat = scene.materials[obj.material];
    TriangleMesh mesh = load_triangle_mesh(obj.mesh_path);
    scene_vertices += mesh.positions.size();
    if (scene_vertices > kMaxSceneVertices) {
      throw InputError(file, "objects[" + std::to_string(i) + "].mesh",
                       "the scene's meshes reach " + std::to_string(scene_vertices) +
                           " vertices with " + obj.mesh_path.string() +
                           ", more than the limit of " + std::to_string(kMaxSceneVertices));
    }
    if (mat.translucency && mat.translucency->thickness_source == ThicknessSource::Vertex &&
        !mesh.has_colors()) {
      throw InputError(file, "objects[" + std::to_string(i) + "].mesh",
                       "material \"" + mat.name + "\" uses \"thickness\": \"vertex\" but " +
                           obj.mesh_path.string() +
                           " has no vertex colours (bake them with `ltrender bake`)");
    }
    if (mat.translucency && mat.translucency->thickness_source == ThicknessSource::Vertex) {
      check_vertex_thickness(mesh, file, "objects[" + std::to_string(i) + "].mesh",
                             obj.mesh_path.string());
    }
    check_uvs_for_material(mesh, mat, file, "objects[" + std::to_string(i) + "].mesh",
                           obj.mesh_path.string());
    // World space in double: what the reference shades and what the GL paths upload
    // (camera-relative) as float.
    transform_to_world(mesh, obj.transform.matrix());
    obj.mesh = std::move(mesh);
  }
  gltf::import_objects(gltf_objects, file, scene);
  return scene;
}

Scene load_scene(const fs::path& path, const SceneOptions& options) {
  const bool gltf_file = gltf::is_gltf_path(path);
  if (!gltf_file && !options.camera.empty()) {
    throw InputError("--camera", options.camera,
                     "only a glTF scene (.gltf, .glb) has named cameras");
  }
  try {
    Scene scene =
        gltf_file ? gltf::load_gltf_scene(path, options.camera)
                  : parse_scene(read_input_file(path, InputKind::Scene), path, path.parent_path());
    if (options.default_lights && renders_unlit(scene)) {
      scene.default_lights = add_default_lights(scene);
      scene.warnings.push_back(path.string() + ": no light and no ambient_light, lit by " +
                               scene.default_lights + " (--lights none: unlit)");
    }
    // Here, where every command loads its scenes, and nowhere else: once per scene.
    for (const std::string& w : scene.warnings) print_warning(w);
    return scene;
  } catch (const std::bad_alloc&) {
    // Within the size cap, but too large for this machine: the scene's failure, named as such
    // (its meshes name themselves).
    throw InputError(path.string(), "", "out of memory reading this scene");
  }
}

SceneNeeds scene_needs(const Scene& scene) {
  SceneNeeds n;
  for (const Light& l : scene.lights) {
    (l.type == Light::Type::Directional ? n.directional_lights : n.point_lights)++;
  }
  for (const SceneObject& o : scene.objects) {
    const Material& m = scene.materials[o.material];
    n.any_albedo_map |= m.albedo_map != nullptr;
    if (!m.translucency) continue;
    n.any_translucency = true;
    n.any_vertex_thickness |= m.translucency->thickness_source == ThicknessSource::Vertex;
    n.any_thickness_map |= m.translucency->thickness_source == ThicknessSource::Texture;
    n.any_ramp |= m.translucency->ramp != nullptr;
    n.any_normalized_h |= m.translucency->normalize_distorted_light;
  }
  n.ambient_light = scene.ambient_light != glm::dvec3(0);
  return n;
}

}  // namespace lt
