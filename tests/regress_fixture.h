// Small real scenes for the regress and report-page tests: a lit quad at 48x32, rendered through
// OSMesa like any scene, so a whole regress run takes a fraction of a second.
#pragma once

#include <string>

#include "image/image.h"
#include "regress/regress.h"
#include "test_util.h"

namespace lt::test {

// A translucent quad lit from behind-left; `extra` is spliced into the scene's top-level object
// (e.g. a "regress" block), `power` changes the lobe so two scenes render differently.
inline void write_quad_scene(const fs::path& dir, const std::string& name, double power = 4,
                             const std::string& extra = "") {
  if (!fs::exists(dir / "quad.obj")) write_file(dir / "quad.obj", quad_obj());
  write_file(dir / (name + ".json"), R"({
    "image": {"width": 48, "height": 32},
    "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40},
    "materials": {"m": {"albedo": [0.8, 0.7, 0.6],
                        "translucency": {"power": )" +
                                         std::to_string(power) +
                                         R"(, "distortion": 0.2, "thickness": 0.5}}},
    "lights": [{"type": "directional", "direction": [0.3, 0.2, 1], "translucency_scale": 2}],
    "objects": [{"mesh": "quad.obj", "material": "m"}])" +
                                         (extra.empty() ? "" : ", " + extra) + "}");
}

// Two quad scenes in `dir` (quad_a at power 4, quad_b at 16) and their goldens in dir/goldens
// through `paths`, written by a `regress --update` run in this process: where the regress tests
// that run the command start. Returns how many goldens it created.
inline size_t write_two_quads_with_goldens(const fs::path& dir, const std::string& paths) {
  write_quad_scene(dir, "quad_a", 4);
  write_quad_scene(dir, "quad_b", 16);
  RegressOptions o;
  o.inputs = {dir / "quad_a.json", dir / "quad_b.json"};
  o.goldens = dir / "goldens";
  o.paths = paths;
  o.update = true;
  o.quiet = true;
  return run_regress(o).count(CaseStatus::kCreated);
}

// Adds `lsb` to the red channel of one pixel of an 8-bit PNG (a golden), in place.
inline void push_pixel(const fs::path& png, int x, int y, int lsb) {
  Image img = read_image(png);
  float* p = img.at(x, y);
  const float moved = p[0] + static_cast<float>(lsb) / 255.0f;
  p[0] = moved > 1.0f ? p[0] - static_cast<float>(lsb) / 255.0f : moved;
  write_image(png, img);
}

}  // namespace lt::test
