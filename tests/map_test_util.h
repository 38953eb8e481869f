// Fixtures of the thickness-map tests: images written through OpenImageIO (any channel count,
// 8-bit or float, a declared colour space), a UV-mapped quad as glTF, and a scene around them.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

#include "gltf_test_util.h"
#include "image/image.h"
#include "model/translucency.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::test {

// Writes `values` (width * height * channels, top row first) as PNG (8-bit) or EXR (float).
inline void write_test_image(const fs::path& path, int width, int height, int channels,
                             const std::vector<float>& values, const char* colour_space = "") {
  const bool exr = path.extension() == ".exr";
  OIIO::ImageSpec spec(width, height, channels,
                       exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (channels == 4 || channels == 2) spec.alpha_channel = channels - 1;
  if (*colour_space) spec.attribute("oiio:ColorSpace", colour_space);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // the values as given, not divided by alpha
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec)) << path;
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, values.data()));
  out->close();
}

// The unit quad in z = 0 facing +Z, its UVs (OpenGL's: v = 0 at the bottom) from (0, 0) at the
// bottom-left corner to (1, 1) at the top-right; glTF stores v downwards, so 1 - v is written.
inline fs::path write_uv_quad(const fs::path& dir, bool with_uvs = true) {
  GltfWriter w;
  const int pos = w.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  const int nrm = w.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int uv = w.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  const int idx = w.accessor(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}, 5123, "SCALAR", 1);
  GltfWriter::json attributes = {{"POSITION", pos}, {"NORMAL", nrm}};
  if (with_uvs) attributes["TEXCOORD_0"] = uv;
  w.doc["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", idx}}}}});
  w.root({{"mesh", 0}});
  return w.write_gltf(dir, with_uvs ? "uv_quad" : "quad_without_uvs");
}

// A scene of the quad seen head-on (orthographic, filling the image) with a light behind it,
// material "skin" reading `thickness` (the JSON of the key) and, if set, `ramp`.
inline std::string map_scene(const std::string& thickness, const std::string& mesh = "uv_quad.gltf",
                             const std::string& ramp = "") {
  return R"({
  "image": {"width": 64, "height": 64},
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "projection": "orthographic", "height": 2},
  "materials": {"skin": {"albedo": [0.8, 0.8, 0.8],
    "translucency": {"power": 2, "distortion": 0.1, "ambient": 0.1, "thickness": )" +
         thickness + (ramp.empty() ? "" : ", \"ramp\": \"" + ramp + "\"") + R"(}}},
  "lights": [{"type": "directional", "direction": [0.1, 0.2, 1], "intensity": 1.5},
             {"type": "directional", "direction": [0, 0, -1], "intensity": 0.3}],
  "objects": [{"gltf": ")" +
         mesh + R"(", "material": "skin"}]
})";
}

// The ground truth of map_scene() (any map), computed here in double from the model (model::shade
// with the map bilinearly sampled at each pixel centre's UV), independently of any path: the quad
// fills the 64 x 64 orthographic image, so pixel (x, y) (row 0 at the top) sees the point
// (-1 + (x + 0.5) / 32, 1 - (y + 0.5) / 32, 0), whose UV is that mapped from [-1, 1] to [0, 1].
inline Image quad_ground_truth(const Scene& scene) {
  Image img(scene.width, scene.height);
  const Material& m = scene.materials[0];
  for (int y = 0; y < scene.height; ++y) {
    for (int x = 0; x < scene.width; ++x) {
      model::SurfacePoint sp;
      sp.P = {-1 + (x + 0.5) * 2 / scene.width, 1 - (y + 0.5) * 2 / scene.height, 0};
      sp.N = {0, 0, 1};
      sp.V = model::view_vector(scene.camera, sp.P - scene.camera.eye);
      sp.uv = {(sp.P.x + 1) / 2, (sp.P.y + 1) / 2};
      const glm::dvec3 c = model::shade(scene, m, sp);
      float* out = img.at(x, y);
      for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(c[k]);
      out[3] = 1;
    }
  }
  return img;
}

}  // namespace lt::test
