// Fixtures of the lobe-ramp tests of the arbfp and combiners paths: ramps built in memory with
// 8-bit texels (what a PNG ramp holds), the ramp that is the power curve, and the orthographic
// backlit sphere (two directional lights, constant thickness: every combiners variant applies)
// carrying one.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "arb_test_util.h"
#include "image/image.h"
#include "load/load_scene.h"
#include "load/thickness_map.h"
#include "map_test_util.h"
#include "metrics/compare.h"
#include "model/texture_sampling.h"
#include "render/session.h"

namespace lt::test {

// A W x 1 ramp whose texel i is texel(i) (an rgb triple), each channel rounded to 1/255 as an
// 8-bit file stores it.
template <typename TexelOf>
std::shared_ptr<const TextureMap> ramp_8bit(int width, TexelOf texel) {
  auto r = std::make_shared<TextureMap>();
  r->file = "ramp.png";
  r->texture.width = width;
  r->texture.height = 1;
  r->grey = true;
  for (int i = 0; i < width; ++i) {
    const glm::dvec3 v = texel(i);
    for (int c = 0; c < 3; ++c) {
      r->texture.texels.push_back(static_cast<float>(std::round(v[c] * 255.0) / 255.0));
    }
    r->grey = r->grey && v.r == v.g && v.g == v.b;
  }
  return r;
}

// t^p at the ramp's texel centres t_i = (i + 0.5) / W: the ramp is the power curve, sampled
// where the reference's ramp lookup returns texel i exactly (model::sample_ramp), in 8 bits.
inline std::shared_ptr<const TextureMap> power_ramp(int width, double p) {
  return ramp_8bit(width, [&](int i) { return glm::dvec3(std::pow((i + 0.5) / width, p)); });
}

// A ramp of one colour, whatever t (a pure red ramp lights only the red channel).
inline std::shared_ptr<const TextureMap> flat_ramp(const glm::dvec3& colour) {
  return ramp_8bit(4, [&](int) { return colour; });
}

// scenes/ortho/backlit_sphere_ortho.json (p = 8, two directional lights, constant thickness),
// its material's lobe the ramp when one is given, and its translucency ambient `lt_ambient`.
inline Scene ortho_sphere(std::shared_ptr<const TextureMap> ramp, double lt_ambient = 0.05) {
  Scene s = load_test_scene("scenes/ortho/backlit_sphere_ortho.json");
  Translucency& tr = *s.materials.front().translucency;
  tr.ramp = std::move(ramp);
  tr.ambient = lt_ambient;
  return s;
}

// The largest weight a lobe value carries to the output, per channel and summed over the
// (directional) lights: albedo * color * s * T. A lobe error e becomes at most e times this.
inline glm::dvec3 lobe_weight(const Scene& s) {
  const Material& m = s.materials.front();
  const Translucency& tr = *m.translucency;
  glm::dvec3 w(0);
  for (const Light& l : s.lights) w += m.albedo * l.color * l.translucency_scale;
  return w * tr.thickness * tr.tint;
}

// The largest difference of channel c between two images of one size, in LSB of 8 bits.
inline double channel_max_lsb(const Image& a, const Image& b, int c) {
  double worst = 0;
  for (size_t i = 0; i < a.pixel_count(); ++i) {
    worst = std::max(worst, std::fabs(static_cast<double>(a.rgba[i * 4 + c]) - b.rgba[i * 4 + c]));
  }
  return worst * 255;
}

// Two renders of one scene whose ramps are pure red and black, the translucency ambient 0: the
// term is the ramp times the rest, so only red may differ (by more than `min_red_lsb`: the lobe
// shows), and green and blue are the same bits.
inline void expect_only_red_differs(const Image& red, const Image& black, double min_red_lsb,
                                    const std::string& what) {
  EXPECT_GT(channel_max_lsb(red, black, 0), min_red_lsb) << what << ": the red lobe shows";
  EXPECT_EQ(channel_max_lsb(red, black, 1), 0) << what << ": no green translucency";
  EXPECT_EQ(channel_max_lsb(red, black, 2), 0) << what << ": no blue translucency";
}

// The same on the orthographic sphere through `path` `variant`, 96 x 96 (its lobe reaches far
// over 100 LSB of red).
inline void expect_red_ramp_lights_only_red(const std::string& path, const std::string& variant) {
  const Scene red = ortho_sphere(flat_ramp({1, 0, 0}), 0);
  const Scene black = ortho_sphere(flat_ramp({0, 0, 0}), 0);
  expect_only_red_differs(render_scene(red, path, variant, 96, 96),
                          render_scene(black, path, variant, 96, 96), 100, path + " " + variant);
}

// The thickness-map quad seen head-on (map_test_util.h: orthographic, two directional lights,
// here constant thickness 1) with an 8-texel rgb ramp with a steep last step, written into `dir`.
// t is the same everywhere on the flat quad: 0.876 for the light behind it (between the last two
// texel centres, 0.51 of the way), 0 for the one in front. A lookup at the power LUT's
// texel-centre remap instead of u = t would read 0.38 texels lower: 0.38 x the red step 0.25 x
// the weight 1.2 = 29 LSB (no channel saturates).
inline Scene coarse_ramp_quad(const TempDir& dir) {
  write_uv_quad(dir.path());
  std::vector<float> ramp;
  for (int i = 0; i < 8; ++i) {
    for (double c : {i < 7 ? i / 40.0 : 0.4, i / 20.0, 0.3 - i / 40.0}) {
      ramp.push_back(static_cast<float>(std::round(c * 255) / 255));
    }
  }
  write_test_image(dir / "ramp.png", 8, 1, 3, ramp);
  write_file(dir / "s.json", map_scene("1", "uv_quad.gltf", "ramp.png"));
  return load_scene(dir / "s.json");
}
// The lobe's weight on it: albedo 0.8 x (intensity 1.5 + 0.3) x s 1 x T 1.
inline constexpr double kCoarseQuadLobeWeight = 0.8 * (1.5 + 0.3);

// `path` `variant` renders the coarse ramp quad (`scene`) over every pixel, within `bound` LSB of
// the `reference` render at the most (and prints what it measured).
inline void expect_coarse_quad_within(const Scene& scene, const Image& reference,
                                      const std::string& path, const std::string& variant,
                                      double bound) {
  const Comparison c = compare_images(render_scene(scene, path, variant), reference,
                                      TestEncoding::kUnorm8, TestEncoding::kFloat, Coverage::kBoth);
  std::printf("%s %s, 8-texel ramp on the quad: %.3f max / %.3f mean LSB\n", path.c_str(),
              variant.c_str(), c.covered.max_lsb, c.covered.mean_lsb);
  EXPECT_EQ(c.covered.pixels, reference.pixel_count()) << variant;
  EXPECT_LE(c.covered.max_lsb, bound) << path << " " << variant;
}

}  // namespace lt::test
