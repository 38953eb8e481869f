// Albedo maps as scene inputs (load/albedo_map.h, load/gltf/gltf_textures.h) and in the model:
// what a file becomes (sRGB decoded, EXR linear), the wrap modes' taps, the JSON key's errors,
// glTF's baseColorTexture with its sampler, texCoord and KHR_texture_transform, and the model's
// product. No GL: the paths are tests/albedo_paths_test.cpp.
#include "load/albedo_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>

#include "core/error.h"
#include "image/srgb.h"
#include "load/load_scene.h"
#include "map_test_util.h"
#include "model/texture_sampling.h"
#include "model/translucency.h"

namespace lt {
namespace {

using json = nlohmann::json;

// IEC 61966-2-1's decoding, written out here rather than borrowed from image/srgb.h.
double iec_decode(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST(Srgb, DecodesByTheIecFormula) {
  EXPECT_EQ(srgb_to_linear(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgb_to_linear(1.0), 1.0);
  // The linear segment below 0.04045 and the power segment above meet there (continuity).
  EXPECT_NEAR(srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-12);
  EXPECT_NEAR(srgb_to_linear(0.04046), 0.04045 / 12.92, 1e-6);
  // Mid grey: 0.5 encoded is 0.2140 linear (the figure every sRGB table gives).
  EXPECT_NEAR(srgb_to_linear(0.5), 0.21404114, 1e-8);
}

// An 8-bit PNG's byte v becomes decode(v / 255) (a picture); an EXR's float stays as it is
// (already linear); a thickness map of the same PNG stays v / 255 (data).
TEST(AlbedoMap, PngIsDecodedFromSrgbExrIsLinear) {
  test::TempDir dir;
  const std::vector<float> values = {0.0f, 20 / 255.0f, 128 / 255.0f, 1.0f};
  test::write_test_image(dir / "a.png", 4, 1, 1, values);
  test::write_test_image(dir / "a.exr", 4, 1, 1, values);
  const auto png = load_albedo_map(dir / "a.png", "s.json", "materials.m.albedo_map");
  const auto exr = load_albedo_map(dir / "a.exr", "s.json", "materials.m.albedo_map");
  const auto data = load_thickness_map(dir / "a.png", "rgb", "s.json", "key");
  EXPECT_TRUE(png->srgb_decoded);
  EXPECT_FALSE(png->exact_in_8_bits());
  EXPECT_FALSE(exr->srgb_decoded);
  for (int x = 0; x < 4; ++x) {
    const double v = std::round(values[static_cast<size_t>(x)] * 255) / 255;
    EXPECT_FLOAT_EQ(png->texture.texel(x, 0).r, static_cast<float>(iec_decode(v))) << x;
    EXPECT_FLOAT_EQ(exr->texture.texel(x, 0).g, values[static_cast<size_t>(x)]) << x;
    EXPECT_FLOAT_EQ(data->texture.texel(x, 0).b, static_cast<float>(v)) << x;
  }
}

// REPEAT and MIRRORED_REPEAT against hand-computed taps on a 4 x 1 row of texels 0, 1, 2, 3:
// x = u * 4 - 0.5 in texel space.
TEST(AlbedoMap, WrapModesTakeTheTapsGlTakes) {
  model::Texture t;
  t.width = 4;
  t.height = 1;
  for (float v : {0.0f, 1.0f, 2.0f, 3.0f}) t.texels.insert(t.texels.end(), {v, v, v});
  auto at = [&](double u, model::Wrap w) {
    t.wrap_s = w;
    return model::sample_bilinear(t, {u, 0.5}).r;
  };
  using W = model::Wrap;
  // u = 1: x = 3.5, between texel 3 and texel 4, which is 3 (clamp), 0 (repeat), 3 (mirror).
  EXPECT_DOUBLE_EQ(at(1.0, W::ClampToEdge), 3.0);
  EXPECT_DOUBLE_EQ(at(1.0, W::Repeat), 1.5);
  EXPECT_DOUBLE_EQ(at(1.0, W::MirroredRepeat), 3.0);
  // u = -0.125: x = -1, texel -1 exactly: 0 (clamp), 3 (repeat), 0 (mirror).
  EXPECT_DOUBLE_EQ(at(-0.125, W::ClampToEdge), 0.0);
  EXPECT_DOUBLE_EQ(at(-0.125, W::Repeat), 3.0);
  EXPECT_DOUBLE_EQ(at(-0.125, W::MirroredRepeat), 0.0);
  // u = 1.375: x = 5: texel 5 is 1 (repeat), 2 (mirror: 4 -> 3, 5 -> 2).
  EXPECT_DOUBLE_EQ(at(1.375, W::Repeat), 1.0);
  EXPECT_DOUBLE_EQ(at(1.375, W::MirroredRepeat), 2.0);
}

std::string albedo_quad_scene(const std::string& albedo_map,
                              const std::string& mesh = "uv_quad.gltf") {
  return R"({"image": {"width": 16, "height": 16},
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "projection": "orthographic", "height": 2},
  "materials": {"skin": {"albedo": [0.8, 0.6, 0.4], "albedo_map": ")" +
         albedo_map + R"(", "translucency": {"power": 2, "thickness": 0.5}}},
  "lights": [{"type": "directional", "direction": [0.1, 0.2, 1]}],
  "objects": [{"gltf": ")" +
         mesh + R"(", "material": "skin"}]})";
}

TEST(AlbedoMap, SceneKeyLoadsTheMapAndItsErrorsNameTheKey) {
  test::TempDir dir;
  test::write_uv_quad(dir.path());
  test::write_uv_quad(dir.path(), false);
  test::write_test_image(dir / "a.png", 2, 2, 3, std::vector<float>(12, 0.5f));
  test::write_file(dir / "ok.json", albedo_quad_scene("a.png"));
  const Scene s = load_scene(dir / "ok.json");
  ASSERT_TRUE(s.materials[0].albedo_map);
  EXPECT_TRUE(scene_needs(s).any_albedo_map);
  EXPECT_TRUE(samples_uvs(s.materials[0]));

  auto error_of = [&](const std::string& text) {
    test::write_file(dir / "bad.json", text);
    try {
      load_scene(dir / "bad.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string missing = error_of(albedo_quad_scene("nope.png"));
  EXPECT_NE(missing.find("materials.skin.albedo_map: albedo map file not found"), std::string::npos)
      << missing;
  const std::string no_uvs = error_of(albedo_quad_scene("a.png", "quad_without_uvs.gltf"));
  EXPECT_NE(no_uvs.find("samples the albedo map"), std::string::npos) << no_uvs;
  EXPECT_NE(no_uvs.find("has no texture coordinates"), std::string::npos) << no_uvs;
}

// The model: the albedo is `albedo` times the map at the UV, multiplying the whole colour, so a
// constant map of value a gives exactly a times the colour without it.
TEST(AlbedoMap, ModelMultipliesTheWholeColourByTheTexel) {
  test::TempDir dir;
  test::write_uv_quad(dir.path());
  test::write_test_image(dir / "a.png", 2, 2, 3, std::vector<float>(12, 180 / 255.0f));
  test::write_file(dir / "s.json", albedo_quad_scene("a.png"));
  Scene with = load_scene(dir / "s.json");
  with.ambient_light = glm::dvec3(0.1);
  Scene without = with;
  without.materials[0].albedo_map = nullptr;
  const double a = iec_decode(180 / 255.0);
  model::SurfacePoint sp;
  sp.P = {0.2, -0.3, 0};
  sp.N = {0, 0.2, 1};
  sp.V = {0, 0, 1};
  sp.uv = {0.3, 0.8};
  const glm::dvec3 c = model::shade(with, with.materials[0], sp);
  const glm::dvec3 c0 = model::shade(without, without.materials[0], sp);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], a * c0[k], 1e-7 * c0[k]) << k;
}

// A glTF quad whose material samples a 2 x 2 PNG embedded in the GLB's buffer, through a sampler
// and a KHR_texture_transform, reading TEXCOORD_1.
struct TexturedQuad {
  test::GltfWriter w;
  // TEXCOORD_1, (u, v) per vertex, and the transform's offset and scale the material gives it.
  const std::vector<float> uv1_values = {0, 0, 0.5f, 0, 0.5f, 0.5f, 0, 0.5f};
  const glm::dvec2 uv1_offset{0.25, 0.5}, uv1_scale{2, 4};
  TexturedQuad(const std::string& png_bytes) {
    w = test::volume_quad();
    const int uv0 = w.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
    const int uv1 = w.floats(uv1_values, "VEC2", 2);
    w.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv0;
    w.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = uv1;
    while (w.bin.size() % 4) w.bin.push_back('\0');
    const size_t offset = w.bin.size();
    w.bin += png_bytes;
    w.doc["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", png_bytes.size()}});
    w.doc["images"] =
        json::array({{{"bufferView", w.doc["bufferViews"].size() - 1}, {"mimeType", "image/png"}}});
    w.doc["samplers"] = json::array({{{"wrapS", 33648}, {"wrapT", 33071}}});
    w.doc["textures"] = json::array({{{"source", 0}, {"sampler", 0}}});
    w.use_extension("KHR_texture_transform");
    w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {
        {"index", 0},
        {"texCoord", 1},
        {"extensions",
         {{"KHR_texture_transform",
           {{"offset", {uv1_offset.x, uv1_offset.y}}, {"scale", {uv1_scale.x, uv1_scale.y}}}}}}};
  }
  // Vertex v's UV as the importer must give it: TEXCOORD_1 through T * S (no rotation) in glTF's
  // space, then v flipped (1 - v), written out here rather than taken from importer_uv.
  glm::dvec2 expected_uv(std::size_t v) const {
    const double u = uv1_values[2 * v], t = uv1_values[2 * v + 1];
    return {uv1_scale.x * u + uv1_offset.x, 1 - (uv1_scale.y * t + uv1_offset.y)};
  }
};

std::string png_bytes(const fs::path& dir) {
  test::write_test_image(dir / "t.png", 2, 2, 3,
                         {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f});
  std::ifstream in(dir / "t.png", std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(AlbedoMap, GltfBaseColourTextureWithSamplerTexCoordAndTransform) {
  test::TempDir dir;
  const TexturedQuad q(png_bytes(dir.path()));
  const Scene s = load_scene(q.w.write_glb(dir.path(), "q"));
  const Material& m = s.materials[0];
  ASSERT_TRUE(m.albedo_map);
  EXPECT_EQ(m.albedo_map->texture.wrap_s, model::Wrap::MirroredRepeat);
  EXPECT_EQ(m.albedo_map->texture.wrap_t, model::Wrap::ClampToEdge);
  // baseColorFactor (0.9, 0.8, 0.7) stays the albedo the map multiplies.
  EXPECT_DOUBLE_EQ(m.albedo.g, 0.8);
  // TEXCOORD_1's (u, v) through T * R * S = (2 u + 0.25, 4 v + 0.5) in glTF's space, then v
  // flipped: vertex 2 (0.5, 0.5) -> (1.25, 2.5) -> (1.25, -1.5).
  const std::vector<glm::dvec2>& uv = s.objects[0].mesh.uvs;
  ASSERT_EQ(uv.size(), 4u);
  EXPECT_DOUBLE_EQ(uv[2].x, 1.25);
  EXPECT_DOUBLE_EQ(uv[2].y, -1.5);
  EXPECT_DOUBLE_EQ(uv[0].x, 0.25);
  EXPECT_DOUBLE_EQ(uv[0].y, 0.5);
  // The image's top row (black, white) is the texture's row 1 (v = 1 at the top); its bottom
  // row starts with red.
  EXPECT_EQ(m.albedo_map->texture.texel(0, 1), glm::dvec3(0));
  EXPECT_EQ(m.albedo_map->texture.texel(1, 1), glm::dvec3(1, 1, 1));
  EXPECT_EQ(m.albedo_map->texture.texel(0, 0), glm::dvec3(1, 0, 0));
  bool noted = false;
  for (const std::string& n : s.import_notes) noted |= n.find("applied") == 0;
  EXPECT_TRUE(noted);
}

// A JSON scene importing the file twice (the second time by its node, moved): the second object
// finds the material the first one mapped, and must read the same TEXCOORD_1 through the same
// transform, as a first import would; not TEXCOORD_0 untransformed, and without TEXCOORD_0 it
// must not be refused for lacking UVs.
TEST(AlbedoMap, EveryObjectOfAGltfFileReadsItsMaterialsTexCoordAndTransform) {
  test::TempDir dir;
  const std::string bytes = png_bytes(dir.path());
  for (const bool with_texcoord_0 : {true, false}) {
    SCOPED_TRACE(with_texcoord_0 ? "with TEXCOORD_0" : "without TEXCOORD_0");
    TexturedQuad q(bytes);
    if (!with_texcoord_0) q.w.doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
    q.w.write_glb(dir.path(), "q");
    const json scene = {
        {"image", {{"width", 32}, {"height", 24}}},
        {"camera", {{"eye", {0, 0, 6}}, {"target", {0, 0, 0}}}},
        {"materials", json::object()},
        {"lights", {{{"type", "directional"}, {"direction", {0, 0, -1}}}}},
        {"objects",
         {{{"gltf", "q.glb"}, {"transform", {{"translate", {-1.5, 0, 0}}}}},
          {{"gltf", "q.glb"}, {"node", "Quad"}, {"transform", {{"translate", {1.5, 0, 0}}}}}}}};
    test::write_file(dir / "twice.json", scene.dump());
    Scene s;
    ASSERT_NO_THROW(s = load_scene(dir / "twice.json"));
    ASSERT_EQ(s.objects.size(), 2u);
    ASSERT_EQ(s.materials.size(), 1u) << "the file's material, mapped once";
    for (std::size_t o = 0; o < 2; ++o) {
      EXPECT_EQ(s.objects[o].material, 0) << "object " << o;
      const std::vector<glm::dvec2>& uv = s.objects[o].mesh.uvs;
      ASSERT_EQ(uv.size(), 4u) << "object " << o;
      for (std::size_t v = 0; v < 4; ++v) {
        EXPECT_DOUBLE_EQ(uv[v].x, q.expected_uv(v).x) << "object " << o << ", vertex " << v;
        EXPECT_DOUBLE_EQ(uv[v].y, q.expected_uv(v).y) << "object " << o << ", vertex " << v;
      }
    }
    EXPECT_NE(s.objects[0].mesh.positions[0], s.objects[1].mesh.positions[0]);
  }
}

// Refusals name the pointer: a wrap glTF does not define, a transform key the extension lacks,
// a rotation that is not a number.
TEST(AlbedoMap, GltfTextureErrorsNameThePointer) {
  test::TempDir dir;
  const std::string bytes = png_bytes(dir.path());
  struct Bad {
    std::function<void(json&)> change;
    std::string where;
  };
  const Bad cases[] = {
      {[](json& d) { d["samplers"][0]["wrapS"] = 10; }, "/samplers/0/wrapS"},
      {[](json& d) {
         d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
          ["KHR_texture_transform"]["skew"] = 1;
       },
       "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/skew"},
      {[](json& d) {
         d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
          ["KHR_texture_transform"]["rotation"] = "quarter";
       },
       "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform"},
      {[](json& d) { d["textures"][0]["source"] = 3; }, "/textures/0/source"},
  };
  for (const Bad& b : cases) {
    TexturedQuad q(bytes);
    b.change(q.w.doc);
    const fs::path file = q.w.write_glb(dir.path(), "bad");
    std::string what = "(no error)";
    try {
      load_scene(file);
    } catch (const InputError& e) {
      what = e.what();
    }
    EXPECT_EQ(what.rfind(file.string() + ":" + b.where, 0), 0u) << what;
  }
}

}  // namespace
}  // namespace lt
