// The power LUT's texture format (:lut-format=, issue 47; docs/textures.md "The LUT's format"):
// the parser's values, each format's texels against the I8 LUT's by the hardware's expansion
// (the nearest 4-bit field by exhaustive search over the 16 levels, the intensity also in
// alpha), the bytes whole tiles give a row, and the generated program read back by the program
// reader draws the variant's frame byte for byte.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/error.h"
#include "gx/program/printer.h"
#include "gx/texture_unit.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/lobe_lut.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx {
namespace {

TEST(GxLutFormat, TheParserTakesTheGreyFormatsAndRefusesTheRest) {
  EXPECT_EQ(parse_gx_variant("t=vertex:lut-format=i4").lut_format, TexFormat::I4);
  EXPECT_EQ(parse_gx_variant("t=texgen:lut-format=ia8").lut_format, TexFormat::IA8);
  EXPECT_EQ(to_string(parse_gx_variant("t=vertex:lut=64:lut-format=ia4")),
            "t=vertex:lut=64:lut-format=ia4");
  // I8 is the default: unset, so the variant is the default's.
  EXPECT_EQ(parse_gx_variant("t=vertex:lut-format=i8"), parse_gx_variant("t=vertex"));
  for (const char* bad : {"t=vertex:lut-format=rgb565", "t=vertex:lut-format=ci4",
                          "lobe=xf-spec:lut-format=i4", "t=vertex:lut-format=i4:lut-format=i8"}) {
    EXPECT_THROW(parse_gx_variant(bad), InputError) << bad;
  }
}

// The 4-bit field whose expansion (k * 17) is nearest to v, the lower on ties: by search.
int nearest_level(int v) {
  int best = 0;
  for (int k = 1; k < 16; ++k)
    if (std::abs(17 * k - v) < std::abs(17 * best - v)) best = k;
  return best;
}

TEST(GxLutFormat, EachFormatHoldsTheI8LutsTexelsAsItsFieldsCan) {
  Material m;
  m.translucency = Translucency{};
  m.translucency->power = 3.5;
  constexpr int kWidth = 256;
  const TextureObject i8 = lobe_lut(m, kWidth);
  ASSERT_EQ(i8.format, kTexFormatI8);
  EXPECT_EQ(lobe_lut(m, kWidth, TexFormat::I8).data, i8.data);
  struct Expect {
    TexFormat format;
    size_t bytes;  // 32 tiles of 32 bytes a row (8 texels a tile's row); IA8 4 texels a row
    bool four_bits;
  };
  for (const Expect& e : {Expect{TexFormat::I4, 1024, true}, Expect{TexFormat::IA4, 1024, true},
                          Expect{TexFormat::IA8, 2048, false}}) {
    SCOPED_TRACE(format_info(e.format).name);
    const TextureObject t = lobe_lut(m, kWidth, e.format);
    EXPECT_EQ(t.format, static_cast<u8>(e.format));
    EXPECT_EQ(t.data.size(), e.bytes);
    int differ = 0;
    for (int i = 0; i < kWidth; ++i) {
      const int v = texel_at(i8, i, 0).r;
      const int want = e.four_bits ? 17 * nearest_level(v) : v;
      const Color8 c = texel_at(t, i, 0);
      differ += c.r != want || c.g != want || c.b != want || c.a != want;
    }
    EXPECT_EQ(differ, 0) << "texels that are not the I8 texel's nearest field";
  }
}

TEST(GxLutFormat, TheProgramReadBackDrawsTheVariantsFrame) {
  const Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  const std::string variant = "t=vertex:lut-format=i4";
  constexpr int kSize = 64;
  const Image direct = render_scene(scene, "gx", variant, kSize, kSize);
  const std::string program =
      print_program(emit_programs(plan_scene(scene, parse_gx_variant(variant))).file);
  EXPECT_NE(program.find("GX_TF_I4"), std::string::npos);
  test::TempDir dir;
  test::write_file(dir / "lut_i4.c", program);
  const Image read_back = render_scene(scene, "gx", variant, kSize, kSize,
                                       PathOptions{(dir / "lut_i4.c").string(), ""});
  EXPECT_TRUE(read_back.rgba == direct.rgba) << "the program's frame differs from the variant's";
  EXPECT_FALSE(render_scene(scene, "gx", "t=vertex", kSize, kSize).rgba == direct.rgba)
      << "16 levels draw I8's frame: the format changes nothing";
}

}  // namespace
}  // namespace lt::gx
