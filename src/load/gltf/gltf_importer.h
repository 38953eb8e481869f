// The walk over a glTF file's node hierarchy that both imports share (gltf_scene.h): a whole
// .gltf/.glb scene and a JSON scene's glTF object. The parse stage: it maps each material once,
// describes each primitive as an object with its world matrix, maps the lights and collects the
// cameras it meets, into a GltfDescription (gltf_description.h); nothing is decoded.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "load/gltf/gltf_description.h"
#include "scene/scene_description.h"

namespace lt::gltf {

// glTF 2.0 §3.5.3: a node's local transform is `matrix` (column-major) or T * R * S, with the
// rotation a unit quaternion (x, y, z, w).
glm::dmat4 local_matrix(const tinygltf::Node& node);

// A node's transform can carry a point beyond the scene's coordinate bound (kMaxCoordinate)
// although the file's numbers are each within it: checked in world space, where the bound means
// something (scene_limits.h). Fails naming `node_ptr`.
void check_world_point(const Document& doc, const std::string& node_ptr, const glm::dvec3& p,
                       const std::string& what);

// "#N" (or N): the index N, the one way to pick a camera (`--camera #N`: /cameras/N) or a
// material (an override's "#N": /materials/N) without a name. -1 when `text` is not an index.
int hash_index(const std::string& text);

struct Importer {
  const Document& doc;
  GltfDescription& out;
  std::map<int, MappedMaterial> material_of;  // glTF material (-1: default) -> how it is drawn
  std::size_t objects = 0;    // the scene's before this import: its limit counts them
  bool import_lights = true;  // false for a JSON scene's object: the scene has its own
  int material_override = -1;
  const std::vector<MaterialOverride>* overrides = nullptr;  // a JSON scene's object's
  // Point and line primitives met, skipped: "/meshes/0/primitives/1 (mesh \"Wire\", LINES)".
  std::vector<std::string> skipped{};
  std::string first_skipped_mode{};  // the pointer of the first one's mode
  std::string first_skipped_name{};  // and its mode's name

  // How glTF material `index` (-1: the default material) is drawn: mapped and appended to
  // out.materials the first time, with the override that selects it (a JSON scene's object).
  MappedMaterial material(int index);
  // The override that selects material `index` (-1: the default material): by its name, else
  // by "#index", else "*".
  const MaterialOverride* override_for(int index) const;
  void apply_override(int index, Material& mat);
  // The primitives of /meshes/{mesh_index}, placed by `world` (the node at `node_ptr`): described.
  void add_mesh(int mesh_index, const glm::dmat4& world, const std::string& node_ptr);
  // The node, its mesh, camera and light, then its children.
  void visit(int node_index, const glm::dmat4& parent, int depth);
};

}  // namespace lt::gltf
