// t=texgen:view=object and lobe=xf-spec:view=object (issue 26, object_view.h): V and L taken
// once per object, at its centre, so the hardware computes t under a perspective camera and point
// lights. The texture matrix must be that V and L's, computed here from the scene's own numbers
// (the sphere's translation, not the planner's bounding box); under an orthographic camera and
// directional lights the per-object V and L are the exact ones, so the images are the exact
// variants'.
#include <gtest/gtest.h>

#include "core/error.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "render/session.h"
#include "scene/scene_parse.h"
#include "test_util.h"

namespace lt {
namespace {

// A sphere moved off the view axis, lit by a point light: V and L differ across it.
Scene off_axis_sphere() {
  const std::string text = R"({
    "image": { "width": 64, "height": 48 },
    "camera": { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40 },
    "materials": { "m": { "albedo": [0.9, 0.9, 0.9],
      "translucency": { "power": 4, "distortion": 0.3, "ambient": 0.1, "thickness": 1 } } },
    "lights": [ { "type": "point", "position": [-1, 0.5, -2], "color": [1, 1, 1],
                  "translucency_scale": 1 } ],
    "objects": [ { "mesh": "../meshes/sphere_s4.ply", "material": "m",
                   "transform": { "translate": [0.8, -0.3, 0.5], "scale": 0.5 } } ]
  })";
  return load_scene(parse_scene(text, "off_axis.json", test::source_dir() / "scenes"));
}

TEST(GxViewObject, TheTextureMatrixIsTheObjectCentresVAndL) {
  const Scene scene = off_axis_sphere();
  const gx::GxVariant v = gx::parse_gx_variant("t=texgen:view=object");
  EXPECT_EQ(gx::refusal(scene, v), "");
  EXPECT_NE(gx::refusal(scene, gx::parse_gx_variant("t=texgen")), "");
  const gx::ScenePlan plan = gx::plan_scene(scene, v);
  ASSERT_EQ(plan.materials.size(), 1u);
  ASSERT_EQ(plan.materials[0].passes.size(), 1u);
  const gx::PassPlan& pass = plan.materials[0].passes[0];
  ASSERT_FALSE(pass.texgens.empty());
  ASSERT_TRUE(pass.texgens[0].matrix_values);
  const auto& m = pass.texgens[0].matrix_values->values;
  // The sphere's centre is its translation; V towards the eye, L towards the light.
  const glm::dvec3 C(0.8, -0.3, 0.5);
  const glm::dvec3 V = glm::normalize(glm::dvec3(0, 0, 4) - C);
  const glm::dvec3 L = glm::normalize(glm::dvec3(-1, 0.5, -2) - C);
  const double d = 0.3, n = 256, scale = (n - 1) / n, offset = 0.5 / n;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[static_cast<size_t>(c)], -d * V[c] * scale, 1e-6) << c;
  EXPECT_NEAR(m[3], -glm::dot(V, L) * scale + offset, 1e-6);
  // Row 1 is unused (a 1-D LUT): zero.
  for (size_t i = 4; i < 8; ++i) EXPECT_EQ(m[i], 0.0f) << i;
}

TEST(GxViewObject, IsTheExactVariantUnderAnOrthographicCamera) {
  const Scene scene = load_scene(test::source_dir() / "scenes/ortho/backlit_sphere_ortho.json");
  for (const char* exact : {"t=texgen", "lobe=xf-spec"}) {
    const std::string per_object = std::string(exact) + ":view=object";
    const Image a = render_scene(scene, "gx", exact, 64, 48);
    const Image b = render_scene(scene, "gx", per_object, 64, 48);
    EXPECT_GT(test::covered_pixels(a), 0u);
    EXPECT_EQ(a.rgba, b.rgba) << per_object;
  }
}

TEST(GxViewObject, RendersUnderAPerspectiveCameraAndAPointLight) {
  const Scene scene = off_axis_sphere();
  const Image exact = render_scene(scene, "gx", "t=vertex");
  for (const char* v : {"t=texgen:view=object", "lobe=xf-spec:view=object"}) {
    const Image img = render_scene(scene, "gx", v);
    EXPECT_EQ(test::non_finite(img), 0u) << v;
    EXPECT_EQ(test::covered_pixels(img), test::covered_pixels(exact)) << v;
  }
}

TEST(GxViewObject, TheGrammarTakesItWhereTheHardwareComputesT) {
  EXPECT_EQ(gx::to_string(gx::parse_gx_variant("t=texgen:view=object")), "t=texgen:view=object");
  EXPECT_EQ(gx::to_string(gx::parse_gx_variant("view=object:lobe=xf-spec")),
            "lobe=xf-spec:view=object");
  EXPECT_EQ(gx::to_string(gx::parse_gx_variant("t=texgen:view=exact")), "t=texgen");
  // t=vertex has the exact V per vertex: a per-object one is refused as input.
  EXPECT_THROW(gx::parse_gx_variant("t=vertex:view=object"), InputError);
  EXPECT_THROW(gx::parse_gx_variant("t=texgen:view=eye"), InputError);
  // A normalised H is not affine in the normal, whatever V and L are.
  Scene s = off_axis_sphere();
  s.materials[0].translucency->normalize_distorted_light = true;
  EXPECT_NE(gx::refusal(s, gx::parse_gx_variant("t=texgen:view=object")), "");
}

}  // namespace
}  // namespace lt
