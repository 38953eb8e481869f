// Every input the ARB generator is tested on: each scene file (demo, ortho, hard, tessellation)
// as it is and, for the demo scenes, with one feature changed at a time (power 0, 1 and 2.5,
// normalised H, vertex thickness, lt ambient 0, orthographic camera, no ambient light, 6 and 21
// lights); each with its first k lights (what the budget's term cost generates); every material;
// every registered variant plus three more widths of the LUT grammar; with and without the term.
// The IR tests and the byte-identity dump walk the same list.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "arb_test_util.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arbfp_path.h"

namespace lt::test {

struct ArbCase {
  std::string label;  // "scenes/backlit_sphere.json normalize-h k=1 sphere pow=mul term"
  const Scene& scene;
  const Material& material;
  const arbfp::PowVariant& variant;
  bool term;
};

inline std::vector<std::string> arb_variant_names() {
  std::vector<std::string> out;
  for (const VariantInfo& v : arbfp_path_info().variants) out.push_back(v.name);
  for (const char* extra : {"pow=lut:128:f16", "pow=lut:2:f32", "pow=lut:4096:u8"}) {
    out.push_back(extra);
  }
  return out;
}

// One feature of a demo scene changed; the name goes into the label.
struct SceneChange {
  const char* name;
  std::function<void(Scene&)> apply;
};

inline std::vector<SceneChange> scene_changes() {
  auto each_term = [](const std::function<void(Translucency&)>& f) {
    return [f](Scene& s) {
      for (Material& m : s.materials) {
        if (m.translucency) f(*m.translucency);
      }
    };
  };
  auto lights = [](size_t n) {
    return [n](Scene& s) {
      Light point;
      point.type = Light::Type::Point;
      point.position = s.camera.eye;  // distance 0 at the eye: exercises nothing special here
      point.kc = 0.5;
      point.kq = 0.25;
      std::vector<Light> base = s.lights;
      base.push_back(point);
      s.lights.clear();
      for (size_t i = 0; i < n; ++i) s.lights.push_back(base[i % base.size()]);
    };
  };
  return {
      {"as-is", [](Scene&) {}},
      {"power-0", each_term([](Translucency& t) { t.power = 0; })},
      {"power-1", each_term([](Translucency& t) { t.power = 1; })},
      {"power-2.5", each_term([](Translucency& t) { t.power = 2.5; })},
      {"normalize-h", each_term([](Translucency& t) { t.normalize_distorted_light = true; })},
      {"vertex-thickness",
       each_term([](Translucency& t) { t.thickness_source = ThicknessSource::Vertex; })},
      {"lt-ambient-0", each_term([](Translucency& t) { t.ambient = 0; })},
      {"ortho", [](Scene& s) { s.camera.projection = Camera::Projection::Orthographic; }},
      {"no-ambient-light", [](Scene& s) { s.ambient_light = glm::dvec3(0); }},
      {"lights-6", lights(6)},
      {"lights-21", lights(21)},
  };
}

// The light counts k the budget and the tests generate for: all of 0..n for a few lights, else
// 0, 1 and n.
inline std::vector<size_t> light_prefixes(size_t n) {
  std::vector<size_t> out;
  if (n <= 6) {
    for (size_t k = 0; k <= n; ++k) out.push_back(k);
  } else {
    out = {0, 1, n};
  }
  return out;
}

inline void for_each_arb_case(const std::function<void(const ArbCase&)>& f) {
  std::vector<std::string> files = json_files("scenes");
  for (const char* sub : {"scenes/ortho", "scenes/hard", "scenes/tessellation"}) {
    for (const std::string& s : json_files(sub)) files.push_back(s);
  }
  std::vector<arbfp::PowVariant> variants;
  for (const std::string& v : arb_variant_names()) variants.push_back(arbfp::parse_variant(v));
  const std::vector<SceneChange> changes = scene_changes();
  for (const std::string& file : files) {
    const Scene loaded = load_test_scene(file);
    const bool demo = fs::path(file).parent_path() == "scenes";
    for (const SceneChange& change : changes) {
      if (!demo && std::string(change.name) != "as-is") continue;
      Scene changed = loaded;
      change.apply(changed);
      for (size_t k : light_prefixes(changed.lights.size())) {
        Scene s = changed;
        s.lights.resize(k);
        for (const Material& m : s.materials) {
          for (const arbfp::PowVariant& v : variants) {
            for (bool term : {true, false}) {
              const std::string label = file + " " + change.name + " k=" + std::to_string(k) + " " +
                                        m.name + " " + v.name() + (term ? " term" : " no-term");
              f({label, s, m, v, term});
            }
          }
        }
      }
    }
  }
}

}  // namespace lt::test
