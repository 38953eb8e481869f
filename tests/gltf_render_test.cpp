// glTF scenes through the renderer: the volume quad against a hand-computed colour, and the
// same scene as JSON and as glTF on every path.
#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "load/gltf/gltf_lights.h"
#include "load/gltf/gltf_materials.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "scene/scene.h"

namespace lt {
namespace {

using json = nlohmann::json;

// Backlit quad, orthographic camera: V = (0,0,1), L = (0,0,-1), N = (0,0,1), so the diffuse
// term is 0 and H = L + N d = (0, 0, d - 1), t = 1 - d = 0.5, lobe = 0.5^2 = 0.25;
// trans = (lobe * scale + ambient) * T * tint = (0.25 * 2 + 0.1) * T * tint with
// T = attenuationColor ^ (0.5 / 1) = (sqrt 0.5, 0.5, 1), and the light's colour pi / pi = 1.
TEST(GltfRender, VolumeQuadThroughReferenceIsTheHandComputedColour) {
  test::TempDir dir;
  const Scene scene = load_scene(test::volume_quad().write_glb(dir.path(), "quad"));
  const Image img = render_scene(scene, "reference", "", 64, 48);
  const float* c = img.at(32, 24);
  EXPECT_NEAR(c[0], 0.9 * 0.6 * std::sqrt(0.5) * 1.0, 1e-6);
  EXPECT_NEAR(c[1], 0.8 * 0.6 * 0.5 * 0.8, 1e-6);
  EXPECT_NEAR(c[2], 0.7 * 0.6 * 1.0 * 0.6, 1e-6);
  EXPECT_EQ(c[3], 1.0f);
}

// The volume quad (perspective) as a JSON scene over an OBJ quad, with every number the import
// derives written out exactly (json dumps round-trip doubles).
std::string json_twin(const Scene& g, const fs::path& obj) {
  const Material& m = g.materials.at(0);
  const Translucency& t = *m.translucency;
  auto v3 = [](const glm::dvec3& v) { return json({v.x, v.y, v.z}); };
  json s = {{"image", {{"width", 64}, {"height", 48}}},
            {"camera",
             {{"eye", v3(g.camera.eye)},
              {"target", v3(g.camera.target)},
              {"up", v3(g.camera.up)},
              {"fov_y_deg", g.camera.fov_y_deg},
              {"near", g.camera.near},
              {"far", g.camera.far}}},
            {"materials",
             {{"jade",
               {{"albedo", v3(m.albedo)},
                {"translucency",
                 {{"power", t.power},
                  {"distortion", t.distortion},
                  {"ambient", t.ambient},
                  {"thickness", v3(t.thickness)},
                  {"tint", v3(t.tint)}}}}}}},
            {"objects", {{{"mesh", obj.filename().string()}, {"material", "jade"}}}}};
  for (const Light& l : g.lights) {
    json j = {{"color", v3(l.color)}, {"translucency_scale", l.translucency_scale}};
    if (l.type == Light::Type::Directional) {
      j["type"] = "directional", j["direction"] = v3(l.direction);
    } else {
      j["type"] = "point", j["position"] = v3(l.position);
      j["attenuation"] = {{"constant", l.kc}, {"linear", l.kl}, {"quadratic", l.kq}};
    }
    s["lights"].push_back(j);
  }
  return s.dump(1);
}

TEST(GltfRender, SameSceneAsJsonAndAsGltfRendersIdenticallyOnEveryPath) {
  test::TempDir dir;
  test::QuadParams q;
  q.orthographic = false;
  test::GltfWriter w = test::volume_quad(q);
  // A point light in front (inverse square, no range) lights the diffuse term too.
  w.light({{"type", "point"}, {"intensity", 20}, {"color", {1, 0.9, 0.8}}});
  w.doc["nodes"].back()["translation"] = {0.5, 0.5, 2};
  const Scene gltf_scene = load_scene(w.write_gltf(dir.path(), "quad"));
  test::write_file(dir / "quad.obj", test::quad_obj());
  test::write_file(dir / "quad.json", json_twin(gltf_scene, dir / "quad.obj"));
  const Scene json_scene = load_scene(dir / "quad.json");
  std::size_t compared = 0;
  for (const PathInfo& p : all_paths()) {
    const std::string variant = resolve_variant(p, "");
    if (!p.refusal(gltf_scene, variant).empty()) continue;
    const Image a = render_scene(gltf_scene, p.name, variant, 64, 48);
    const Image b = render_scene(json_scene, p.name, variant, 64, 48);
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
      differing += to_unorm8(a.rgba[i]) != to_unorm8(b.rgba[i]);
    EXPECT_EQ(differing, 0u) << p.name << ": 8-bit values that differ between glTF and JSON";
    EXPECT_EQ(test::non_finite(a), 0u) << p.name;
    EXPECT_GT(test::covered_pixels(a), 0u) << p.name;
    ++compared;
  }
  EXPECT_EQ(compared, all_paths().size()) << "no path refuses this scene";
}

// Every path, every variant, renders a glTF scene (GLB, data URI as well as external buffer):
// no NaN or Inf, something covered.
TEST(GltfRender, EveryPathAndVariantRendersAGltfScene) {
  test::TempDir dir;
  const Scene scene = load_scene(test::volume_quad().write_gltf_data_uri(dir.path(), "quad"));
  for (const PathInfo& p : all_paths()) {
    for (const VariantInfo& v : p.variants) {
      if (!p.refusal(scene, v.name).empty()) continue;
      const Image img = render_scene(scene, p.name, v.name, 32, 24);
      EXPECT_EQ(test::non_finite(img), 0u) << p.name << " " << v.name;
      EXPECT_GT(test::covered_pixels(img), 0u) << p.name << " " << v.name;
    }
  }
}

}  // namespace
}  // namespace lt
