// One test per row of docs/scenes-and-gltf.md's glTF mapping table, on files the tests write.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "gltf_test_util.h"
#include "load/gltf/gltf_lights.h"
#include "load/gltf/gltf_materials.h"
#include "load/load_scene.h"
#include "scene/scene.h"

namespace lt {
namespace {

using json = nlohmann::json;
constexpr double kPi = 3.14159265358979323846;

bool has_note(const Scene& s, const std::string& text) {
  for (const std::string& n : s.import_notes) {
    if (n.find(text) != std::string::npos) return true;
  }
  return false;
}

class GltfMapping : public ::testing::Test {
 protected:
  Scene load(const test::GltfWriter& w) { return load_scene(w.write_gltf(dir_.path(), "m")); }
  test::TempDir dir_;
};

TEST_F(GltfMapping, BaseColorFactorIsTheAlbedo) {
  const Scene s = load(test::volume_quad());
  EXPECT_EQ(s.materials.at(0).albedo, glm::dvec3(0.9, 0.8, 0.7));
  EXPECT_EQ(s.materials.at(0).name, "jade");
}

TEST_F(GltfMapping, VolumeThicknessIsTheExtensionsBeerLambertTransmittance) {
  const Scene s = load(test::volume_quad());
  const Translucency& t = *s.materials.at(0).translucency;
  EXPECT_EQ(t.thickness_source, ThicknessSource::Constant);
  EXPECT_NEAR(t.thickness.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(t.thickness.y, 0.5, 1e-15);
  EXPECT_NEAR(t.thickness.z, 1.0, 1e-15);
  // Thin parts bright: half the thickness lets more through.
  EXPECT_GT(gltf::volume_transmittance({0.5, 0.5, 0.5}, 0.25, 1).x,
            gltf::volume_transmittance({0.5, 0.5, 0.5}, 0.5, 1).x);
  // The extension's default distance (+inf) attenuates nothing.
  EXPECT_EQ(gltf::volume_transmittance({0.1, 0.2, 0.3}, 5, INFINITY), glm::dvec3(1));
}

TEST_F(GltfMapping, ThicknessTextureFallsBackToTheFactorWithAWarning) {
  test::GltfWriter w = test::volume_quad();
  w.doc["materials"][0]["extensions"]["KHR_materials_volume"]["thicknessTexture"] = {{"index", 0}};
  w.doc["textures"] = json::array({json::object()});
  const Scene s = load(w);
  EXPECT_NEAR(s.materials.at(0).translucency->thickness.y, 0.5, 1e-15);
  EXPECT_TRUE(has_note(s, "warning /materials/0/extensions/KHR_materials_volume/thicknessTexture"));
  EXPECT_TRUE(has_note(s, "ignored /textures"));
}

TEST_F(GltfMapping, DiffuseTransmissionIsTheAmbientAndTheTint) {
  // A copy: the scene load() returns is a temporary.
  const Translucency t = *load(test::volume_quad()).materials.at(0).translucency;
  EXPECT_EQ(t.ambient, 0.1);
  EXPECT_EQ(t.tint, glm::dvec3(1, 0.8, 0.6));
}

TEST_F(GltfMapping, ExtrasGivePowerDistortionAndTheLightsScale) {
  const Scene s = load(test::volume_quad());
  EXPECT_EQ(s.materials.at(0).translucency->power, 2);
  EXPECT_EQ(s.materials.at(0).translucency->distortion, 0.5);
  EXPECT_EQ(s.lights.at(0).translucency_scale, 2);
}

TEST_F(GltfMapping, WithoutExtrasTheDocumentedDefaults) {
  test::GltfWriter w = test::volume_quad();
  w.doc["materials"][0].erase("extras");
  w.doc["nodes"][1].erase("extras");
  w.doc["extensions"]["KHR_lights_punctual"]["lights"][0].erase("extras");
  const Scene s = load(w);
  EXPECT_EQ(s.materials.at(0).translucency->power, gltf::kDefaultPower);
  EXPECT_EQ(s.materials.at(0).translucency->distortion, gltf::kDefaultDistortion);
  EXPECT_EQ(s.lights.at(0).translucency_scale, 1);
  EXPECT_TRUE(has_note(s, "default /materials/0: power 8"));
}

TEST_F(GltfMapping, AMaterialWithoutTheExtensionsIsDiffuseOnly) {
  test::GltfWriter w = test::volume_quad();
  w.doc["materials"][0] = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}}}};
  const Scene s = load(w);
  EXPECT_FALSE(s.materials.at(0).translucency.has_value());
  EXPECT_EQ(s.materials.at(0).name, "/materials/0");
}

TEST_F(GltfMapping, AnUnknownExtrasKeyIsAnErrorNamingIt) {
  test::GltfWriter w = test::volume_quad();
  w.doc["materials"][0]["extras"]["ltrender"]["powr"] = 3;
  try {
    load(w);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/materials/0/extras/ltrender/powr");
  }
}

TEST_F(GltfMapping, PhotometricLightsBecomeTheScenesLinearIntensity) {
  test::GltfWriter w = test::volume_quad();  // directional: pi lux
  w.light({{"type", "point"}, {"intensity", 4 * kPi}, {"color", {1, 0.5, 0.25}}});
  w.doc["nodes"].back()["translation"] = {1, 2, 3};
  const Scene s = load(w);
  EXPECT_NEAR(s.lights.at(0).color.x, 1.0, 1e-15);
  EXPECT_NEAR(s.lights.at(0).direction.z, 1.0, 1e-15);  // -Z of a node turned 180 degrees about Y
  const Light& p = s.lights.at(1);
  EXPECT_EQ(p.type, Light::Type::Point);
  EXPECT_EQ(p.position, glm::dvec3(1, 2, 3));
  EXPECT_NEAR(p.color.x, 4, 1e-14);
  EXPECT_NEAR(p.color.y, 2, 1e-14);
  EXPECT_EQ(p.kc, 0);
  EXPECT_EQ(p.kl, 0);
  EXPECT_EQ(p.kq, 1);
}

// The fit and its stated error (docs/scenes-and-gltf.md): kq = 5/4, window error RMS 0.27, max 0.8
// at the range; no kc or kl > 0 lowers the RMS error, at any range.
double rms_window_error(double kc, double kl, double kq, double range) {
  double sum = 0;
  for (int i = 0; i <= 1000; ++i) {
    const double d = range * i / 1000, window = std::clamp(1 - std::pow(d / range, 4), 0.0, 1.0);
    const double den = kc + kl * d + kq * d * d;
    const double e = (den > 0 ? d * d / den : 0) - window;
    sum += e * e;
  }
  return std::sqrt(sum / 1001);
}

TEST_F(GltfMapping, RangeBecomesAFittedAttenuationWithItsErrorStated) {
  for (double range : {0.5, 10.0, 1000.0}) {
    const gltf::RangeFit f = gltf::fit_range_falloff(range);
    EXPECT_EQ(f.kq, 1.25);
    EXPECT_NEAR(f.rms_window_error, 0.267, 0.001);
    EXPECT_NEAR(f.max_window_error, 0.8, 1e-12);
    EXPECT_EQ(f.at_distance, 1.0);
    const double best = rms_window_error(f.kc, f.kl, f.kq, range);
    for (double kq : {1.2, 1.3}) EXPECT_GT(rms_window_error(0, 0, kq, range), best);
    for (double k : {1e-3, 1e-2, 1e-1}) {
      EXPECT_GT(rms_window_error(k * range * range, 0, f.kq, range), best) << k;
      EXPECT_GT(rms_window_error(0, k * range, f.kq, range), best) << k;
      EXPECT_GT(rms_window_error(k * range * range, 0, f.kq - k, range), best) << k;
      EXPECT_GT(rms_window_error(0, k * range, f.kq - k, range), best) << k;
    }
  }
  test::GltfWriter w = test::volume_quad();
  w.light({{"type", "point"}, {"range", 10}});
  EXPECT_TRUE(has_note(load(w), "range 10.0 -> kc 0.0 kl 0.0 kq 1.25"));
}

TEST_F(GltfMapping, CamerasPerspectiveAndOrthographic) {
  const Scene ortho = load(test::volume_quad());
  EXPECT_EQ(ortho.camera.projection, Camera::Projection::Orthographic);
  EXPECT_EQ(ortho.camera.height, 3);  // 2 x ymag
  EXPECT_EQ(ortho.camera.eye, glm::dvec3(0, 0, 3));
  EXPECT_EQ(ortho.camera.forward(), glm::dvec3(0, 0, -1));
  test::QuadParams q;
  q.orthographic = false;
  const Scene persp = load(test::volume_quad(q));
  EXPECT_EQ(persp.camera.projection, Camera::Projection::Perspective);
  EXPECT_NEAR(persp.camera.fov_y_deg, 0.7 * 180 / kPi, 1e-12);
  EXPECT_EQ(persp.camera.near, 0.1);
  EXPECT_EQ(persp.camera.far, 10);
  EXPECT_EQ(persp.width, 640);  // 480 x aspectRatio 4/3
  EXPECT_EQ(persp.height, 480);
}

TEST_F(GltfMapping, ACameraIsChosenByItsNameOrItsNodes) {
  test::GltfWriter w = test::volume_quad();
  w.doc["cameras"].push_back(
      {{"name", "side"},
       {"type", "orthographic"},
       {"orthographic", {{"xmag", 1}, {"ymag", 4}, {"znear", 0.1}, {"zfar", 10}}}});
  w.root({{"name", "SideEye"}, {"camera", 1}, {"translation", {0, 0, 5}}});
  const fs::path file = w.write_gltf(dir_.path(), "m");
  EXPECT_EQ(load_scene(file).camera.height, 3);
  EXPECT_EQ(load_scene(file, {"side"}).camera.height, 8);
  EXPECT_EQ(load_scene(file, {"SideEye"}).camera.eye.z, 5);
  EXPECT_THROW(load_scene(file, {"top"}), InputError);
}

// Issue 24: unnamed cameras could not be picked, and the error listed them as "none".
TEST_F(GltfMapping, AnUnnamedCameraIsChosenByItsIndexAndListedAsOne) {
  test::GltfWriter w = test::volume_quad();
  w.doc["cameras"][0].erase("name");
  w.doc["nodes"].back().erase("name");
  w.doc["cameras"].push_back(
      {{"type", "orthographic"},
       {"orthographic", {{"xmag", 1}, {"ymag", 4}, {"znear", 0.1}, {"zfar", 10}}}});
  w.root({{"camera", 1}, {"translation", {0, 0, 5}}});
  const fs::path file = w.write_gltf(dir_.path(), "m");
  EXPECT_EQ(load_scene(file).camera.height, 3);  // the first one, as before
  for (const char* second : {"#1", "1"}) {
    const Scene s = load_scene(file, {second});
    EXPECT_EQ(s.camera.height, 8) << second;  // 2 x ymag
    EXPECT_EQ(s.camera.eye.z, 5) << second;
  }
  EXPECT_EQ(load_scene(file, {"#0"}).camera.height, 3);
  try {
    load_scene(file, {"#2"});
    FAIL() << "no camera #2";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--camera");
    EXPECT_NE(std::string(e.what()).find("(cameras: #0, #1)"), std::string::npos) << e.what();
  }
  // A name wins over an index: a camera named "1" is the one "1" picks.
  w.doc["cameras"][0]["name"] = "1";
  const fs::path named = w.write_gltf(dir_.path(), "named");
  EXPECT_EQ(load_scene(named, {"1"}).camera.height, 3);
  EXPECT_EQ(load_scene(named, {"#1"}).camera.height, 8);
}

TEST_F(GltfMapping, NodeTransformsComposeDownTheHierarchy) {
  test::GltfWriter w = test::volume_quad();
  // Parent: translate (10, 0, 0), scale 2 (TRS); child: a matrix translating (0, 1, 0)
  // (column-major) that holds the mesh.
  w.doc["nodes"][0].erase("mesh");
  w.doc["nodes"][0]["translation"] = {10, 0, 0};
  w.doc["nodes"][0]["scale"] = {2, 2, 2};
  const int child =
      w.node({{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1}}});
  w.doc["nodes"][0]["children"] = {child};
  const Scene s = load(w);
  // Vertex (-1, -1, 0): child -> (-1, 0, 0), parent -> (10 - 2, 0, 0).
  EXPECT_EQ(s.objects.at(0).mesh.positions.at(0), glm::dvec3(8, 0, 0));
  EXPECT_EQ(s.objects.at(0).mesh.positions.at(2), glm::dvec3(12, 4, 0));
  EXPECT_EQ(s.objects.at(0).mesh.normals.at(0), glm::dvec3(0, 0, 1));
}

// Attributes: every index type, no indices, normals computed, COLOR_0 normalised, TEXCOORD_0.
TEST_F(GltfMapping, AttributesAndIndicesOfEveryType) {
  for (int index_type : {5121, 5123, 5125, 0}) {
    test::GltfWriter w = test::volume_quad();
    auto& prim = w.doc["meshes"][0]["primitives"][0];
    prim["attributes"].erase("NORMAL");
    if (index_type == 5121)
      prim["indices"] = w.accessor(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}, 5121, "SCALAR", 1);
    if (index_type == 5125)
      prim["indices"] = w.accessor(std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}, 5125, "SCALAR", 1);
    if (index_type == 0) {
      prim.erase("indices");
      prim["attributes"]["POSITION"] =
          w.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
    }
    const std::size_t n = index_type == 0 ? 6 : 4;
    if (index_type == 5123) {
      prim["attributes"]["COLOR_0"] =
          w.accessor(std::vector<std::uint16_t>(n * 4, 65535), 5123, "VEC4", 4, true);
    } else {
      prim["attributes"]["COLOR_0"] =
          w.accessor(std::vector<std::uint8_t>(n * 3, 51), 5121, "VEC3", 3, true);
    }
    prim["attributes"]["TEXCOORD_0"] = w.floats(std::vector<float>(n * 2, 0.25f), "VEC2", 2);
    const Scene s = load(w);
    const TriangleMesh& m = s.objects.at(0).mesh;
    EXPECT_EQ(m.triangles.size(), 2u) << index_type;
    EXPECT_EQ(m.triangles.at(1), index_type == 0 ? glm::uvec3(3, 4, 5) : glm::uvec3(0, 2, 3));
    EXPECT_EQ(m.normals.at(1), glm::dvec3(0, 0, 1)) << "computed, area-weighted";
    EXPECT_DOUBLE_EQ(m.colors.at(0).x, index_type == 5123 ? 1.0 : 0.2);
    EXPECT_EQ(m.uvs.at(0), glm::dvec2(0.25, 0.75)) << "v flipped to OpenGL's bottom-up";
    EXPECT_TRUE(has_note(s, "computed /meshes/0/primitives/0/attributes/NORMAL"));
  }
}

TEST_F(GltfMapping, Color0IsTheThicknessWhenTheExtrasAskForIt) {
  test::GltfWriter w = test::volume_quad();
  w.doc["materials"][0]["extras"]["ltrender"]["thickness"] = "vertex";
  w.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
      w.floats(std::vector<float>(12, 0.5f), "VEC3", 3);
  const Scene s = load(w);
  EXPECT_EQ(s.materials.at(0).translucency->thickness_source, ThicknessSource::Vertex);
  EXPECT_EQ(s.objects.at(0).mesh.colors.at(3), glm::dvec3(0.5));
}

TEST_F(GltfMapping, GlbDataUriAndExternalBufferLoadTheSame) {
  const test::GltfWriter w = test::volume_quad();
  const Scene a = load_scene(w.write_gltf(dir_.path(), "a"));
  const Scene b = load_scene(w.write_glb(dir_.path(), "b"));
  const Scene c = load_scene(w.write_gltf_data_uri(dir_.path(), "c"));
  EXPECT_EQ(a.objects.at(0).mesh.positions, b.objects.at(0).mesh.positions);
  EXPECT_EQ(a.objects.at(0).mesh.positions, c.objects.at(0).mesh.positions);
  EXPECT_EQ(a.objects.at(0).mesh.triangles, c.objects.at(0).mesh.triangles);
}

TEST_F(GltfMapping, EveryIgnoredPropertyIsNamed) {
  test::GltfWriter w = test::volume_quad();
  w.doc["materials"][0]["emissiveFactor"] = {1, 0, 0};
  w.doc["materials"][0]["doubleSided"] = true;
  w.doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.5;
  w.doc["materials"][0]["extensions"]["KHR_materials_clearcoat"] = json::object();
  w.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
      w.floats(std::vector<float>(16, 0), "VEC4", 4);
  w.doc["animations"] = json::array();
  w.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"] = json::object();
  w.doc["nodes"][0]["weights"] = {0.5};
  const Scene s = load(w);
  for (const char* p : {"ignored /materials/0/emissiveFactor", "ignored /materials/0/doubleSided",
                        "ignored /materials/0/pbrMetallicRoughness/roughnessFactor",
                        "ignored /materials/0/extensions/KHR_materials_clearcoat",
                        "ignored /meshes/0/primitives/0/attributes/TANGENT", "ignored /animations",
                        "ignored /meshes/0/primitives/0/extensions/KHR_materials_variants",
                        "ignored /nodes/0/weights", "ignored /cameras/0/orthographic/xmag",
                        "mapped /materials/0/pbrMetallicRoughness/baseColorFactor",
                        "mapped /materials/0/extensions/KHR_materials_volume",
                        "mapped /materials/0/extensions/KHR_materials_diffuse_transmission",
                        "mapped /extensions/KHR_lights_punctual/lights/0", "mapped /cameras/0"}) {
    EXPECT_TRUE(has_note(s, p)) << p;
  }
  EXPECT_FALSE(has_note(s, "ignored /materials/0/extensions/KHR_materials_volume"));
}

TEST_F(GltfMapping, SceneLimitsApply) {
  test::GltfWriter w = test::volume_quad();
  for (int i = 0; i < 64; ++i) w.light({{"type", "directional"}});
  try {
    load(w);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.what_only().find("65 lights, more than the limit of 64"), std::string::npos)
        << e.what();
  }
  test::GltfWriter far = test::volume_quad();
  far.doc["nodes"][0]["scale"] = {1e9, 1, 1};  // vertex x = -1e9 * 1 is inside, the matrix too
  far.doc["nodes"][0]["translation"] = {1, 0, 0};
  try {
    load(far);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/nodes/0");
    EXPECT_NE(e.what_only().find("beyond the coordinate limit"), std::string::npos) << e.what();
  }
  test::GltfWriter big = test::volume_quad();
  big.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {2e4, 1, 1, 1};
  EXPECT_THROW(load(big), InputError);  // kMaxColour
}

}  // namespace
}  // namespace lt
