#include "load/load_scene.h"

#include <new>

#include "core/error.h"
#include "core/fs.h"
#include "load/albedo_map.h"
#include "load/gltf/gltf_document.h"
#include "load/gltf/gltf_scene.h"
#include "load/thickness_map.h"
#include "mesh/mesh_io.h"
#include "scene/default_lights.h"
#include "scene/scene_limits.h"
#include "scene/scene_parse.h"

namespace lt {

namespace {

// A missing mesh or glTF file, or one that is no file to read (a directory, a FIFO), is the
// scene's mistake: name the scene's key. Errors inside the file name the file and its line
// instead (read_mesh, gltf::read_document).
void check_object_file(const ObjectDescription& object, const std::string& scene_file) {
  const std::string kind = object.file_key();
  const std::string key = object.key + "." + kind;
  std::error_code ec;
  if (!fs::exists(object.path, ec)) {
    throw InputError(scene_file, key, kind + " file not found: " + object.path.string());
  }
  try {
    check_input_file(object.path, object.source == ObjectDescription::Source::Gltf
                                      ? InputKind::Gltf
                                      : InputKind::Mesh);
  } catch (const InputError& e) {
    throw InputError(scene_file, key, kind + " file " + object.path.string() + " " + e.what_only());
  }
}

void load_maps(Material& material, const std::vector<MapReference>& maps,
               const std::string& scene_file) {
  for (const MapReference& m : maps) {
    switch (m.kind) {
      case MapReference::Kind::AlbedoMap:
        material.albedo_map = load_albedo_map(m.file, scene_file, m.key);
        break;
      case MapReference::Kind::Ramp:
        material.translucency->ramp = load_lobe_ramp(m.file, scene_file, m.key);
        break;
      case MapReference::Kind::ThicknessMap:
        material.translucency->thickness_map =
            load_thickness_map(m.file, m.channels, scene_file, m.key);
        break;
    }
  }
}

// A mesh object's mesh, checked against its material and the scene's vertex limit, in world
// space in double: what the reference shades and what the GL paths upload (camera-relative) as
// float.
TriangleMesh load_object_mesh(const ObjectDescription& object, const Material& mat,
                              const std::string& scene_file, std::size_t& scene_vertices,
                              std::vector<std::string>& warnings) {
  const std::string key = object.key + ".mesh";
  const std::string name = object.path.string();
  const LoadedMesh loaded = read_mesh(object.path);
  // What the reader accepted or dropped is said on a render too, not only by `bake`.
  for (const std::string& w : loaded.warnings) warnings.push_back(name + ": " + w);
  TriangleMesh mesh = to_triangle_mesh(loaded);
  scene_vertices += mesh.positions.size();
  if (scene_vertices > kMaxSceneVertices) {
    throw InputError(scene_file, key,
                     "the scene's meshes reach " + std::to_string(scene_vertices) +
                         " vertices with " + name + ", more than the limit of " +
                         std::to_string(kMaxSceneVertices));
  }
  if (mat.translucency && mat.translucency->thickness_source == ThicknessSource::Vertex) {
    if (!mesh.has_colors()) {
      throw InputError(scene_file, key,
                       "material \"" + mat.name + "\" uses \"thickness\": \"vertex\" but " + name +
                           " has no vertex colours (bake them with `ltrender bake`)");
    }
    check_vertex_thickness(mesh, scene_file, key, name);
  }
  check_uvs_for_material(mesh, mat, scene_file, key, name, loaded.uvs_dropped);
  transform_to_world(mesh, object.transform.matrix());
  return mesh;
}

}  // namespace

Scene load_scene(SceneDescription description) {
  const std::string file = description.file.string();
  for (const ObjectDescription& o : description.objects) check_object_file(o, file);
  for (MaterialDescription& m : description.materials) load_maps(m.material, m.maps, file);
  for (ObjectDescription& o : description.objects) {
    for (MaterialOverride& override : o.overrides)
      load_maps(override.material, override.maps, file);
  }

  Scene scene;
  static_cast<SceneSettings&>(scene) = std::move(static_cast<SceneSettings&>(description));
  for (MaterialDescription& m : description.materials)
    scene.materials.push_back(std::move(m.material));

  // The mesh objects first, then the glTF objects' meshes after them (load/gltf/gltf_scene.h).
  std::size_t scene_vertices = 0;
  for (const ObjectDescription& o : description.objects) {
    if (o.source != ObjectDescription::Source::Mesh) continue;
    SceneObject obj;
    obj.mesh_path = o.path;
    obj.material = o.material;
    obj.transform = o.transform;
    obj.mesh = load_object_mesh(o, scene.materials[static_cast<std::size_t>(o.material)], file,
                                scene_vertices, scene.warnings);
    scene.objects.push_back(std::move(obj));
  }
  gltf::import_objects(description.objects, file, scene);
  return scene;
}

Scene load_scene(const fs::path& path, const SceneOptions& options) {
  const bool gltf_file = gltf::is_gltf_path(path);
  if (!gltf_file && !options.camera.empty()) {
    throw InputError("--camera", options.camera,
                     "only a glTF scene (.gltf, .glb) has named cameras");
  }
  try {
    Scene scene = gltf_file ? gltf::load_gltf_scene(gltf::describe_gltf_scene(path), options.camera)
                            : load_scene(parse_scene_file(path));
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

}  // namespace lt
