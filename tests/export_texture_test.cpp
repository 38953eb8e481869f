// `ltrender export texture IMAGE --format FMT [--mipmaps] -o FILE.tpl` (docs/textures.md): the
// TPL it writes read back and decoded as the console does, against colours RGB565 holds exactly
// and the box filter's mean; bad input refused in one line, nothing written.
#include <gtest/gtest.h>

#include "gx/texture_decoder.h"
#include "gx/tpl_file.h"
#include "image/image.h"
#include "test_util.h"

namespace lt {
namespace {

// A 4x2 PNG: top row RGB565-exact red-ish, bottom row blue-ish (8-bit values v / 255).
fs::path write_png(const test::TempDir& dir) {
  Image image(4, 2);
  for (int x = 0; x < 4; ++x) {
    float* top = image.at(x, 0);
    float* bottom = image.at(x, 1);
    top[0] = gx::bits5_to_8(31) / 255.0f;  // 255
    top[1] = gx::bits6_to_8(16) / 255.0f;  // 65
    top[2] = 0;
    bottom[0] = 0;
    bottom[1] = gx::bits6_to_8(8) / 255.0f;  // 32
    bottom[2] = gx::bits5_to_8(20) / 255.0f; // 165
    top[3] = bottom[3] = 1;
  }
  const fs::path png = dir / "in.png";
  write_image(png, image);
  return png;
}

std::vector<gx::TplTexture> read_tpl_file(const fs::path& tpl) {
  const std::string bytes = test::read_file(tpl);
  return gx::read_tpl(std::span(reinterpret_cast<const gx::u8*>(bytes.data()), bytes.size()),
                      tpl.string());
}

TEST(ExportTexture, Rgb565TexelsDecodeToTheImageAndMipsAverageIt) {
  const test::TempDir dir;
  const fs::path png = write_png(dir), tpl = dir / "out.tpl";
  const auto r = test::run_ltrender("export texture " + png.string() +
                                    " --format RGB565 --mipmaps -o " + tpl.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<gx::TplTexture> textures = read_tpl_file(tpl);
  ASSERT_EQ(textures.size(), 1u);
  const gx::TplTexture& t = textures[0];
  EXPECT_EQ(t.format, gx::TexFormat::RGB565);
  EXPECT_EQ(t.levels, 3);  // 4x2, 2x1, 1x1
  EXPECT_EQ(t.min_filter, 5u);
  const gx::TextureView level0{t.format, 4, 2, std::span(t.data).first(32)};
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(gx::decode_texel(level0, x, 0), (gx::Color8{255, 65, 0, 255}));  // row 0 = top
    EXPECT_EQ(gx::decode_texel(level0, x, 1), (gx::Color8{0, 32, 165, 255}));
  }
  // Level 1 (2x1): the mean of red-ish and blue-ish, (127.5, 48.5, 82.5) rounded half up to
  // (128, 49, 83), then RGB565's nearest: r 128 -> 16 (132) or 15 (123): 132; g 49 -> 12 (48);
  // b 83 -> 10 (82).
  const gx::TextureView level1{t.format, 2, 1, std::span(t.data).subspan(32, 32)};
  EXPECT_EQ(gx::decode_texel(level1, 0, 0), (gx::Color8{132, 48, 82, 255}));
}

TEST(ExportTexture, BadInputIsRefusedInOneLineAndNothingIsWritten) {
  const test::TempDir dir;
  const fs::path png = write_png(dir), tpl = dir / "out.tpl";
  const auto unknown = test::run_ltrender("export texture " + png.string() +
                                          " --format RGB888 -o " + tpl.string());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err,
            "ltrender: error: export:--format: RGB888: unknown texture format (valid: I4, I8, IA4, "
            "IA8, RGB565, RGB5A3, RGBA8, CI4, CI8, CI14X2, CMPR)\n");
  const auto no_format = test::run_ltrender("export texture " + png.string() + " -o " + tpl.string());
  EXPECT_EQ(no_format.exit_code, 2);
  EXPECT_EQ(test::count_lines(no_format.err), 1);
  const auto wrong_extension =
      test::run_ltrender("export texture " + png.string() + " --format I8 -o " + (dir / "x.png").string());
  EXPECT_EQ(wrong_extension.exit_code, 2);
  Image wide(1025, 1);
  const fs::path big = dir / "wide.png";
  write_image(big, wide);
  const auto too_big = test::run_ltrender("export texture " + big.string() + " --format I8 -o " + tpl.string());
  EXPECT_EQ(too_big.exit_code, 2);
  EXPECT_NE(too_big.err.find("1025x1 is over the texture unit's 1024 texels a side"), std::string::npos)
      << too_big.err;
  EXPECT_FALSE(fs::exists(tpl));
}

}  // namespace
}  // namespace lt
