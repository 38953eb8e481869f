// A glTF file's two stages (load/gltf/gltf_scene.h): the parse stage describes the file without
// decoding an accessor or an image, so bytes that cannot be decoded are refused by the load
// stage, naming the accessor or image, after the description was made.
#include <gtest/gtest.h>

#include <limits>

#include "core/error.h"
#include "gltf_test_util.h"
#include "load/gltf/gltf_scene.h"

namespace lt {
namespace {

// The load stage's error for `d`, or "" when it loads.
std::string load_error(gltf::GltfDescription d) {
  try {
    gltf::load_gltf_scene(std::move(d));
  } catch (const InputError& e) {
    return e.where() + ": " + e.what_only();
  }
  return "";
}

TEST(GltfStages, CorruptVertexBytesAreDescribedThenRefusedByTheLoadNamingTheAccessor) {
  test::TempDir dir;
  test::GltfWriter w = test::volume_quad();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&w.bin[4], &nan, 4);                     // POSITION (accessor 0), vertex 0's y
  w.doc["nodes"][0]["translation"] = {0.5, 0.25, -2};  // the quad's node
  const gltf::GltfDescription d = gltf::describe_gltf_scene(w.write_gltf(dir.path(), "q"));

  ASSERT_EQ(d.primitives.size(), 1u);
  EXPECT_EQ(d.primitives[0].mesh, 0);
  EXPECT_EQ(d.primitives[0].node_ptr, "/nodes/0");
  EXPECT_EQ(d.primitives[0].world[3], glm::dvec4(0.5, 0.25, -2, 1));
  ASSERT_EQ(d.materials.size(), 1u);
  EXPECT_EQ(d.materials[0].material.name, "jade");
  EXPECT_FALSE(d.materials[0].texture);
  ASSERT_EQ(d.lights.size(), 1u);
  ASSERT_EQ(d.cameras.size(), 1u);
  EXPECT_EQ(d.cameras[0].world[3], glm::dvec4(0, 0, 3, 1));  // the "Eye" node's translation

  const std::string error = load_error(d);
  EXPECT_EQ(error.rfind("/accessors/0: POSITION of vertex 0 is ", 0), 0u) << error;
  EXPECT_NE(error.find("(not finite)"), std::string::npos) << error;
}

TEST(GltfStages, AnImageThatIsNoPictureIsDescribedThenRefusedByTheLoadNamingTheImage) {
  test::TempDir dir;
  test::GltfWriter w = test::volume_quad();
  w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  w.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
  w.doc["samplers"] = {{{"wrapS", 33648}, {"wrapT", 33071}}};
  w.doc["images"] = {{{"uri", "data:image/png;base64,AAAA"}}};  // three zero bytes: no PNG
  const gltf::GltfDescription d = gltf::describe_gltf_scene(w.write_gltf(dir.path(), "t"));

  ASSERT_EQ(d.materials.size(), 1u);
  ASSERT_TRUE(d.materials[0].texture);
  const gltf::TextureDescription& t = *d.materials[0].texture;
  EXPECT_EQ(t.pointer, "/materials/0/pbrMetallicRoughness/baseColorTexture");
  EXPECT_EQ(t.image, 0);
  EXPECT_EQ(t.wrap_s, TextureWrap::MirroredRepeat);
  EXPECT_EQ(t.wrap_t, TextureWrap::ClampToEdge);
  EXPECT_FALSE(d.materials[0].material.albedo_map);  // not decoded yet

  const std::string error = load_error(d);
  EXPECT_EQ(error, "/images/0: is neither PNG nor JPEG (the image formats glTF 2.0 allows)")
      << error;
}

}  // namespace
}  // namespace lt
