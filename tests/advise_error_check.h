// An error advise reports for one variant, measured again outside advise (issues 46 and 47):
// the variant and the ground truth each rendered with render_scene at advise's size, in a session
// of their own, and compared with compare_images as advise states it measures (docs/advise.md,
// advise/material_error.h): the gx frame as the 8-bit bytes it holds (the console's EFB keeps 8
// bits a channel), the reference as floats, over the pixels both cover (Coverage::kBoth). advise
// narrows "covered" to one material's pixels from the G-buffer; the scenes these tests use have
// one material, and the reference's coverage is that same G-buffer's, so the regions are equal.
// Nothing here goes through advise's VariantTrials or compare_material.
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "load/load_scene.h"
#include "metrics/compare.h"
#include "render/session.h"

namespace lt::test {

// Expects `reported` (advise's JSON {"max", "mean", ...} for `variant` on the gx path) to be the
// error measured here. Exactly: the same renderers and the same compare arithmetic run on the
// same pixels, and nlohmann's JSON writes a double so that it reads back to the same bits.
inline void expect_advise_error_is_measured_again(const std::filesystem::path& scene_file,
                                                  const nlohmann::json& advise,
                                                  const std::string& variant,
                                                  const nlohmann::json& reported) {
  const Scene scene = load_scene(scene_file);
  ASSERT_EQ(scene.materials.size(), 1u) << "the covered region is one material's (see above)";
  const int width = advise.at("width"), height = advise.at("height");
  const Image test = render_scene(scene, "gx", variant, width, height);
  const Image reference = render_scene(scene, "reference", "", width, height);
  const Comparison c =
      compare_images(test, reference, TestEncoding::kUnorm8, TestEncoding::kFloat, Coverage::kBoth);
  ASSERT_GT(c.covered.pixels, 0u) << variant;
  EXPECT_EQ(c.test_non_finite_pixels, 0u) << variant;
  EXPECT_EQ(reported.at("max").get<double>(), c.covered.max_lsb) << variant;
  EXPECT_EQ(reported.at("mean").get<double>(), c.covered.mean_lsb) << variant;
}

}  // namespace lt::test
