// The reference's vector lanes (paths/reference/reference_shading_lanes.h) against model::shade,
// the scalar definition of model.md: every pixel of a run equal to model::shade's result narrowed
// to float, bit for bit, on every Highway target this machine runs, for random G-buffer values
// (the hard cases among them: zero and tiny normals, a point light at the pixel, t = 0 and 1)
// under lights and materials of every kind the lanes branch on. Maps and ramps, sampled a lane
// at a time by model's own functions, are held by scripts/cpu_path_images.sh's scenes.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <bit>
#include <cstdint>
#include <random>

#include "model/translucency.h"
#include "paths/reference/reference_shading_lanes.h"

namespace lt {
namespace {

Scene lanes_scene(Camera::Projection projection) {
  Scene s;
  s.camera.projection = projection;
  s.camera.eye = {0.3, 0.2, 4};
  s.ambient_light = {0.02, 0.03, 0.01};
  Light sun;
  sun.direction = glm::normalize(glm::dvec3(0.2, -0.4, -1));
  sun.color = {1, 0.9, 0.8};
  sun.translucency_scale = 2;
  Light lamp;
  lamp.type = Light::Type::Point;
  lamp.position = {0.25, -0.5, 0.75};  // also a pixel's position below: distance 0
  lamp.color = {0.5, 0.6, 1.5};
  lamp.kc = 0;  // a light at distance 0 floors the denominator at 1e-6
  lamp.kl = 0.3;
  lamp.kq = 0.7;
  s.lights = {sun, lamp};
  Translucency constant;
  constant.power = 3.5;
  constant.distortion = 0.3;
  constant.ambient = 0.05;
  constant.thickness = {0.7, 0.5, 0.2};
  constant.tint = {1, 0.4, 0.3};
  Translucency normalised = constant;
  normalised.normalize_distorted_light = true;
  normalised.distortion = -1.2;
  normalised.thickness_source = ThicknessSource::Vertex;
  Translucency flat_lobe = constant;
  flat_lobe.power = 0;  // 0^0 := 1
  s.materials = {Material{"constant", {0.9, 0.8, 0.7}, nullptr, constant},
                 Material{"normalised_vertex", {0.5, 1, 0.25}, nullptr, normalised},
                 Material{"flat_lobe", {1, 1, 1}, nullptr, flat_lobe},
                 Material{"diffuse", {0.3, 0.6, 0.9}, nullptr, std::nullopt}};
  return s;
}

// A run of random G-buffer values; a few lanes take the hard cases.
PixelRun random_run(std::mt19937& rng, const Scene& scene) {
  std::uniform_real_distribution<float> u(-1, 1);
  PixelRun run;
  run.count = kPixelRunCapacity;
  for (size_t i = 0; i < run.count; ++i) {
    for (int c = 0; c < 3; ++c) {
      run.position[c][i] = u(rng) - (c == 2 ? 4.0f : 0.0f);  // in front of the eye
      run.normal[c][i] = u(rng);
      run.thickness[c][i] = (u(rng) + 1) / 2;
    }
    run.uv[0][i] = run.uv[1][i] = 0;
  }
  for (int c = 0; c < 3; ++c) {
    run.normal[c][1] = 0;                                                  // no normal
    run.normal[c][2] = 1e-7f;                                              // below kMinNormalLength
    run.position[c][3] = static_cast<float>(scene.lights[1].position[c]);  // at the light
  }
  return run;
}

size_t mismatches(const Scene& scene, size_t material, std::mt19937& rng) {
  size_t bad = 0;
  for (int r = 0; r < 50; ++r) {
    const PixelRun run = random_run(rng, scene);
    ShadedRun out;
    reference::shade_run(scene, scene.materials[material], run, out);
    for (size_t i = 0; i < run.count; ++i) {
      model::SurfacePoint sp;
      sp.P = {run.position[0][i], run.position[1][i], run.position[2][i]};
      sp.N = {run.normal[0][i], run.normal[1][i], run.normal[2][i]};
      sp.V = model::view_vector(scene.camera, sp.P);
      sp.vertex_thickness = {run.thickness[0][i], run.thickness[1][i], run.thickness[2][i]};
      const glm::dvec3 want = model::shade(scene, scene.materials[material], sp);
      for (int c = 0; c < 3; ++c) {
        const float w = static_cast<float>(want[c]);
        if (std::bit_cast<std::uint32_t>(out.rgb[c][i]) != std::bit_cast<std::uint32_t>(w) &&
            bad++ < 5) {
          ADD_FAILURE() << scene.materials[material].name << " lane " << i << " channel " << c
                        << ": " << out.rgb[c][i] << ", model::shade " << w;
        }
      }
    }
  }
  return bad;
}

TEST(ReferenceLanes, EveryTargetIsModelShadeToTheBit) {
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  for (auto projection : {Camera::Projection::Perspective, Camera::Projection::Orthographic}) {
    const Scene scene = lanes_scene(projection);
    for (std::int64_t t : targets) {
      hwy::SetSupportedTargetsForTest(t);
      std::mt19937 rng(39);
      for (size_t m = 0; m < scene.materials.size(); ++m)
        EXPECT_EQ(mismatches(scene, m, rng), 0u) << hwy::TargetName(t) << " " << m;
    }
  }
  hwy::SetSupportedTargetsForTest(0);
}

}  // namespace
}  // namespace lt
