#include "load/gltf/gltf_importer.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
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

MappedMaterial Importer::material(int index) {
  // A scene's material: no texture of the file, its albedo map reads TEXCOORD_0 as it is.
  if (material_override >= 0) return {material_override, {}};
  auto it = material_of.find(index);
  if (it != material_of.end()) return it->second;
  const std::size_t m = out.first_material + out.materials.size();
  if (m >= kMaxMaterials)
    doc.fail("/materials", over_limit_message(m + 1, "materials", kMaxMaterials));
  if (index >= static_cast<int>(doc.model.materials.size())) {
    doc.fail("/materials/" + std::to_string(index), "no such material");
  }
  GltfMaterial mat =
      index < 0 ? GltfMaterial{default_material(), {}} : map_material(doc, index, out.notes);
  MappedMaterial mapped{static_cast<int>(m), {}};
  if (mat.texture) mapped.uv = mat.texture->coordinates;
  if (overrides) {
    // A scene's albedo map replaces the file's texture and reads TEXCOORD_0 as it is.
    if (const MaterialOverride* o = override_for(index); o && o->material.albedo_map)
      mapped.uv = {};
    apply_override(index, mat.material);
  }
  out.materials.push_back(std::move(mat));
  return material_of[index] = mapped;
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
  out.notes.push_back(
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
    const std::size_t n = objects + out.primitives.size();
    if (n >= kMaxObjects)
      doc.fail(ptr, over_limit_message(n + 1, "objects (primitives)", kMaxObjects));
    const int mode = mesh.primitives[p].mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
      // No surface to shade (gltf_topology.h): skipped, said once per file (skip_warning).
      if (skipped.empty()) first_skipped_mode = ptr + "/mode", first_skipped_name = mode_name(mode);
      skipped.push_back(
          ptr + " (mesh " +
          json(mesh.name.empty() ? "#" + std::to_string(mesh_index) : mesh.name).dump() + ", " +
          mode_name(mode) + ")");
      out.notes.push_back("ignored " + ptr + ": " + mode_name(mode) + " carry no surface to shade");
      continue;
    }
    // notes_at after the material's notes: a braced list is evaluated left to right.
    out.primitives.push_back({mesh_index, static_cast<int>(p),
                              material(mesh.primitives[p].material), world, node_ptr,
                              out.notes.size()});
  }
  note_unmapped_keys(at_pointer(doc.json, "/meshes/" + std::to_string(mesh_index)),
                     "/meshes/" + std::to_string(mesh_index), {"primitives"},
                     "not part of the term", out.notes);
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
    out.cameras.push_back({node.camera, node_index, world});
    if (!import_lights)
      out.notes.push_back("ignored " + ptr + "/camera: a JSON scene's object brings no camera");
  }
  const json& light = at_pointer(doc.json, ptr + "/extensions/KHR_lights_punctual/light");
  if (light.is_number_integer() && !import_lights) {
    out.notes.push_back("ignored " + ptr +
                        "/extensions/KHR_lights_punctual: a JSON scene's object brings no lights");
  } else if (light.is_number_integer()) {
    if (out.lights.size() >= kMaxLights)
      doc.fail(ptr, over_limit_message(out.lights.size() + 1, "lights", kMaxLights));
    out.lights.push_back(map_light(doc, light.get<int>(), world, out.notes));
    check_world_point(doc, ptr, out.lights.back().position, "its light");
  }
  note_unmapped_keys(at_pointer(doc.json, ptr), ptr,
                     {"children", "matrix", "translation", "rotation", "scale", "mesh", "camera",
                      "KHR_lights_punctual"},
                     "not part of the term (no skinning or animation)", out.notes);
  for (int child : node.children) visit(child, world, depth + 1);
}

}  // namespace lt::gltf
