// Guard elision (arb_guards.h): the distance of a triangle of normals from the origin, checked
// against analytic cases; on every demo and hard scene the program without the guards the scene
// cannot trigger renders the same float image as the one with every guard (`:guards=all`); the
// hard cases that need a guard keep it.
#include "paths/arbfp/arb_guards.h"

#include <gtest/gtest.h>

#include <cstring>

#include "arb_ir_query.h"
#include "arb_test_util.h"
#include "load/load_scene.h"
#include "paths/arbfp/arb_generator.h"
#include "arb/arb_ir_counter.h"
#include "render/session.h"

namespace lt {
namespace {

using glm::dvec3;

TEST(ArbGuards, DistanceOfATriangleFromTheOrigin) {
  // Face region: the plane x + y + z = 1 is 1/sqrt(3) from the origin.
  EXPECT_NEAR(arbfp::distance_to_origin(dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)),
              1 / std::sqrt(3.0), 1e-15);
  // The origin inside the triangle.
  EXPECT_EQ(arbfp::distance_to_origin(dvec3(-1, -1, 0), dvec3(1, -1, 0), dvec3(0, 1, 0)), 0);
  // Vertex region: the closest point is (1, 0, 0).
  EXPECT_NEAR(arbfp::distance_to_origin(dvec3(1, 0, 0), dvec3(2, 0, 0), dvec3(1, 1, 0)), 1, 1e-15);
  // Edge region: the edge from (1, -1, 0) to (1, 1, 0) passes at 1.
  EXPECT_NEAR(arbfp::distance_to_origin(dvec3(1, -1, 0), dvec3(1, 1, 0), dvec3(3, 0, 0)), 1, 1e-15);
  // Degenerate (collinear) triangles: through the origin, and at distance 1 from it.
  EXPECT_EQ(arbfp::distance_to_origin(dvec3(-1, 0, 0), dvec3(1, 0, 0), dvec3(0.5, 0, 0)), 0);
  EXPECT_NEAR(arbfp::distance_to_origin(dvec3(1, 1, 0), dvec3(2, 1, 0), dvec3(3, 1, 0)),
              std::sqrt(2.0), 1e-15);
  // Normals of a smooth patch (all within 30 degrees of +z): far from the origin.
  EXPECT_GT(arbfp::distance_to_origin(dvec3(0.5, 0, 0.866), dvec3(0, 0.5, 0.866), dvec3(0, 0, 1)),
            0.8);
}

// The float image of the arbfp path for a variant (no 8-bit rounding hides a difference).
std::vector<float> render_float(const Scene& scene, const std::string& variant) {
  RenderSession session(scene, 96, 72);
  auto path = session.build(find_path("arbfp"), variant);
  return test::frame_in_float_target(*path, 96, 72);
}

std::vector<std::string> scenes_of(std::initializer_list<const char*> dirs) {
  std::vector<std::string> out;
  for (const char* d : dirs) {
    for (const std::string& s : test::json_files(d)) out.push_back(s);
  }
  return out;
}

// Every scene: fewer instructions or the same, and the same bits in a float target.
TEST(ArbGuards, ElidedProgramsRenderTheSameAsGuardedOnes) {
  int dropped = 0;
  for (const std::string& file : scenes_of({"scenes", "scenes/ortho", "scenes/hard"})) {
    const Scene scene = test::load_test_scene(file);
    for (const char* variant : {"pow=mul", "pow=lut:256:u8"}) {
      const std::string all = std::string(variant) + ":guards=all";
      for (const Material& m : scene.materials) {
        const auto elided = arbfp::generate_arb(scene, m, arbfp::parse_variant(variant));
        const auto guarded = arbfp::generate_arb(scene, m, arbfp::parse_variant(all));
        const int a = arbfp::ir::count(elided.fragment_program).alu;
        const int b = arbfp::ir::count(guarded.fragment_program).alu;
        EXPECT_LE(a, b) << file << " " << m.name;
        dropped += b - a;
      }
      const std::vector<float> x = render_float(scene, variant), y = render_float(scene, all);
      ASSERT_EQ(x.size(), y.size());
      EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(float)), 0)
          << file << " " << variant << ": the elided program renders differently";
    }
  }
  EXPECT_GT(dropped, 0) << "some scene drops a guard";
}

// The hard cases whose case is a guard's keep it: a light at a vertex or inside the mesh the
// distance-0 CMP. The meshes of zero_normals.json and degenerate_triangles.json have no zero
// normal once loaded (the reader recomputes zero-length normals from the faces,
// docs/numeric-conventions.md), so no interpolated normal of theirs can vanish and their guard
// is dropped (the render test above shows the same image); cancelling normals, model.md's other
// zero-normal case, keep it.
TEST(ArbGuards, HardCasesKeepTheGuardsTheyNeed) {
  for (const char* file :
       {"scenes/hard/point_light_at_vertex.json", "scenes/hard/light_inside_mesh.json"}) {
    const Scene scene = test::load_test_scene(file);
    for (const Material& m : scene.materials) {
      const auto p = arbfp::generate_arb(scene, m, arbfp::parse_variant("pow=mul"));
      EXPECT_TRUE(test::has_op(p.fragment_program, arbfp::ir::Op::CMP)) << file << " " << m.name;
    }
  }
  for (const char* file :
       {"scenes/hard/zero_normals.json", "scenes/hard/degenerate_triangles.json"}) {
    const Scene scene = test::load_test_scene(file);
    double shortest = 1e300;
    for (const SceneObject& o : scene.objects) {
      for (const dvec3& n : o.mesh.normals) shortest = std::min(shortest, glm::length(n));
    }
    EXPECT_GT(shortest, 0.5) << file << ": a zero normal survived loading";
  }
  // One triangle whose normals cancel along an edge: (1, 0, 0) and (-1, 0, 0) interpolate to 0.
  const test::TempDir dir;
  test::write_file(dir / "cancel.obj",
                   "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nvn 1 0 0\nvn -1 0 0\nvn 0 0 1\n"
                   "f 1//1 2//2 3//3\n");
  test::write_file(dir / "cancel.json",
                   R"({ "image": { "width": 32, "height": 32 },
  "camera": { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0] },
  "materials": { "m": { "albedo": [1, 1, 1], "translucency": { "power": 2 } } },
  "lights": [ { "type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1] } ],
  "objects": [ { "mesh": "cancel.obj", "material": "m" } ] })");
  const Scene scene = load_scene(dir / "cancel.json");
  const auto p =
      arbfp::generate_arb(scene, scene.materials.front(), arbfp::parse_variant("pow=mul"));
  EXPECT_TRUE(test::has_op(p.fragment_program, arbfp::ir::Op::SGE)) << "the zero-normal guard";
}

// On a demo scene with three point lights away from a smooth mesh every guard goes, and the
// notes say so (`info` prints them).
TEST(ArbGuards, InfoNamesTheDroppedGuards) {
  const Scene scene = test::load_test_scene("scenes/three_point_blob.json");
  const auto p =
      arbfp::generate_arb(scene, scene.materials.front(), arbfp::parse_variant("pow=mul"));
  EXPECT_FALSE(test::has_op(p.fragment_program, arbfp::ir::Op::SGE));
  EXPECT_FALSE(test::has_op(p.fragment_program, arbfp::ir::Op::CMP));
  EXPECT_FALSE(test::has_op(p.fragment_program, arbfp::ir::Op::MAX));
  int notes = 0;
  for (const std::string& n : p.notes) notes += n.find("dropped") != std::string::npos;
  EXPECT_EQ(notes, 1 + 2 * 3) << "zero normal, and per light distance 0 and attenuation floor";
}

}  // namespace
}  // namespace lt
