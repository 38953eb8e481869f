#include "load/gltf/gltf_importer.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "load/gltf/gltf_geometry.h"
#include "load/gltf/gltf_lights.h"
#include "load/gltf/gltf_materials.h"
#include "load/gltf/gltf_notes.h"
#include "load/gltf/gltf_topology.h"
#include "scene/scene_limits.h"

namespace lt::gltf {

namespace {
using json = nlohmann::json;
}  // namespace

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

void check_world_point(const Document& doc, const std::string& node_ptr, const glm::dvec3& p,
                       const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    if (!(std::abs(p[c]) <= kMaxCoordinate)) {
      doc.fail(node_ptr, "its transform puts " + what + " at " + json({p.x, p.y, p.z}).dump() +
                             ", beyond the coordinate limit 1e9");
    }
  }
}

int hash_index(const std::string& text) {
  const std::string digits = text.rfind('#', 0) == 0 ? text.substr(1) : text;
  if (digits.empty() || digits.size() > 6 ||
      !std::all_of(digits.begin(), digits.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
    return -1;
  return std::stoi(digits);
}

int Importer::material(int index) {
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
  Material mat = index < 0 ? default_material() : map_material(doc, index, scene.import_notes, &uv);
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
const MaterialOverride* Importer::override_for(int index) const {
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

void Importer::apply_override(int index, Material& mat) {
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

void Importer::add_mesh(int mesh_index, const glm::dmat4& world, const std::string& node_ptr) {
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
      if (skipped.empty()) first_skipped_mode = ptr + "/mode", first_skipped_name = mode_name(mode);
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

void Importer::visit(int node_index, const glm::dmat4& parent, int depth) {
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

}  // namespace lt::gltf
