// The reference's vector lanes (paths/reference/reference_shading_lanes.h) against model::shade,
// the scalar definition of model.md: every pixel of a run equal to model::shade's result narrowed
// to float, bit for bit, on every Highway target this machine runs, for random G-buffer values
// (the hard cases among them: zero and tiny normals, a point light at the pixel, t = 0 and 1)
// under lights and materials of every kind the lanes branch on. Maps and ramps, sampled a lane
// at a time by model's own functions, are held by scripts/cpu_path_images.sh's scenes.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "model/texture_sampling.h"
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
  Translucency whole = constant;
  whole.power = 6;  // a whole power: model::lobe_power's own x^p
  s.materials = {Material{"constant", {0.9, 0.8, 0.7}, nullptr, constant},
                 Material{"whole_power", {0.7, 0.9, 0.8}, nullptr, whole},
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

// A map's sample in lanes (bilinear_lanes-inl.h) against model::sample_bilinear, bit for bit on
// every target: textures of odd sizes (one texel, one row, one column) under every pair of wrap
// modes, at coordinates inside and outside [0, 1] and far outside (up to the 1e15 texels where
// the wrap stops: there the quotient of the modulo is rounded), on texel centres and edges, and
// NaN, Inf and beyond 1e15 texels.
TEST(BilinearLanes, IsModelSampleBilinearToTheBitOnEveryTarget) {
  std::mt19937_64 rng(39);
  std::uniform_real_distribution<double> texel_value(-1, 2), inside(0, 1), outside(-3, 4);
  const model::Wrap wraps[] = {model::Wrap::ClampToEdge, model::Wrap::Repeat,
                               model::Wrap::MirroredRepeat};
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  size_t compared = 0;
  for (auto [w, h] : {std::pair{1, 1}, {7, 1}, {1, 5}, {13, 9}, {64, 32}}) {
    model::Texture tex;
    tex.width = w;
    tex.height = h;
    for (int i = 0; i < w * h * 3; ++i) tex.texels.push_back(static_cast<float>(texel_value(rng)));
    std::vector<double> u, v;
    for (int i = 0; i < 3000; ++i) {
      const bool out = i % 3 == 0;
      u.push_back(out ? outside(rng) : inside(rng));
      v.push_back(out ? outside(rng) : inside(rng));
    }
    for (int i = 0; i <= 2 * w; ++i)
      u.push_back(i / (2.0 * w)), v.push_back(0.5);  // centres, edges
    for (double special :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity(), 1e16, -1e16, 1e14, -0.0})
      u.push_back(special), v.push_back(inside(rng)), u.push_back(inside(rng)),
          v.push_back(special);
    const size_t n = u.size();
    std::vector<double> got(3 * n);
    for (model::Wrap ws : wraps) {
      for (model::Wrap wt : wraps) {
        tex.wrap_s = ws;
        tex.wrap_t = wt;
        for (std::int64_t t : targets) {
          hwy::SetSupportedTargetsForTest(t);
          reference::sample_bilinear(tex, u.data(), v.data(), got.data(), n);
          size_t bad = 0;
          for (size_t i = 0; i < n; ++i) {
            const glm::dvec3 want = model::sample_bilinear(tex, {u[i], v[i]});
            for (int c = 0; c < 3; ++c) {
              if (std::bit_cast<std::uint64_t>(got[c * n + i]) !=
                      std::bit_cast<std::uint64_t>(want[c]) &&
                  ++bad <= 3)
                ADD_FAILURE() << hwy::TargetName(t) << " " << w << "x" << h << " "
                              << model::wrap_name(ws) << "/" << model::wrap_name(wt) << " at ("
                              << u[i] << ", " << v[i] << ") channel " << c << ": lanes "
                              << got[c * n + i] << ", model " << want[c];
            }
            ++compared;
          }
          EXPECT_EQ(bad, 0u) << hwy::TargetName(t);
        }
      }
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GT(compared, 100000u);
}

}  // namespace
}  // namespace lt
