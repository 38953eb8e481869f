// The scene of scene-format.md, validated and loaded (load/load_scene.h: its meshes in world
// space, its maps read): what every path draws. A scene names only what it uses, and every stage
// a path builds is derived from it (see SceneNeeds), so nothing is built for a feature it lacks.
// Plain data: nothing here reads a file.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/texture_map.h"
#include "scene/triangle_mesh.h"

namespace lt {

struct Camera {
  enum class Projection { Perspective, Orthographic };
  glm::dvec3 eye{0, 0, 4}, target{0, 0, 0}, up{0, 1, 0};
  Projection projection = Projection::Perspective;
  double fov_y_deg = 40;  // perspective
  double height = 2;      // orthographic: visible height in scene units
  double near = 0.1, far = 100;

  glm::dvec3 forward() const { return glm::normalize(target - eye); }
  // World to eye rotation (looking down -z, `up` up): the one view every path shares, with the
  // eye at the origin (camera-relative rendering).
  glm::dmat4 view_from_origin() const;
};

// Texture: a thickness map sampled at the mesh's UVs (load/thickness_map.h).
enum class ThicknessSource { Vertex, Constant, Texture };

struct Translucency {
  double power = 1;       // p >= 0
  double distortion = 0;  // d, any real
  double ambient = 0;     // a >= 0
  ThicknessSource thickness_source = ThicknessSource::Constant;
  glm::dvec3 thickness{1, 1, 1};  // the constant (Constant), unused for Vertex and Texture
  glm::dvec3 tint{1, 1, 1};
  bool normalize_distorted_light = false;
  // Shared, not copied: scenes are copied per path (camera_relative_lights), maps are large.
  std::shared_ptr<const TextureMap> thickness_map;  // Texture
  std::shared_ptr<const TextureMap> ramp;           // set: the ramp's value at t replaces t^power
};

struct Material {
  std::string name;
  glm::dvec3 albedo{1, 1, 1};
  // Set: the diffuse albedo is `albedo` times this map at the mesh's UVs (linear rgb, decoded
  // from sRGB: load/albedo_map.h), the seed's cDiffuseAlbedo read from a texture.
  std::shared_ptr<const TextureMap> albedo_map;
  std::optional<Translucency> translucency;  // absent: plain diffuse, no translucency stage
};

// The material reads the mesh's UVs: it samples a thickness map or an albedo map.
bool samples_uvs(const Material& material);

struct Light {
  enum class Type { Directional, Point };
  Type type = Type::Directional;
  glm::dvec3 direction{0, 0, 1};  // directional: where the light travels (L = -direction)
  glm::dvec3 position{0, 0, 0};   // point
  glm::dvec3 color{1, 1, 1};      // already multiplied by intensity
  double translucency_scale = 1;  // s >= 0, the seed's per-light control
  double kc = 1, kl = 0, kq = 0;  // point-light attenuation (GL/GX k0 k1 k2)
};

struct Transform {
  glm::dvec3 translate{0, 0, 0};
  glm::dvec3 rotate_deg{0, 0, 0};  // applied X, then Y, then Z
  glm::dvec3 scale{1, 1, 1};       // a number in the file means uniform scale

  glm::dmat4 matrix() const;
};

struct SceneObject {
  std::filesystem::path mesh_path;
  int material = 0;  // index into Scene::materials
  Transform transform;
  TriangleMesh mesh;  // world space (transform applied in double, normals renormalised)
};

// The optional "regress" block (docs/regress.md): `ltrender regress`'s thresholds
// for this scene, over the path's default; an unset field keeps the default. The names under
// "paths" are checked by regress, which knows the paths (the scene does not).
struct ToleranceOverride {
  std::optional<double> fail_lsb, fail_percent, hard_fail_lsb;
  std::optional<double> warn_lsb, warn_percent, hard_warn_lsb;  // the warn tier (idiff's -warn)
  std::optional<double> edge_shift_percent;  // pixels that may be edge shifts (compare.h)
  std::optional<std::string> region;  // "covered" or "image"
};
struct RegressBlock {
  ToleranceOverride every_path;
  std::map<std::string, ToleranceOverride> per_path;
};

// What a scene file states and loading keeps unchanged: both SceneDescription (the file parsed,
// scene_description.h) and Scene hold it.
struct SceneSettings {
  std::filesystem::path file;
  int width = 640, height = 480;
  glm::dvec3 background{0, 0, 0};
  Camera camera;
  glm::dvec3 ambient_light{0, 0, 0};
  std::vector<Light> lights;
  RegressBlock regress;
};

struct Scene : SceneSettings {
  std::vector<Material> materials;
  std::vector<SceneObject> objects;
  // A glTF scene's import: one line per property mapped, defaulted or ignored (`ltrender info`).
  std::vector<std::string> import_notes;
  // What the user should know although the scene loads (a skipped primitive, the default
  // lights), one line each: load_scene prints them as `ltrender: warning: ...`, `info` lists them.
  std::vector<std::string> warnings;
  // What load_scene added when the scene had no light (scene/default_lights.h); empty: none.
  std::string default_lights;
};

// What a scene uses, derived once, shared by every path and by `ltrender info`.
struct SceneNeeds {
  int directional_lights = 0;
  int point_lights = 0;
  bool any_translucency = false;
  bool any_vertex_thickness = false;
  bool any_thickness_map = false;  // a material samples a thickness map (UVs are uploaded)
  bool any_albedo_map = false;     // a material samples an albedo map (UVs are uploaded)
  bool any_ramp = false;           // a material's lobe is an artist's ramp
  bool any_normalized_h = false;
  bool ambient_light = false;  // scene ambient_light non-zero
};
SceneNeeds scene_needs(const Scene& scene);

}  // namespace lt
