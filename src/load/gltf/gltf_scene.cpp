#include "load/gltf/gltf_scene.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/error.h"
#include "load/gltf/gltf_cameras.h"
#include "load/gltf/gltf_document.h"
#include "load/gltf/gltf_geometry.h"
#include "load/gltf/gltf_importer.h"
#include "load/gltf/gltf_notes.h"
#include "load/gltf/gltf_textures.h"

namespace lt::gltf {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

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

// The one warning line of a file whose point or line primitives were skipped (empty: none), or
// the refusal when nothing else was left to draw.
std::string skip_warning(const Document& doc, const Importer& im) {
  const std::vector<std::string>& skipped = im.skipped;
  if (skipped.empty()) return "";
  if (im.out.primitives.empty())
    doc.fail(im.first_skipped_mode, im.first_skipped_name +
                                        " carry no surface (points and lines are not shaded), and "
                                        "no triangles are left to draw (" +
                                        std::to_string(skipped.size()) + " skipped)");
  std::string list;
  for (std::size_t i = 0; i < skipped.size() && i < 3; ++i) list += (i ? ", " : "") + skipped[i];
  if (skipped.size() > 3) list += " and " + std::to_string(skipped.size() - 3) + " more";
  return doc.path.string() + ": skipped " + std::to_string(skipped.size()) +
         (skipped.size() == 1 ? " primitive" : " primitives") +
         " without a surface (points and lines are not shaded): " + list;
}

// The load stage: appends the description's materials, objects and lights to `scene`, and its
// notes with each decoded item's own in the walk's place. Decodes in the walk's order, a
// material's texture before the first primitive that uses it, so errors come as the walk met them.
void load_description(GltfDescription& d, Scene& scene) {
  const Document& doc = *d.doc;
  std::size_t vertices = 0, taken = 0;
  for (const SceneObject& o : scene.objects) vertices += o.mesh.positions.size();
  auto notes_to = [&](std::size_t at) {  // the description's notes up to `at`
    for (; taken < at; ++taken) scene.import_notes.push_back(std::move(d.notes[taken]));
  };
  for (GltfMaterial& m : d.materials) scene.materials.push_back(m.material);
  std::vector<bool> loaded(d.materials.size());
  for (const PrimitiveDescription& p : d.primitives) {
    // < 0: the scene's already (its own material, or one an earlier object of the file mapped).
    const int m = p.material.index - static_cast<int>(d.first_material);
    if (m >= 0 && !loaded[static_cast<std::size_t>(m)] && d.materials[m].texture) {
      notes_to(d.materials[m].texture->notes_at);
      auto map = load_base_colour_texture(doc, *d.materials[m].texture, scene.import_notes);
      // A scene's override that gives an albedo map replaces the file's texture.
      auto& albedo_map = scene.materials[static_cast<std::size_t>(p.material.index)].albedo_map;
      if (!albedo_map) albedo_map = std::move(map);
    }
    if (m >= 0) loaded[static_cast<std::size_t>(m)] = true;
    notes_to(p.notes_at);
    SceneObject obj;
    obj.mesh_path = doc.path;
    obj.material = p.material.index;
    obj.mesh = load_primitive(doc, p, scene.materials[static_cast<std::size_t>(p.material.index)],
                              vertices, scene.import_notes);
    scene.objects.push_back(std::move(obj));
  }
  notes_to(d.notes.size());
  scene.lights.insert(scene.lights.end(), d.lights.begin(), d.lights.end());
  scene.warnings.insert(scene.warnings.end(), d.warnings.begin(), d.warnings.end());
}

// A file the JSON scene imports, read once however many objects take it: its materials are
// mapped once (two objects of one file share them; appended twice they would be two materials
// of one name, listed twice by `info` and refused by gx's C names), and a note it gives once.
struct ImportedFile {
  std::shared_ptr<const Document> doc;
  // As Importer::material_of, kept between its objects, per set of overrides (overrides_json):
  // a material found here brings the UVs it was mapped with (MappedMaterial).
  std::map<std::string, std::map<int, MappedMaterial>> material_of;
  std::set<std::string> notes;
};

// Every override names a material the file has ("*" always does).
void check_override_selectors(const ObjectDescription& object, const Document& doc,
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

void import_object(const ObjectDescription& object, ImportedFile& file,
                   const std::string& scene_file, Scene& scene) {
  const Document& doc = *file.doc;
  check_override_selectors(object, doc, scene_file);
  GltfDescription d;
  d.doc = file.doc, d.first_material = scene.materials.size();
  Importer im{doc, d, file.material_of[object.overrides_json], scene.objects.size()};
  im.overrides = &object.overrides;
  im.import_lights = false;
  im.material_override = object.material;
  if (object.node.empty()) {
    int scene_index = 0;
    for (int root : scene_roots(doc, scene_index)) im.visit(root, object.transform.matrix(), 0);
  } else {
    int found = -1;
    for (std::size_t n = 0; n < doc.model.nodes.size() && found < 0; ++n) {
      if (doc.model.nodes[n].name == object.node) found = static_cast<int>(n);
    }
    if (found < 0)
      throw InputError(scene_file, object.key + ".node",
                       "no node named \"" + object.node + "\" in " + object.path.string());
    im.visit(found, object.transform.matrix() * ancestors_matrix(doc, found), 0);
  }
  const std::string warning = skip_warning(doc, im);
  if (!warning.empty() && file.notes.insert(warning).second) d.warnings.push_back(warning);
  if (d.primitives.empty())
    throw InputError(
        scene_file, object.key,
        "no mesh under " +
            (object.node.empty() ? std::string("the scene") : "node \"" + object.node + "\"") +
            " of " + object.path.string());
  file.material_of[object.overrides_json] = im.material_of;
  const std::size_t first_note = scene.import_notes.size();
  load_description(d, scene);
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

void import_objects(const std::vector<ObjectDescription>& objects, const std::string& scene_file,
                    Scene& scene) {
  std::map<fs::path, ImportedFile> files;
  for (const ObjectDescription& object : objects) {
    if (object.source != ObjectDescription::Source::Gltf) continue;
    auto [it, first] = files.try_emplace(object.path.lexically_normal());
    if (first) {
      it->second.doc = std::make_shared<const Document>(read_document(object.path));
      for (const std::string& w : it->second.doc->warnings) {
        if (it->second.notes.insert(w).second) scene.import_notes.push_back(w);
      }
    }
    import_object(object, it->second, scene_file, scene);
  }
}

GltfDescription describe_gltf_scene(const fs::path& path) {
  GltfDescription d;
  d.doc = std::make_shared<const Document>(read_document(path));
  const Document& doc = *d.doc;
  d.notes = doc.warnings;
  Importer im{doc, d, {}, 0};
  int scene_index = 0;
  for (int root : scene_roots(doc, scene_index)) im.visit(root, glm::dmat4(1.0), 0);
  for (std::size_t s = 0; s < doc.model.scenes.size(); ++s) {
    if (static_cast<int>(s) != scene_index)
      d.notes.push_back("ignored /scenes/" + std::to_string(s) + ": not the scene to render");
  }
  const std::string warning = skip_warning(doc, im);
  if (d.primitives.empty())
    doc.fail("/scenes/" + std::to_string(scene_index), "the scene has no mesh to render");
  if (!warning.empty()) d.warnings.push_back(warning);
  return d;
}

Scene load_gltf_scene(GltfDescription d, const std::string& camera) {
  const Document& doc = *d.doc;
  Scene scene;
  scene.file = doc.path;
  scene.width = kDefaultWidth;
  scene.height = kDefaultHeight;
  load_description(d, scene);
  if (!camera.empty()) {
    camera_from(doc, chosen_camera(doc, d.cameras, camera), scene);
  } else if (!d.cameras.empty()) {
    camera_from(doc, d.cameras.front(), scene);
  } else {
    framing_camera(scene);
  }
  if (scene.lights.empty())
    scene.import_notes.push_back(
        "no KHR_lights_punctual light in the scene (`info`'s lights line says what lights it)");

  // Textures, images and samplers are read through a base colour texture (its own notes say
  // which); without one they are listed as ignored ("asset" again instead: mapped already).
  const bool sampled = std::any_of(scene.materials.begin(), scene.materials.end(),
                                   [](const Material& m) { return m.albedo_map != nullptr; });
  note_unmapped_keys(
      doc.json, "",
      {"asset", "scene", "scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers",
       sampled ? "textures" : "asset", sampled ? "images" : "asset", sampled ? "samplers" : "asset",
       "materials", "cameras", "extensionsUsed", "extensionsRequired", "KHR_lights_punctual"},
      "not used by the term", scene.import_notes);
  return scene;
}

}  // namespace lt::gltf
