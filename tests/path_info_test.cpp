// Every path's PathInfo the same way (issue 24): a typed variant parsed once, the registry's
// one message for an unknown listed name, and the evaluate step regress shares (render/evaluate.h).
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"
#include "paths/combiners/combiner_budget.h"
#include "paths/combiners/combiners_path.h"
#include "paths/path.h"
#include "render/evaluate.h"

namespace lt {
namespace {

std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every listed name is its own canonical spelling, on every path (a grammar path may accept
// more spellings, never rename a listed one).
TEST(PathInfo, EveryListedVariantResolvesToItself) {
  for (const PathInfo& p : all_paths()) {
    EXPECT_EQ(resolve_variant(p, ""), p.variants.front().name) << p.name;
    for (const VariantInfo& v : p.variants) EXPECT_EQ(resolve_variant(p, v.name), v.name) << p.name;
  }
}

// The message a listed path gives for a name it does not have, written out here (not taken from
// the code that builds it): the path, and every valid name in the listed order.
TEST(PathInfo, AnUnknownListedVariantIsNamedWithTheValidOnes) {
  const std::string half = input_error([] { (void)resolve_variant(find_path("half"), "pow=sq"); });
  EXPECT_NE(half.find("path half has no such variant (valid: pow=exact, pow=sg, pow=unguarded)"),
            std::string::npos)
      << half;
  const std::string glsl = input_error([] { (void)resolve_variant(find_path("glsl"), "f32"); });
  EXPECT_NE(glsl.find("path glsl has no such variant (valid: pow=exact, pow=exact:f32)"),
            std::string::npos)
      << glsl;
  for (const char* name : {"reference", "flat"}) {
    const std::string e = input_error([&] { (void)resolve_variant(find_path(name), "x"); });
    EXPECT_NE(e.find(std::string("path ") + name + " has no such variant"), std::string::npos) << e;
  }
}

// The combiners variant is parsed once into its enum; the budget, which is given the user's
// text, parses it the same way (it used to count an unknown name as t=vertex).
TEST(PathInfo, CombinersVariantsAreTyped) {
  EXPECT_EQ(parse_combiners_variant(""), CombinersVariant::TVertex);
  EXPECT_EQ(parse_combiners_variant("t=vertex"), CombinersVariant::TVertex);
  EXPECT_EQ(parse_combiners_variant("t=texgen"), CombinersVariant::TTexgen);
  EXPECT_EQ(parse_combiners_variant("lobe=cube"), CombinersVariant::LobeCube);
  const std::string e = input_error([] { (void)parse_combiners_variant("lobe=cubes"); });
  EXPECT_NE(e.find("path combiners has no such variant (valid: t=vertex, t=texgen, lobe=cube)"),
            std::string::npos)
      << e;
  EXPECT_EQ(resolve_variant(find_path("combiners"), "lobe=cube"), "lobe=cube");
  Scene scene;
  const std::string b = input_error([&] { (void)combiner_budget(scene, "", "t=vertx"); });
  EXPECT_NE(b.find("path combiners has no such variant"), std::string::npos) << b;
}

// A path without a capability says so through its data, and calling it anyway is a bug
// (an internal-error abort), not a silent empty answer.
TEST(PathInfo, CapabilitiesFollowTheirData) {
  const PathInfo& half = find_path("half");
  EXPECT_TRUE(half.budget_profiles.empty());
  EXPECT_FALSE(half.writes_fifo_log);
  EXPECT_DEATH((void)half.budget(Scene{}, "", ""), "path half has no budget");
  EXPECT_TRUE(find_path("gx").writes_fifo_log);
  EXPECT_FALSE(find_path("combiners").budget_profiles.empty());
}

// regress's comparison with a golden: the golden's alpha is replaced by the render's coverage,
// both sides are compared as bytes. A golden that differs only where the render covers nothing
// has no covered error; one byte off inside the coverage is one LSB.
TEST(Evaluate, AGoldenIsComparedOverTheRendersCoverage) {
  // Values k/255 on both sides: the bytes k, whatever the rounding of a value between two bytes.
  const float k128 = 128.0f / 255.0f;
  Image render(2, 1), golden(2, 1);
  for (size_t i = 0; i < 2; ++i) {
    for (int c = 0; c < 3; ++c) render.rgba[i * 4 + c] = golden.rgba[i * 4 + c] = k128;
    golden.rgba[i * 4 + 3] = 1;  // a PNG's alpha: opaque
  }
  render.rgba[3] = 1;      // pixel 0 covered
  render.rgba[4 + 3] = 0;  // pixel 1 not
  golden.rgba[4] = 1.0f;   // 255 against 128, outside the coverage
  const Comparison far = compare_with_golden(render, golden);
  EXPECT_EQ(far.covered.max_lsb, 0.0);
  EXPECT_DOUBLE_EQ(far.image.max_lsb, 127.0);
  golden.rgba[4] = k128;
  golden.rgba[0] = 129.0f / 255.0f;  // one byte off inside the coverage
  EXPECT_DOUBLE_EQ(compare_with_golden(render, golden).covered.max_lsb, 1.0);
}

}  // namespace
}  // namespace lt
