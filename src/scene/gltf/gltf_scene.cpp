#include "scene/gltf/gltf_scene.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <map>
#include <set>

#include "core/error.h"
#include "scene/gltf/gltf_document.h"
#include "scene/gltf/gltf_geometry.h"
#include "scene/gltf/gltf_lights.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/gltf/gltf_notes.h"
#include "scene/gltf/gltf_topology.h"
#include "scene/scene_limits.h"

namespace lt::gltf {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// A camera's far plane when zfar is absent (an infinite projection, glTF 2.0 §3.10.3): this many
// times znear, which keeps a 24-bit depth buffer usable.
constexpr double kInfiniteFarOverNear = 1e5;

// glTF 2.0 §3.5.3: a node's local transform is `matrix` (column-major) or T * R * S, with the
// rotation a unit quaternion (x, y, z, w).
glm::dmat4 local_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) m = glm::translate(m, glm::make_vec3(node.translation.data()));
  if (node.rotation.size() == 4) {
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    m = m * glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3) m = glm::scale(m, glm::make_vec3(node.scale.data()));
  return m;
}

// A node's transform can carry a point beyond the scene's coordinate bound (kMaxCoordinate)
// although the file's numbers are each within it: checked in world space, where the bound means
// something (scene_limits.h).
void check_world_point(const Document& doc, const std::string& node_ptr, const glm::dvec3& p,
                       const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    if (!(std::abs(p[c]) <= kMaxCoordinate)) {
      doc.fail(node_ptr, "its transform puts " + what + " at " + json({p.x, p.y, p.z}).dump() +
                             ", beyond the coordinate limit 1e9");
    }
  }
}

struct CameraInstance {
  int camera, node;
  glm::dmat4 world;
};

struct Importer {
  const Document& doc;
  Scene& scene;
  std::map<int, int> material_of;  // glTF material (-1: default) -> Scene::materials index
  std::vector<CameraInstance> cameras;
  std::size_t vertices = 0;
  bool import_lights = true;  // false for a JSON scene's object: the scene has its own
  int material_override = -1;
  std::map<int, TextureCoordinates> uv_of = {};  // Scene::materials index -> its albedo map's UVs
  const std::vector<MaterialOverride>* overrides = nullptr;  // a JSON scene's object's
  // Point and line primitives met, skipped: "/meshes/0/primitives/1 (mesh \"Wire\", LINES)".
  std::vector<std::string> skipped{};
  std::string first_skipped_mode{};  // the pointer of the first one's mode
  std::string first_skipped_name{};  // and its mode's name

  int material(int index) {
    if (material_override >= 0) return material_override;
    auto it = material_of.find(index);
    if (it != material_of.end()) return it->second;
    if (scene.materials.size() >= kMaxMaterials) {
      doc.fail("/materials",
               over_limit_message(scene.materials.size() + 1, "materials", kMaxMaterials));
    }
    if (index >= static_cast<int>(doc.model.materials.size())) {
      doc.fail("/materials/" + std::to_string(index), "no such material");
    }
    TextureCoordinates uv;
    Material mat =
        index < 0 ? default_material() : map_material(doc, index, scene.import_notes, &uv);
    if (overrides) {
      // A scene's albedo map replaces the file's texture and reads TEXCOORD_0 as it is.
      if (const MaterialOverride* o = override_for(index); o && o->material.albedo_map) uv = {};
      apply_override(index, mat);
    }
    scene.materials.push_back(std::move(mat));
    const int m = static_cast<int>(scene.materials.size() - 1);
    uv_of[m] = uv;
    return material_of[index] = m;
  }

  // The override that selects material `index` (-1: the default material): by its name, else
  // by "#index", else "*".
  const MaterialOverride* override_for(int index) const {
    const std::string name =
        index < 0 ? std::string() : doc.model.materials[static_cast<std::size_t>(index)].name;
    for (const std::string& selector :
         {name, index < 0 ? std::string() : "#" + std::to_string(index), std::string("*")}) {
      if (selector.empty()) continue;
      for (const MaterialOverride& o : *overrides)
        if (o.selector == selector) return &o;
    }
    return nullptr;
  }

  void apply_override(int index, Material& mat) {
    const MaterialOverride* o = override_for(index);
    if (!o) return;
    if (o->albedo_given) mat.albedo = o->material.albedo;
    // An albedo map given here replaces the file's base colour texture; it reads TEXCOORD_0.
    if (o->material.albedo_map) mat.albedo_map = o->material.albedo_map;
    if (o->material.translucency) mat.translucency = o->material.translucency;
    scene.import_notes.push_back(
        "mapped " + o->key + " -> " +
        (index < 0 ? std::string("the default material") : "/materials/" + std::to_string(index)) +
        (o->albedo_given ? ": albedo" : ":") +
        (o->material.translucency ? std::string(o->albedo_given ? " and " : " ") + "translucency"
                                  : std::string()) +
        " from the scene");
  }

  void add_mesh(int mesh_index, const glm::dmat4& world, const std::string& node_ptr) {
    const tinygltf::Mesh& mesh = doc.model.meshes[static_cast<std::size_t>(mesh_index)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const std::string ptr =
          "/meshes/" + std::to_string(mesh_index) + "/primitives/" + std::to_string(p);
      if (scene.objects.size() >= kMaxObjects) {
        doc.fail(ptr,
                 over_limit_message(scene.objects.size() + 1, "objects (primitives)", kMaxObjects));
      }
      const int mode = mesh.primitives[p].mode;
      if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
        // No surface to shade (gltf_topology.h): skipped, said once per file (skip_warning).
        if (skipped.empty())
          first_skipped_mode = ptr + "/mode", first_skipped_name = mode_name(mode);
        skipped.push_back(
            ptr + " (mesh " +
            json(mesh.name.empty() ? "#" + std::to_string(mesh_index) : mesh.name).dump() + ", " +
            mode_name(mode) + ")");
        scene.import_notes.push_back("ignored " + ptr + ": " + mode_name(mode) +
                                     " carry no surface to shade");
        continue;
      }
      SceneObject obj;
      obj.mesh_path = doc.path;
      obj.material = material(mesh.primitives[p].material);
      // The UVs the material's albedo map reads (its texCoord set and texture transform); a
      // scene's material override reads TEXCOORD_0 as it is.
      const auto uv = uv_of.find(obj.material);
      PrimitiveMesh prim = read_primitive(doc, mesh_index, static_cast<int>(p),
                                          uv == uv_of.end() ? TextureCoordinates{} : uv->second);
      vertices += prim.mesh.positions.size();
      if (vertices > kMaxSceneVertices)
        doc.fail(ptr, over_limit_message(vertices, "vertices", kMaxSceneVertices));
      scene.import_notes.insert(scene.import_notes.end(), prim.notes.begin(), prim.notes.end());
      const Material& mat = scene.materials[static_cast<std::size_t>(obj.material)];
      if (mat.translucency && mat.translucency->thickness_source == ThicknessSource::Vertex) {
        if (!prim.mesh.has_colors())
          doc.fail(ptr, "material \"" + mat.name +
                            "\" takes its thickness from COLOR_0, which this primitive lacks");
        check_vertex_thickness(prim.mesh, doc.path.string(), ptr + "/attributes/COLOR_0",
                               "the primitive");
      } else if (prim.mesh.has_colors()) {
        scene.import_notes.push_back("ignored " + ptr +
                                     "/attributes/COLOR_0 as base colour: read and kept, the "
                                     "thickness only with extras.ltrender.thickness \"vertex\"");
      }
      check_uvs_for_material(prim.mesh, mat, doc.path.string(), ptr, "the primitive");
      transform_to_world(prim.mesh, world);
      for (std::size_t v = 0; v < prim.mesh.positions.size(); ++v) {
        check_world_point(doc, node_ptr, prim.mesh.positions[v],
                          "vertex " + std::to_string(v) + " of " + ptr);
      }
      obj.mesh = std::move(prim.mesh);
      scene.objects.push_back(std::move(obj));
    }
    note_unmapped_keys(at_pointer(doc.json, "/meshes/" + std::to_string(mesh_index)),
                       "/meshes/" + std::to_string(mesh_index), {"primitives"},
                       "not part of the term", scene.import_notes);
  }

  void visit(int node_index, const glm::dmat4& parent, int depth) {
    const std::string ptr = "/nodes/" + std::to_string(node_index);
    if (node_index < 0 || static_cast<std::size_t>(node_index) >= doc.model.nodes.size())
      doc.fail(ptr, "no such node");
    // §3.5.1: the node hierarchy is a set of disjoint trees; a cycle would recurse forever.
    if (depth > 1024) doc.fail(ptr, "the node hierarchy is deeper than 1024 (a cycle?)");
    const tinygltf::Node& node = doc.model.nodes[static_cast<std::size_t>(node_index)];
    const glm::dmat4 world = parent * local_matrix(node);
    if (node.mesh >= static_cast<int>(doc.model.meshes.size()))
      doc.fail(ptr + "/mesh", "no such mesh");
    if (node.camera >= static_cast<int>(doc.model.cameras.size()))
      doc.fail(ptr + "/camera", "no such camera");
    if (node.mesh >= 0) add_mesh(node.mesh, world, ptr);
    if (node.camera >= 0) {
      cameras.push_back({node.camera, node_index, world});
      if (!import_lights)
        scene.import_notes.push_back("ignored " + ptr +
                                     "/camera: a JSON scene's object brings no camera");
    }
    const json& light = at_pointer(doc.json, ptr + "/extensions/KHR_lights_punctual/light");
    if (light.is_number_integer() && !import_lights) {
      scene.import_notes.push_back(
          "ignored " + ptr +
          "/extensions/KHR_lights_punctual: a JSON scene's object brings no lights");
    } else if (light.is_number_integer()) {
      if (scene.lights.size() >= kMaxLights)
        doc.fail(ptr, over_limit_message(scene.lights.size() + 1, "lights", kMaxLights));
      scene.lights.push_back(map_light(doc, light.get<int>(), world, scene.import_notes));
      check_world_point(doc, ptr, scene.lights.back().position, "its light");
    }
    note_unmapped_keys(at_pointer(doc.json, ptr), ptr,
                       {"children", "matrix", "translation", "rotation", "scale", "mesh", "camera",
                        "KHR_lights_punctual"},
                       "not part of the term (no skinning or animation)", scene.import_notes);
    for (int child : node.children) visit(child, world, depth + 1);
  }

  void camera_from(const CameraInstance& inst) {
    const tinygltf::Camera& cam = doc.model.cameras[static_cast<std::size_t>(inst.camera)];
    const std::string ptr = "/cameras/" + std::to_string(inst.camera);
    Camera& c = scene.camera;
    // §3.10.1: a camera looks down its node's -Z with +Y up.
    c.eye = glm::dvec3(inst.world * glm::dvec4(0, 0, 0, 1));
    check_world_point(doc, "/nodes/" + std::to_string(inst.node), c.eye, "its camera");
    c.target = c.eye + glm::normalize(glm::dvec3(inst.world * glm::dvec4(0, 0, -1, 0)));
    c.up = glm::dvec3(inst.world * glm::dvec4(0, 1, 0, 0));
    if (cam.type == "perspective") {
      c.projection = Camera::Projection::Perspective;
      c.fov_y_deg = cam.perspective.yfov * 180 / M_PI;
      c.near = cam.perspective.znear;
      c.far = cam.perspective.zfar > 0 ? cam.perspective.zfar : c.near * kInfiniteFarOverNear;
      if (!(c.fov_y_deg >= 1e-3 && c.fov_y_deg <= 179))
        doc.fail(ptr + "/perspective/yfov", "out of range (0.001 to 179 degrees)");
      if (!(c.near > 0)) doc.fail(ptr + "/perspective/znear", "must be > 0");
      if (cam.perspective.aspectRatio > 0) {
        scene.width = static_cast<int>(std::clamp(
            std::round(kDefaultHeight * cam.perspective.aspectRatio), 1.0, kMaxImageSide));
      }
      scene.import_notes.push_back(
          "mapped " + ptr + " (perspective, node " + std::to_string(inst.node) + ") -> fov_y_deg " +
          json(c.fov_y_deg).dump() + ", near " + json(c.near).dump() + ", far " +
          json(c.far).dump() + (cam.perspective.zfar > 0 ? "" : " (no zfar: near x 1e5)") +
          ", image " + std::to_string(scene.width) + "x" + std::to_string(scene.height));
    } else {
      c.projection = Camera::Projection::Orthographic;
      // §3.10.3: ymag is half the orthographic view's height.
      c.height = 2 * cam.orthographic.ymag;
      c.near = cam.orthographic.znear;
      c.far = cam.orthographic.zfar;
      if (!(c.height > 0)) doc.fail(ptr + "/orthographic/ymag", "must be > 0");
      scene.import_notes.push_back("mapped " + ptr + " (orthographic, node " +
                                   std::to_string(inst.node) + ") -> height " +
                                   json(c.height).dump() + " (2 x ymag), near " +
                                   json(c.near).dump() + ", far " + json(c.far).dump());
      scene.import_notes.push_back("ignored " + ptr +
                                   "/orthographic/xmag: the image's aspect sets the width");
    }
    if (!(c.far > c.near)) doc.fail(ptr, "zfar must be greater than znear");
    if (!(glm::length(glm::cross(c.forward(), c.up)) > 1e-9))
      doc.fail("/nodes/" + std::to_string(inst.node), "its transform collapses the camera's axes");
  }

  // No camera in the file: look down -Z at the meshes' bounding box, from far enough away that
  // its bounding sphere fits the default 40 degree view.
  void framing_camera() {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const SceneObject& o : scene.objects) {
      for (const glm::dvec3& p : o.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    if (scene.objects.empty() || lo.x > hi.x) lo = hi = glm::dvec3(0);
    const glm::dvec3 centre = (lo + hi) * 0.5;
    const double radius = std::max(glm::length(hi - lo) * 0.5, 1e-3);
    Camera& c = scene.camera;
    const double distance = radius / std::sin(glm::radians(c.fov_y_deg) * 0.5);
    c.target = centre;
    c.eye = centre + glm::dvec3(0, 0, distance);
    c.near = std::max(distance - radius, distance * 1e-3);
    c.far = distance + radius * 2;
    scene.import_notes.push_back(
        "default camera: no camera in the file, framing the meshes from +Z (eye " +
        json({c.eye.x, c.eye.y, c.eye.z}).dump() + ")");
  }
};

bool camera_named(const Document& doc, const CameraInstance& c, const std::string& name) {
  return doc.model.cameras[static_cast<std::size_t>(c.camera)].name == name ||
         doc.model.nodes[static_cast<std::size_t>(c.node)].name == name;
}

// "#N" (or N): the index N, the one way to pick a camera (`--camera #N`: /cameras/N) or a
// material (an override's "#N": /materials/N) without a name. -1 when `text` is not an index.
int hash_index(const std::string& text) {
  const std::string digits = text.rfind('#', 0) == 0 ? text.substr(1) : text;
  if (digits.empty() || digits.size() > 6 ||
      !std::all_of(digits.begin(), digits.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
    return -1;
  return std::stoi(digits);
}

// How `--camera` can name a camera the scene places: its name, else its node's, else #N.
std::string camera_label(const Document& doc, const CameraInstance& c) {
  const std::string& name = doc.model.cameras[static_cast<std::size_t>(c.camera)].name;
  if (!name.empty()) return name;
  const std::string& node = doc.model.nodes[static_cast<std::size_t>(c.node)].name;
  if (!node.empty()) return node;
  std::string index = "#";  // appended, not "#" + ...: GCC 12 warns falsely (-Wrestrict) on that
  return index += std::to_string(c.camera);
}

// The camera `--camera` asks for: by name (of the camera or its node) first, so a camera named
// "2" stays reachable by its name, then by index.
const CameraInstance& chosen_camera(const Document& doc, const std::vector<CameraInstance>& cameras,
                                    const std::string& wanted) {
  auto it = std::find_if(cameras.begin(), cameras.end(),
                         [&](const CameraInstance& c) { return camera_named(doc, c, wanted); });
  const int index = hash_index(wanted);
  if (it == cameras.end() && index >= 0)
    it = std::find_if(cameras.begin(), cameras.end(),
                      [&](const CameraInstance& c) { return c.camera == index; });
  if (it != cameras.end()) return *it;
  std::string labels;
  for (const CameraInstance& c : cameras)
    labels += (labels.empty() ? "" : ", ") + camera_label(doc, c);
  throw InputError("--camera", wanted,
                   "no camera of that name or index (#N: /cameras/N) on a node of the scene in " +
                       doc.path.string() + " (cameras: " + (labels.empty() ? "none" : labels) +
                       ")");
}

// The product of a node's ancestors' transforms (glTF 2.0 §3.5.3: world = parent's world x
// local), found through the children lists.
glm::dmat4 ancestors_matrix(const Document& doc, int node) {
  glm::dmat4 m(1.0);
  for (int depth = 0; depth < 1024; ++depth) {
    int parent = -1;
    for (std::size_t p = 0; p < doc.model.nodes.size() && parent < 0; ++p) {
      const auto& ch = doc.model.nodes[p].children;
      if (std::find(ch.begin(), ch.end(), node) != ch.end()) parent = static_cast<int>(p);
    }
    if (parent < 0) return m;
    m = local_matrix(doc.model.nodes[static_cast<std::size_t>(parent)]) * m;
    node = parent;
  }
  doc.fail("/nodes/" + std::to_string(node), "the node hierarchy is deeper than 1024 (a cycle?)");
}

// The roots of the scene to render: §3.5.2 names it by `scene`; without it the spec leaves the
// choice to the application, and the first is taken.
const std::vector<int>& scene_roots(const Document& doc, int& scene_index) {
  if (doc.model.scenes.empty()) doc.fail("/scenes", "the file has no scene to render");
  scene_index = doc.model.defaultScene >= 0 ? doc.model.defaultScene : 0;
  if (scene_index >= static_cast<int>(doc.model.scenes.size())) doc.fail("/scene", "no such scene");
  return doc.model.scenes[static_cast<std::size_t>(scene_index)].nodes;
}

// The one warning line of a file whose point or line primitives were skipped (empty: none), and
// the refusal when nothing else was left to draw.
std::string skip_warning(const Document& doc, const std::vector<std::string>& skipped) {
  if (skipped.empty()) return "";
  std::string list;
  for (std::size_t i = 0; i < skipped.size() && i < 3; ++i) list += (i ? ", " : "") + skipped[i];
  if (skipped.size() > 3) list += " and " + std::to_string(skipped.size() - 3) + " more";
  return doc.path.string() + ": skipped " + std::to_string(skipped.size()) +
         (skipped.size() == 1 ? " primitive" : " primitives") +
         " without a surface (points and lines are not shaded): " + list;
}
[[noreturn]] void refuse_nothing_left(const Document& doc, const Importer& im) {
  doc.fail(im.first_skipped_mode,
           im.first_skipped_name +
               " carry no surface (points and lines are not shaded), and no triangles are left "
               "to draw (" +
               std::to_string(im.skipped.size()) + " skipped)");
}

}  // namespace

namespace {

// A file the JSON scene imports, read once however many objects take it: its materials are
// mapped once (two objects of one file share them; appended twice they would be two materials
// of one name, listed twice by `info` and refused by gx's C names), and a note it gives once.
struct ImportedFile {
  Document doc;
  // As Importer::material_of, kept between its objects, per set of overrides (overrides_json).
  std::map<std::string, std::map<int, int>> material_of;
  std::set<std::string> notes;
};

// Every override names a material the file has ("*" always does).
void check_override_selectors(const ObjectImport& object, const Document& doc,
                              const std::string& scene_file) {
  const auto& materials = doc.model.materials;
  for (const MaterialOverride& o : object.overrides) {
    if (o.selector == "*") continue;
    const bool named =
        std::any_of(materials.begin(), materials.end(),
                    [&](const tinygltf::Material& m) { return m.name == o.selector; });
    const int index = o.selector.rfind('#', 0) == 0 ? hash_index(o.selector) : -1;
    if (named || (index >= 0 && index < static_cast<int>(materials.size()))) continue;
    std::string names;
    for (std::size_t m = 0; m < materials.size() && m < 8; ++m)
      names += (m ? ", " : "") + (materials[m].name.empty() ? "#" + std::to_string(m)
                                                            : json(materials[m].name).dump());
    if (materials.size() > 8) names += ", ...";
    throw InputError(scene_file, o.key,
                     "no material named \"" + o.selector + "\" (nor #N, N < " +
                         std::to_string(materials.size()) + ") in " + object.path.string() +
                         " (its materials: " + (names.empty() ? "none" : names) + ")");
  }
}

void import_object(const ObjectImport& object, ImportedFile& file, const std::string& scene_file,
                   Scene& scene) {
  const Document& doc = file.doc;
  const std::size_t first_note = scene.import_notes.size();
  check_override_selectors(object, doc, scene_file);
  Importer im{doc, scene, file.material_of[object.overrides_json], {}, 0};
  im.overrides = &object.overrides;
  for (const SceneObject& o : scene.objects) im.vertices += o.mesh.positions.size();
  im.import_lights = false;
  im.material_override = object.material;
  const std::size_t first = scene.objects.size();
  if (object.node.empty()) {
    int scene_index = 0;
    for (int root : scene_roots(doc, scene_index)) im.visit(root, object.placement, 0);
  } else {
    int found = -1;
    for (std::size_t n = 0; n < doc.model.nodes.size() && found < 0; ++n) {
      if (doc.model.nodes[n].name == object.node) found = static_cast<int>(n);
    }
    if (found < 0)
      throw InputError(scene_file, object.key + ".node",
                       "no node named \"" + object.node + "\" in " + object.path.string());
    im.visit(found, object.placement * ancestors_matrix(doc, found), 0);
  }
  if (scene.objects.size() == first && !im.skipped.empty()) refuse_nothing_left(doc, im);
  const std::string warning = skip_warning(doc, im.skipped);
  if (!warning.empty() && file.notes.insert(warning).second) scene.warnings.push_back(warning);
  if (scene.objects.size() == first)
    throw InputError(
        scene_file, object.key,
        "no mesh under " +
            (object.node.empty() ? std::string("the scene") : "node \"" + object.node + "\"") +
            " of " + object.path.string());
  for (std::size_t i = first; i < scene.objects.size(); ++i)
    scene.objects[i].transform = Transform{};
  file.material_of[object.overrides_json] = im.material_of;
  // The file's notes once: a second object of the file repeats what the first one noted.
  auto kept = scene.import_notes.begin() + static_cast<std::ptrdiff_t>(first_note);
  for (auto it = kept; it != scene.import_notes.end(); ++it) {
    if (!file.notes.insert(*it).second) continue;
    if (kept != it) *kept = std::move(*it);
    ++kept;
  }
  scene.import_notes.erase(kept, scene.import_notes.end());
}

}  // namespace

void import_objects(const std::vector<ObjectImport>& objects, const std::string& scene_file,
                    Scene& scene) {
  std::map<fs::path, ImportedFile> files;
  for (const ObjectImport& object : objects) {
    auto it = files.find(object.path.lexically_normal());
    if (it == files.end()) {
      it = files
               .emplace(object.path.lexically_normal(),
                        ImportedFile{read_document(object.path), {}, {}})
               .first;
      for (const std::string& w : it->second.doc.warnings) {
        if (it->second.notes.insert(w).second) scene.import_notes.push_back(w);
      }
    }
    import_object(object, it->second, scene_file, scene);
  }
}

Scene load_gltf_scene(const fs::path& path, const std::string& camera) {
  const Document doc = read_document(path);
  Scene scene;
  scene.file = path;
  scene.width = kDefaultWidth;
  scene.height = kDefaultHeight;
  Importer im{doc, scene, {}, {}, 0};
  scene.import_notes.insert(scene.import_notes.end(), doc.warnings.begin(), doc.warnings.end());

  int scene_index = 0;
  for (int root : scene_roots(doc, scene_index)) im.visit(root, glm::dmat4(1.0), 0);
  for (std::size_t s = 0; s < doc.model.scenes.size(); ++s) {
    if (static_cast<int>(s) != scene_index)
      scene.import_notes.push_back("ignored /scenes/" + std::to_string(s) +
                                   ": not the scene to render");
  }
  if (scene.objects.empty() && !im.skipped.empty()) refuse_nothing_left(doc, im);
  if (scene.objects.empty())
    doc.fail("/scenes/" + std::to_string(scene_index), "the scene has no mesh to render");
  if (!im.skipped.empty()) scene.warnings.push_back(skip_warning(doc, im.skipped));

  if (!camera.empty()) {
    im.camera_from(chosen_camera(doc, im.cameras, camera));
  } else if (!im.cameras.empty()) {
    im.camera_from(im.cameras.front());
  } else {
    im.framing_camera();
  }
  if (scene.lights.empty())
    scene.import_notes.push_back(
        "no KHR_lights_punctual light in the scene (`info`'s lights line says what lights it)");

  // Textures, images and samplers are read through a base colour texture (its own notes say
  // which); without one they are listed as ignored.
  const bool sampled = std::any_of(scene.materials.begin(), scene.materials.end(),
                                   [](const Material& m) { return m.albedo_map != nullptr; });
  if (sampled) {
    note_unmapped_keys(doc.json, "",
                       {"asset", "scene", "scenes", "nodes", "meshes", "accessors", "bufferViews",
                        "buffers", "textures", "images", "samplers", "materials", "cameras",
                        "extensionsUsed", "extensionsRequired", "KHR_lights_punctual"},
                       "not used by the term", scene.import_notes);
  } else {
    note_unmapped_keys(
        doc.json, "",
        {"asset", "scene", "scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers",
         "materials", "cameras", "extensionsUsed", "extensionsRequired", "KHR_lights_punctual"},
        "not used by the term", scene.import_notes);
  }
  return scene;
}

}  // namespace lt::gltf
