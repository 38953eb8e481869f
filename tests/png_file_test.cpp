// image/png_file.h: PNG read with libpng in the process gives OpenImageIO's floats bit for bit
// (OpenImageIO, read here through its own API, is the judge), on PNGs of every colour type, bit
// depth, palette, tRNS and interlace that libpng writes, and on the real PNGs of the tree and of
// Debian's assimp-testmodels; what write_png_rgb8 writes reads back through OpenImageIO as the
// bytes given; a damaged file fails with one message.
#include "image/png_file.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "decoded_image.h"
#include "image/image.h"
#include "test_util.h"

namespace lt {
namespace {

using test::DecodedImage;

DecodedImage read_with_libpng(const fs::path& path) {
  std::unique_ptr<ImageFileReader> reader;
  std::string error;
  EXPECT_EQ(open_png(path.string(), true, reader, error), PngOpen::kOpened) << path << error;
  return test::read_all_channels(reader.get());
}

void expect_same_decoding(const fs::path& path) {
  SCOPED_TRACE(path.string());
  const DecodedImage oiio = test::read_with_oiio(path, true), ours = read_with_libpng(path);
  EXPECT_EQ(ours.spec.width, oiio.spec.width);
  EXPECT_EQ(ours.spec.height, oiio.spec.height);
  EXPECT_EQ(ours.spec.channels, oiio.spec.channels);
  EXPECT_EQ(ours.spec.alpha_channel, oiio.spec.alpha_channel);
  EXPECT_EQ(ours.spec.bits, oiio.spec.bits);
  ASSERT_EQ(ours.samples.size(), oiio.samples.size());
  size_t differing = 0;
  for (size_t i = 0; i < ours.samples.size(); ++i)
    differing += std::memcmp(&ours.samples[i], &oiio.samples[i], sizeof(float)) != 0;
  EXPECT_EQ(differing, 0u) << "samples differing in their bits";
}

// A PNG written by libpng itself with whatever header `png_kind` asks: a palette with tRNS,
// grey at 1, 2 and 4 bits, 16-bit samples, Adam7 interlace. Rows are raw seeded bytes (every bit
// pattern is a valid sample; palette indices are kept below the palette's size).
struct PngKind {
  const char* name;
  int colour_type, bit_depth, interlace;
  bool transparency;
};

[[noreturn]] void test_png_error(png_structp png, png_const_charp message) {
  ADD_FAILURE() << "libpng: " << message;
  png_longjmp(png, 1);
}

bool write_kind(png_structp png, png_infop info, std::FILE* f, const PngKind& k, int w, int h,
                png_bytep* rows, const png_color* palette, const png_byte* alpha) {
  const int entries = std::min(16, 1 << k.bit_depth);  // a palette holds at most 2^depth colours
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), k.bit_depth,
               k.colour_type, k.interlace, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (k.colour_type == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette, entries);
  png_color_16 key{};
  key.gray = 1, key.red = 3, key.green = 5, key.blue = 7;
  if (k.transparency)
    png_set_tRNS(png, info, alpha, k.colour_type == PNG_COLOR_TYPE_PALETTE ? entries : 0, &key);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

void write_png_of_kind(const fs::path& path, const PngKind& k, int w, int h, unsigned seed) {
  const int channels = k.colour_type == PNG_COLOR_TYPE_RGB          ? 3
                       : k.colour_type == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                       : k.colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                                    : 1;
  const size_t row_bytes = (static_cast<size_t>(w) * channels * k.bit_depth + 7) / 8;
  std::vector<png_byte> bytes(row_bytes * h);
  std::mt19937 rng(seed);
  for (auto& b : bytes) b = static_cast<png_byte>(rng());
  // Palette indices stay within its 16 entries (4 bits or fewer).
  if (k.colour_type == PNG_COLOR_TYPE_PALETTE && k.bit_depth == 8)
    for (auto& b : bytes) b &= 15;
  std::vector<png_bytep> rows(h);
  for (int y = 0; y < h; ++y) rows[y] = bytes.data() + y * row_bytes;
  png_color palette[16];
  png_byte alpha[16];
  for (int i = 0; i < 16; ++i) {
    palette[i] = {static_cast<png_byte>(rng()), static_cast<png_byte>(rng()),
                  static_cast<png_byte>(rng())};
    alpha[i] = static_cast<png_byte>(rng());
  }
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_TRUE(f);
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, test_png_error, nullptr);
  png_infop info = png_create_info_struct(png);
  EXPECT_TRUE(write_kind(png, info, f, k, w, h, rows.data(), palette, alpha));
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

TEST(PngFile, EveryKindOfPngDecodesToOpenImageIosFloats) {
  test::TempDir dir;
  const PngKind kinds[] = {
      {"grey1", PNG_COLOR_TYPE_GRAY, 1, PNG_INTERLACE_NONE, false},
      {"grey2", PNG_COLOR_TYPE_GRAY, 2, PNG_INTERLACE_NONE, false},
      {"grey4_trns", PNG_COLOR_TYPE_GRAY, 4, PNG_INTERLACE_NONE, true},
      {"grey8", PNG_COLOR_TYPE_GRAY, 8, PNG_INTERLACE_NONE, false},
      {"grey16", PNG_COLOR_TYPE_GRAY, 16, PNG_INTERLACE_NONE, false},
      {"grey_alpha8", PNG_COLOR_TYPE_GRAY_ALPHA, 8, PNG_INTERLACE_NONE, false},
      {"grey_alpha16", PNG_COLOR_TYPE_GRAY_ALPHA, 16, PNG_INTERLACE_NONE, false},
      {"rgb8", PNG_COLOR_TYPE_RGB, 8, PNG_INTERLACE_NONE, false},
      {"rgb8_trns", PNG_COLOR_TYPE_RGB, 8, PNG_INTERLACE_NONE, true},
      {"rgb8_adam7", PNG_COLOR_TYPE_RGB, 8, PNG_INTERLACE_ADAM7, false},
      {"rgb16", PNG_COLOR_TYPE_RGB, 16, PNG_INTERLACE_NONE, false},
      {"rgba8", PNG_COLOR_TYPE_RGB_ALPHA, 8, PNG_INTERLACE_NONE, false},
      {"rgba16_adam7", PNG_COLOR_TYPE_RGB_ALPHA, 16, PNG_INTERLACE_ADAM7, false},
      {"palette4", PNG_COLOR_TYPE_PALETTE, 4, PNG_INTERLACE_NONE, false},
      {"palette8_trns", PNG_COLOR_TYPE_PALETTE, 8, PNG_INTERLACE_NONE, true},
      {"palette2_trns_adam7", PNG_COLOR_TYPE_PALETTE, 2, PNG_INTERLACE_ADAM7, true},
  };
  unsigned seed = 1;
  for (const PngKind& k : kinds) {
    const fs::path file = dir / (std::string(k.name) + ".png");
    write_png_of_kind(file, k, 37, 29, seed++);  // odd sizes: partial bytes, partial Adam7 passes
    expect_same_decoding(file);
  }
}

TEST(PngFile, RealFilesDecodeToOpenImageIosFloats) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(test::source_dir()))
    if (e.is_regular_file() && e.path().extension() == ".png" &&
        e.path().string().find("/build") == std::string::npos)
      files.push_back(e.path());
  // Debian's assimp-testmodels: textures other tools wrote (palettes, RGBA, grey).
  const fs::path assimp = "/usr/share/assimp/models";
  if (fs::exists(assimp))
    for (const auto& e : fs::recursive_directory_iterator(assimp))
      if (e.is_regular_file() && e.path().extension() == ".png" && fs::file_size(e.path()) < 300000)
        files.push_back(e.path());
  ASSERT_GE(files.size(), 20u);
  for (const fs::path& f : files)
    if (has_png_signature(f)) expect_same_decoding(f);
}

TEST(PngFile, AlphaMultipliedByColourIsLeftToOpenImageIo) {
  test::TempDir dir;
  write_png_of_kind(dir / "rgba.png", {"rgba8", PNG_COLOR_TYPE_RGB_ALPHA, 8, 0, false}, 5, 4, 7);
  std::unique_ptr<ImageFileReader> reader;
  std::string error;
  EXPECT_EQ(open_png((dir / "rgba.png").string(), false, reader, error), PngOpen::kDeclined);
  EXPECT_FALSE(reader);
  write_png_of_kind(dir / "rgb.png", {"rgb8", PNG_COLOR_TYPE_RGB, 8, 0, false}, 5, 4, 7);
  EXPECT_EQ(open_png((dir / "rgb.png").string(), false, reader, error), PngOpen::kOpened);
}

TEST(PngFile, WrittenRgbReadsBackThroughOpenImageIo) {
  test::TempDir dir;
  const int w = 13, h = 7;
  std::vector<uint8_t> rgb(w * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i * 37 + 11);
  std::string error;
  ASSERT_TRUE(write_png_rgb8((dir / "w.png").string(), w, h, rgb.data(), error)) << error;
  auto in = OIIO::ImageInput::open((dir / "w.png").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, w);
  EXPECT_EQ(in->spec().height, h);
  EXPECT_EQ(in->spec().nchannels, 3);
  std::vector<uint8_t> back(rgb.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
  EXPECT_EQ(back, rgb);
}

TEST(PngFile, DamagedFilesFailWithOneMessage) {
  test::TempDir dir;
  write_png_of_kind(dir / "good.png", {"rgb8", PNG_COLOR_TYPE_RGB, 8, 0, false}, 32, 32, 3);
  const std::string good = test::read_file(dir / "good.png");
  // Cut inside the pixel data: the header opens, the pixels fail.
  test::write_file(dir / "cut.png", good.substr(0, good.size() / 2));
  std::unique_ptr<ImageFileReader> reader;
  std::string error;
  ASSERT_EQ(open_png((dir / "cut.png").string(), true, reader, error), PngOpen::kOpened);
  std::vector<float> px(32 * 32 * 3);
  EXPECT_FALSE(reader->read_channels(0, 3, px.data(), error));
  EXPECT_EQ(error, "PNG read error: IDAT: hit end of file");
  // A header whose CRC does not match: refused at open.
  std::string bad_crc = good;
  bad_crc[29] ^= 0x5a;  // IHDR's CRC follows its 13 bytes (offsets 29-32)
  test::write_file(dir / "crc.png", bad_crc);
  reader.reset();
  error.clear();
  EXPECT_EQ(open_png((dir / "crc.png").string(), true, reader, error), PngOpen::kFailed);
  EXPECT_EQ(error.rfind("PNG read error: ", 0), 0u) << error;
  // Through read_image: one line naming the file.
  try {
    (void)read_image(dir / "cut.png");
    ADD_FAILURE() << "a cut PNG was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.png: cannot decode image: PNG read error: "),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(has_png_signature(dir / "missing.png"));
  test::write_file(dir / "text.png", "not a png at all");
  EXPECT_FALSE(has_png_signature(dir / "text.png"));
}

}  // namespace
}  // namespace lt
