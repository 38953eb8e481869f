#include "advise/refined_scene.h"

#include <map>
#include <nlohmann/json.hpp>

#include "core/file_name.h"
#include "core/fs.h"
#include "load/gltf/gltf_document.h"
#include "mesh/mesh_io.h"

namespace lt::advise {

namespace {

using Json = nlohmann::ordered_json;

// A file the scene names (relative to the scene's folder, as the loader resolves it), named
// relative to `dir` instead; absolute when no relative path leads there (another drive).
std::string rebased(const std::string& value, const fs::path& base_dir, const fs::path& dir) {
  const fs::path target = fs::absolute(base_dir / value).lexically_normal();
  const fs::path relative = target.lexically_relative(fs::absolute(dir).lexically_normal());
  return (relative.empty() ? target : relative).generic_string();
}

void rebase_key(Json& object, const char* key, const fs::path& base_dir, const fs::path& dir) {
  if (object.is_object() && object.contains(key) && object[key].is_string())
    object[key] = rebased(object[key].get<std::string>(), base_dir, dir);
}

// The files a material names (scene-format.md): "albedo_map", translucency's "ramp" and its
// thickness map's "texture".
void rebase_material(Json& material, const fs::path& base_dir, const fs::path& dir) {
  if (!material.is_object()) return;
  rebase_key(material, "albedo_map", base_dir, dir);
  if (!material.contains("translucency")) return;
  Json& t = material["translucency"];
  rebase_key(t, "ramp", base_dir, dir);
  if (t.is_object() && t.contains("thickness"))
    rebase_key(t["thickness"], "texture", base_dir, dir);
}

}  // namespace

RefinedFiles write_refined_scene(const Advice& a, const fs::path& staging,
                                 const fs::path& final_dir) {
  RefinedFiles out;
  std::map<std::size_t, std::string> mesh_of_object;  // scene object -> written file
  for (const MaterialAdvice& ma : a.materials) {
    if (!ma.refinement || !ma.refinement->holds_at) continue;
    for (const auto& [object, mesh] : ma.refinement->meshes) {
      const std::string name =
          file_name_safe(ma.name) + "_object" + std::to_string(object) + ".ply";
      write_triangle_mesh(staging / name, mesh);
      out.written.push_back(name);
      mesh_of_object[object] = name;
    }
  }
  if (mesh_of_object.empty()) return out;
  const fs::path& scene_file = a.options.scene_file;
  if (gltf::is_gltf_path(scene_file)) {
    out.not_written = "a glTF scene has no \"mesh\" key to point at the refined meshes";
    return out;
  }
  Json scene = Json::parse(read_input_file(scene_file, InputKind::Scene));  // loaded already
  const fs::path base_dir = scene_file.parent_path();
  if (scene.contains("materials") && scene["materials"].is_object()) {
    for (auto& [name, material] : scene["materials"].items())
      rebase_material(material, base_dir, final_dir);
  }
  // The loader puts the "mesh" objects first in scene.objects, in file order, then what the
  // glTF objects bring (scene.cpp).
  std::size_t mesh_objects = 0;
  for (Json& o : scene["objects"]) {
    if (o.contains("gltf")) {
      rebase_key(o, "gltf", base_dir, final_dir);
      if (o.contains("materials") && o["materials"].is_object()) {
        for (auto& [name, material] : o["materials"].items())
          rebase_material(material, base_dir, final_dir);
      }
      continue;
    }
    const auto refined = mesh_of_object.find(mesh_objects++);
    if (refined == mesh_of_object.end()) {
      rebase_key(o, "mesh", base_dir, final_dir);
      continue;
    }
    o["mesh"] = refined->second;  // beside the scene
    o.erase("transform");         // the mesh is written in world space
  }
  if (mesh_of_object.rbegin()->first >= mesh_objects) {
    out.not_written = "a refined object was brought by a glTF file, which has no \"mesh\" key";
    return out;
  }
  out.written.push_back("refined.json");
  write_text_file(staging / out.written.back(), scene.dump(2) + "\n");
  return out;
}

}  // namespace lt::advise
