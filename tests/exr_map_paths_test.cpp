// A float (EXR) thickness map through every path (gl/map_texture.h, gx/thickness_texture.h):
// what each path's texture holds of it, and each path against the reference within a bound
// derived from that quantisation. The map is a smooth grey gradient whose texels fall between
// 8-bit steps, with exactly 0 and 1 among them; its 8-bit twin holds the same texels rounded to
// the nearest 1/255. The scene is map_test_util.h's quad (64 x 64, orthographic, two directional
// lights) in a real OSMesa context. One process per test (GL).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gl/context.h"
#include "gl/map_texture.h"
#include "load/load_scene.h"
#include "map_test_util.h"
#include "metrics/compare.h"
#include "render/session.h"

namespace lt {
namespace {

constexpr int kMapWidth = 16, kMapHeight = 4;

// Texel (x, y), top row first: 0 at the top-left, exactly 1 at the bottom-right, and between
// 8-bit steps elsewhere (x / 15 * (0.7 + 0.1 y) is no multiple of 1/255 but at those two).
std::vector<float> gradient_texels() {
  std::vector<float> texels;
  for (int y = 0; y < kMapHeight; ++y)
    for (int x = 0; x < kMapWidth; ++x)
      texels.push_back(static_cast<float>(x / 15.0 * (0.7 + 0.1 * y)));
  return texels;
}

std::vector<float> rounded_to_8_bits(std::vector<float> texels) {
  for (float& t : texels) t = static_cast<float>(std::round(t * 255.0) / 255.0);
  return texels;
}

// The nearest half (fp16) of a normal v in [2^-14, 1], written out here rather than borrowed from
// the half path: 11 significant bits, so a step of 2^(e - 10) where 2^e <= v < 2^(e + 1).
float nearest_half(float v) {
  if (v == 0.0f) return 0.0f;
  const double step = std::ldexp(1.0, static_cast<int>(std::floor(std::log2(v))) - 10);
  return static_cast<float>(std::nearbyint(v / step) * step);  // ties to even, as the upload
}

// The scene twice: `map.exr` (the float gradient) and `map8.png` (the same texels in 8 bits).
struct ExrScenes {
  test::TempDir dir;
  Scene exr, q8;
};
std::unique_ptr<ExrScenes> write_exr_scenes() {
  auto s = std::make_unique<ExrScenes>();
  test::write_test_image(s->dir / "map.exr", kMapWidth, kMapHeight, 1, gradient_texels());
  test::write_test_image(s->dir / "map8.png", kMapWidth, kMapHeight, 1,
                         rounded_to_8_bits(gradient_texels()));
  test::write_uv_quad(s->dir.path());
  test::write_file(s->dir / "exr.json", test::map_scene(R"({"texture": "map.exr"})"));
  test::write_file(s->dir / "q8.json", test::map_scene(R"({"texture": "map8.png"})"));
  s->exr = load_scene(s->dir / "exr.json");
  s->q8 = load_scene(s->dir / "q8.json");
  return s;
}

// The most a thickness error dT can move the output, in LSB per unit of T: the term is
// albedo * color * att * (lobe s + a) * T summed over the lights, lobe <= 1 and att = 1
// (directional), so 255 * 0.8 * (1.5 (1 + 0.1) + 0.3 (1 + 0.1)) = 404 LSB per unit of T.
double lsb_per_unit_thickness(const Scene& scene) {
  const Material& m = scene.materials[0];
  double sum = 0;
  for (const Light& l : scene.lights)
    sum += l.color.r * (l.translucency_scale + m.translucency->ambient);
  return 255 * m.albedo.r * sum;
}

size_t differing_bytes(const Image& a, const Image& b) {
  EXPECT_EQ(a.rgba.size(), b.rgba.size());
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i)
    n += to_unorm8(a.rgba[i]) != to_unorm8(b.rgba[i]);
  return n;
}

// What the GL paths' textures hold: read back from a real context. Fp16 (glsl, arbfp) holds
// each texel's nearest half, 1 and 0 exactly; Unorm8 (combiners) the nearest 1/255.
TEST(ExrMapPaths, GlTexturesHoldHalfOrTheNearest8BitStep) {
  const auto s = write_exr_scenes();
  const TextureMap& map = *s->exr.materials[0].translucency->thickness_map;
  ASSERT_TRUE(map.source_float);
  const gl::Context ctx(8, 8);
  const std::vector<float> texels = gradient_texels();  // top row first
  for (const gl::MapTexelClass c : {gl::MapTexelClass::Fp16, gl::MapTexelClass::Unorm8}) {
    const gl::MapTexture texture(ctx, map, c);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    GLint internal = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    EXPECT_EQ(internal, c == gl::MapTexelClass::Fp16 ? GL_RGB16F_ARB : GL_RGB8);
    std::vector<float> back(kMapWidth * kMapHeight * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_FLOAT, back.data());
    int between_steps = 0;
    for (int y = 0; y < kMapHeight; ++y) {
      for (int x = 0; x < kMapWidth; ++x) {
        // Texture row 0 is the image's bottom row (v = 0).
        const float v = texels[static_cast<size_t>((kMapHeight - 1 - y) * kMapWidth + x)];
        const float expected = c == gl::MapTexelClass::Fp16
                                   ? nearest_half(v)
                                   : static_cast<float>(std::round(v * 255.0) / 255.0);
        EXPECT_FLOAT_EQ(back[static_cast<size_t>(y * kMapWidth + x) * 3], expected)
            << texture.description() << " texel " << x << ", " << y;
        between_steps += std::abs(v * 255 - std::round(v * 255)) > 0.01;
      }
    }
    EXPECT_GT(between_steps, kMapWidth * kMapHeight / 2);  // the gradient is not 8-bit data
    // The image's bottom row is texture row 0: 0 at its left, exactly 1 at its right, in both.
    EXPECT_EQ(back[0], 0.0f);
    EXPECT_EQ(back[(kMapWidth - 1) * 3], 1.0f);
  }
}

// The reference uses the float texels: its EXR image is the model's ground truth within float
// noise, and a different, farther image when the map is rounded to 8 bits first (the rounding,
// up to 0.5/255 of T, times the term: measured ~0.3 LSB here).
TEST(ExrMapPaths, ReferenceUsesTheFloatTexels) {
  const auto s = write_exr_scenes();
  const Image truth = test::quad_ground_truth(s->exr);
  const Comparison from_exr =
      compare_images(render_scene(s->exr, "reference", ""), truth, TestEncoding::kFloat);
  const Comparison from_q8 =
      compare_images(render_scene(s->q8, "reference", ""), truth, TestEncoding::kFloat);
  std::printf("reference vs ground truth: EXR map max %.4f, 8-bit map max %.4f LSB\n",
              from_exr.covered.max_lsb, from_q8.covered.max_lsb);
  EXPECT_EQ(from_exr.covered.pixels, truth.pixel_count());
  EXPECT_LT(from_exr.covered.max_lsb, 0.02);
  EXPECT_GT(from_q8.covered.max_lsb, 0.1);
  EXPECT_LE(from_q8.covered.max_lsb, 0.5 / 255 * lsb_per_unit_thickness(s->exr) + 0.02);
}

// Each path against the reference with the EXR map: error(EXR) <= the path's own error with a
// map it holds exactly + what its upload moves T by, times lsb_per_unit_thickness (404 LSB per
// unit of T):
//  - 8-bit uploads (combiners GL_RGB8, gx I8): 0.5/255 of T, 0.79 LSB. The EXR image is the
//    8-bit twin's bit for bit (both upload the same bytes), so by the triangle inequality through
//    the twin the own error is the twin's, checked against its own bound here: combiners its
//    8-bit LUT and stage products, 3 (measured 1.79); gx its truncations, 5 (as
//    gx_map_path_test's RGBA8 quad; measured 4.02).
//  - half: its texels are rounded to half whatever the file (2^-12 of T for T <= 1, 0.099 LSB),
//    and its sampler and arithmetic are the same on the twin: own bound 1.5 (measured 0.82).
//  - fp16 uploads (glsl, arbfp GL_RGB16F): 2^-12 of T, 0.099 LSB. Their own error is float
//    shading and llvmpipe's float filtering of a float texture, rounded once to 8 bits: 0.5 LSB
//    plus float noise, 0.52. Not the twin's: an 8-bit texture is filtered with llvmpipe's 8-bit
//    weights, which costs more (measured 1.38 here, printed) than the fp16 rounding does.
// Every image but the 8-bit paths' differs from the twin's: the float data is used.
TEST(ExrMapPaths, EveryPathIsWithinItsUploadsQuantisationOfTheReference) {
  struct Case {
    const char* path;
    double own_bound;
    bool eight_bit;      // the upload rounds to 1/255 (else to half)
    bool twin_is_exact;  // own_bound holds for the 8-bit twin too (the same sampler)
  };
  const auto s = write_exr_scenes();
  const Image ref_exr = render_scene(s->exr, "reference", "");
  const Image ref_q8 = render_scene(s->q8, "reference", "");
  const double gain = lsb_per_unit_thickness(s->exr);
  for (const Case& k : {Case{"glsl", 0.52, false, false}, Case{"arbfp", 0.52, false, false},
                        Case{"half", 1.5, false, true}, Case{"combiners", 3.0, true, true},
                        Case{"gx", 5.0, true, true}}) {
    const Image exr = render_scene(s->exr, k.path, "");
    const Image q8 = render_scene(s->q8, k.path, "");
    const Comparison twin = compare_images(q8, ref_q8, TestEncoding::kUnorm8);
    const Comparison got = compare_images(exr, ref_exr, TestEncoding::kUnorm8);
    const double upload = k.eight_bit ? 0.5 / 255 : std::ldexp(1.0, -12);
    const double bound = k.own_bound + upload * gain;
    std::printf("%-9s 8-bit twin max %.3f mean %.3f; EXR max %.3f mean %.3f, bound %.3f\n", k.path,
                twin.covered.max_lsb, twin.covered.mean_lsb, got.covered.max_lsb,
                got.covered.mean_lsb, bound);
    EXPECT_EQ(got.covered.pixels, exr.pixel_count()) << k.path;
    if (k.twin_is_exact) EXPECT_LE(twin.covered.max_lsb, k.own_bound) << k.path;
    EXPECT_LE(got.covered.max_lsb, bound) << k.path;
    if (k.eight_bit)
      EXPECT_EQ(differing_bytes(exr, q8), 0u) << k.path << ": the upload is not the 8-bit map's";
    else
      EXPECT_GT(differing_bytes(exr, q8), 0u) << k.path << ": the float texels are not used";
  }
}

}  // namespace
}  // namespace lt
