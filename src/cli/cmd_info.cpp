#include <iostream>

#include "cli/commands.h"
#include "cli/lights_option.h"
#include "load/load_scene.h"
#include "model/texture_sampling.h"
#include "render/session.h"

namespace lt::cli {

namespace {

std::string thickness_description(const Translucency& t) {
  switch (t.thickness_source) {
    case ThicknessSource::Vertex:
      return "vertex";
    case ThicknessSource::Constant:
      return "constant";
    case ThicknessSource::Texture: {
      const TextureMap& m = *t.thickness_map;
      return "map " + m.file.string() + " (" + m.channels + ", " + std::to_string(m.texture.width) +
             "x" + std::to_string(m.texture.height) + ", " + std::to_string(m.source_bits) +
             "-bit " + (m.source_float ? "float" : "linear") + (m.grey ? ", grey" : "") + ")";
    }
  }
  return "?";
}
// "albedo map wood.png (64x64, 8-bit sRGB decoded, REPEAT x REPEAT) x albedo [1, 1, 1]"
std::string albedo_description(const Material& m) {
  if (!m.albedo_map) return "";
  const TextureMap& a = *m.albedo_map;
  const model::Texture& t = a.texture;
  return ", albedo map " + a.file.string() + " (" + std::to_string(t.width) + "x" +
         std::to_string(t.height) + ", " + std::to_string(a.source_bits) + "-bit " +
         (a.srgb_decoded ? "sRGB decoded" : "float linear") + ", " + model::wrap_name(t.wrap_s) +
         " x " + model::wrap_name(t.wrap_t) + ") times the albedo";
}
const char* yes_no(bool b) {
  return b ? "yes" : "no";
}
}  // namespace

Action add_info(CLI::App& app) {
  auto scene_path = std::make_shared<std::string>();
  auto show_source = std::make_shared<bool>(false);
  auto* sub = app.add_subcommand("info", "What a scene needs and what each path builds for it");
  sub->add_option("SCENE", *scene_path, "Scene file (JSON, .gltf or .glb)")->required();
  sub->add_flag("--source", *show_source, "Also print every generated program");
  auto scene_options = std::make_shared<SceneOptions>();
  add_lights_option(sub, *scene_options);
  auto profile = std::make_shared<std::string>();
  sub->add_option("--profile", *profile,
                  "arbfp: the pass plan for a profile (ps_2_0 ...): which lights each pass draws");
  return [scene_path, show_source, profile, scene_options]() -> int {
    const Scene scene = load_scene(*scene_path, *scene_options);
    const SceneNeeds n = scene_needs(scene);
    std::ostream& o = std::cout;
    size_t tris = 0, verts = 0;
    for (const SceneObject& obj : scene.objects) {
      tris += obj.mesh.triangles.size();
      verts += obj.mesh.positions.size();
    }
    o << "scene " << *scene_path << ": " << scene.width << "x" << scene.height << ", "
      << (scene.camera.projection == Camera::Projection::Perspective ? "perspective"
                                                                     : "orthographic")
      << " camera, " << scene.objects.size() << " objects (" << verts << " vertices, " << tris
      << " triangles)\n";
    o << "needs: " << n.directional_lights << " directional + " << n.point_lights
      << " point lights (attenuation " << yes_no(n.point_lights > 0) << "), translucency "
      << yes_no(n.any_translucency) << ", vertex thickness " << yes_no(n.any_vertex_thickness)
      << ", normalised H " << yes_no(n.any_normalized_h) << ", ambient light "
      << yes_no(n.ambient_light) << ", albedo map " << yes_no(n.any_albedo_map) << "\n";
    o << "lights: "
      << (scene.default_lights.empty()
              ? std::to_string(scene.lights.size()) + " from the scene"
              : std::to_string(scene.lights.size()) + " from " + scene.default_lights +
                    " (the scene has none; --lights none: unlit)")
      << "\n";
    // A glTF import: what each property of the file became, and what was left out.
    if (!scene.import_notes.empty())
      o << "glTF import (" << scene.import_notes.size() << " notes):\n";
    for (const std::string& note : scene.import_notes) o << "  " << note << "\n";
    for (const Material& m : scene.materials) {
      o << "  material " << m.name << ": ";
      if (!m.translucency) {
        o << "diffuse only (no translucency stage)" << albedo_description(m) << "\n";
        continue;
      }
      const Translucency& t = *m.translucency;
      o << "power " << t.power << ", distortion " << t.distortion << ", ambient " << t.ambient
        << ", thickness " << thickness_description(t)
        << (t.normalize_distorted_light ? ", normalised H" : "") << albedo_description(m);
      if (t.ramp) {
        o << ", lobe from the ramp " << t.ramp->file.string() << " (" << t.ramp->texture.width
          << " texels" << (t.ramp->grey ? ", grey" : ", rgb")
          << "; replaces t^power on every path, whatever the pow variant; gx lobe=xf-spec "
             "refuses it)";
      }
      o << "\n";
    }
    // Build every path once (1x1 is enough to build programs) and list what it made.
    RenderSession session(scene, 1, 1);
    for (const PathInfo& p : all_paths()) {
      const std::string v = resolve_variant(p, "");
      PathOptions options;
      if (p.takes_profile) options.profile = *profile;
      auto path = session.build(p, v, options);
      o << "path " << p.name << " (" << v << "):\n";
      for (const BuiltStage& s : path->stages()) {
        o << "  [" << s.kind << "] " << s.name << "\n";
        if (*show_source && !s.source.empty()) o << s.source << "\n";
      }
    }
    return 0;
  };
}

}  // namespace lt::cli
