// image/exr_file.h: an EXR read with OpenEXR in the process gives OpenImageIO's floats and spec
// bit for bit (OpenImageIO, read here through its own API, is the judge), on the kinds the
// reader takes (half and float; RGB and RGBA; values that are not round in half, negative, zero
// signs, denormals, infinities and NaN), with alpha associated or not; the kinds it declines
// (tiles, other channels, a shifted window) are left to OpenImageIO; what write_exr_rgba_float
// writes reads back through OpenImageIO as the floats given, with the compression OpenImageIO
// writes; a damaged file fails with one message or is declined to the module's message.
#include "image/exr_file.h"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
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

DecodedImage exr_read_in_process(const fs::path& path) {
  std::unique_ptr<ImageFileReader> reader;
  std::string error;
  EXPECT_EQ(open_exr(path.string(), reader, error), ExrOpen::kOpened) << path << error;
  if (reader) {
    EXPECT_TRUE(reader->spec().floating);
    EXPECT_FALSE(reader->spec().is_8bit);
  }
  return test::read_all_channels(reader.get());
}

// Bit for bit: NaN's payload and zero's sign included.
void expect_same_bits(const std::vector<float>& a, const std::vector<float>& b,
                      const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  size_t differ = 0, first = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::memcmp(&a[i], &b[i], sizeof(float)) != 0 && differ++ == 0) first = i;
  }
  EXPECT_EQ(differ, 0u) << what << ": first at sample " << first << " (" << a[first] << " vs "
                        << b[first] << ")";
}

// Samples no rounding hides: random values over many octaves and both signs, and every special.
std::vector<float> awkward_samples(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
  std::uniform_int_distribution<int> octave(-30, 20);
  std::vector<float> v(count);
  for (float& x : v) x = std::ldexp(mantissa(rng), octave(rng));
  const float specials[] = {0.0f,
                            -0.0f,
                            1.0f,
                            65504.0f,
                            65520.0f,
                            6.0e-8f,
                            1e-40f,
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
  for (size_t i = 0; i < std::size(specials) && i < count; ++i) v[i * 7 % count] = specials[i];
  return v;
}

// An EXR written by OpenEXR with the given channels and type, scan lines (half samples are the
// floats rounded by Imath::half, as a writer of half files rounds them).
void write_exr(const fs::path& path, int w, int h, const std::vector<std::string>& channels,
               Imf::PixelType type, const std::vector<float>& samples) {
  Imf::Header header(w, h);
  Imf::FrameBuffer frame;
  const size_t n = channels.size();
  std::vector<float> floats = samples;
  std::vector<Imath::half> halves(samples.begin(), samples.end());
  const size_t size = type == Imf::HALF ? sizeof(Imath::half) : sizeof(float);
  for (size_t c = 0; c < n; ++c) {
    header.channels().insert(channels[c], Imf::Channel(type));
    char* base = type == Imf::HALF ? reinterpret_cast<char*>(halves.data() + c)
                                   : reinterpret_cast<char*>(floats.data() + c);
    frame.insert(channels[c], Imf::Slice(type, base, size * n, size * n * w));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(h);
}

// A frame buffer of zeros for every channel of `header`, each in its own type, over its data
// window (a slice's base is where pixel (0, 0) would be).
Imf::FrameBuffer zeros_for(const Imf::Header& header, std::vector<float>& storage) {
  const Imath::Box2i w = header.dataWindow();
  const long width = w.max.x - w.min.x + 1, height = w.max.y - w.min.y + 1;
  size_t count = 0;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) ++count;
  storage.assign(static_cast<size_t>(width * height) * count, 0.0f);  // floats: room for halves
  Imf::FrameBuffer frame;
  size_t c = 0;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it, ++c) {
    const size_t size = it.channel().type == Imf::HALF ? 2 : 4;
    char* first = reinterpret_cast<char*>(storage.data() + c * width * height);
    char* base = first - (w.min.x + static_cast<long>(w.min.y) * width) * static_cast<long>(size);
    frame.insert(it.name(), Imf::Slice(it.channel().type, base, size, size * width));
  }
  return frame;
}

TEST(ExrFile, HalfAndFloatRgbAndRgbaDecodeToOpenImageIosFloats) {
  test::TempDir dir;
  const int w = 37, h = 23;
  int checked = 0;
  for (const Imf::PixelType type : {Imf::HALF, Imf::FLOAT}) {
    for (const std::vector<std::string>& channels :
         {std::vector<std::string>{"R", "G", "B"}, std::vector<std::string>{"R", "G", "B", "A"}}) {
      const fs::path path = dir / ("t" + std::to_string(checked) + ".exr");
      write_exr(path, w, h, channels, type, awkward_samples(w * h * channels.size(), checked + 1));
      const DecodedImage ours = exr_read_in_process(path);
      for (bool unassociated : {false, true}) {
        const DecodedImage theirs = test::read_with_oiio(path, unassociated);
        const std::string what = path.filename().string() + (unassociated ? " unassociated" : "");
        EXPECT_EQ(ours.spec.width, theirs.spec.width) << what;
        EXPECT_EQ(ours.spec.height, theirs.spec.height) << what;
        EXPECT_EQ(ours.spec.channels, theirs.spec.channels) << what;
        EXPECT_EQ(ours.spec.alpha_channel, theirs.spec.alpha_channel) << what;
        EXPECT_EQ(ours.spec.bits, theirs.spec.bits) << what;
        expect_same_bits(ours.samples, theirs.samples, what);
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4);
}

// A channel range read alone is those channels of the whole read.
TEST(ExrFile, AChannelRangeIsThoseChannelsOfTheWhole) {
  test::TempDir dir;
  const int w = 9, h = 5;
  write_exr(dir / "a.exr", w, h, {"R", "G", "B", "A"}, Imf::FLOAT, awkward_samples(w * h * 4, 7));
  const DecodedImage whole = exr_read_in_process(dir / "a.exr");
  std::unique_ptr<ImageFileReader> reader;
  std::string error;
  ASSERT_EQ(open_exr((dir / "a.exr").string(), reader, error), ExrOpen::kOpened) << error;
  std::vector<float> gb(static_cast<size_t>(w) * h * 2);
  ASSERT_TRUE(reader->read_channels(1, 3, gb.data(), error)) << error;
  std::vector<float> expected;
  for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p) {
    expected.push_back(whole.samples[p * 4 + 1]);
    expected.push_back(whole.samples[p * 4 + 2]);
  }
  expect_same_bits(gb, expected, "channels 1..2");
}

TEST(ExrFile, WrittenRgbaReadsBackThroughOpenImageIoWithItsCompression) {
  test::TempDir dir;
  const int w = 31, h = 17;
  const std::vector<float> rgba = awkward_samples(w * h * 4, 11);
  std::string error;
  ASSERT_TRUE(write_exr_rgba_float((dir / "ours.exr").string(), w, h, rgba.data(), error)) << error;
  const DecodedImage back = test::read_with_oiio(dir / "ours.exr", false);
  EXPECT_EQ(back.spec.channels, 4);
  EXPECT_EQ(back.spec.alpha_channel, 3);
  EXPECT_EQ(back.spec.bits, 32);
  expect_same_bits(back.samples, rgba, "written and read back");
  // The compression OpenImageIO chooses for the same pixels, so that a golden written before
  // and after this writer existed is the same kind of file.
  OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B", "A"};
  auto out = OIIO::ImageOutput::create((dir / "theirs.exr").string());
  ASSERT_TRUE(out && out->open((dir / "theirs.exr").string(), spec) &&
              out->write_image(OIIO::TypeDesc::FLOAT, rgba.data()) && out->close());
  Imf::InputFile ours((dir / "ours.exr").c_str()), theirs((dir / "theirs.exr").c_str());
  EXPECT_EQ(ours.header().compression(), theirs.header().compression());
  EXPECT_EQ(ours.header().lineOrder(), theirs.header().lineOrder());
}

TEST(ExrFile, OtherKindsAreLeftToOpenImageIo) {
  test::TempDir dir;
  std::unique_ptr<ImageFileReader> reader;
  std::string error;
  // One channel, and five.
  write_exr(dir / "y.exr", 4, 4, {"Y"}, Imf::FLOAT, std::vector<float>(16, 0.5f));
  EXPECT_EQ(open_exr((dir / "y.exr").string(), reader, error), ExrOpen::kDeclined);
  write_exr(dir / "five.exr", 4, 4, {"R", "G", "B", "A", "Z"}, Imf::HALF,
            std::vector<float>(80, 0.25f));
  EXPECT_EQ(open_exr((dir / "five.exr").string(), reader, error), ExrOpen::kDeclined);
  // Mixed types.
  {
    Imf::Header header(4, 4);
    header.channels().insert("R", Imf::Channel(Imf::HALF));
    header.channels().insert("G", Imf::Channel(Imf::FLOAT));
    header.channels().insert("B", Imf::Channel(Imf::FLOAT));
    std::vector<float> storage;
    Imf::OutputFile file((dir / "mixed.exr").c_str(), header);
    file.setFrameBuffer(zeros_for(header, storage));
    file.writePixels(4);
  }
  EXPECT_EQ(open_exr((dir / "mixed.exr").string(), reader, error), ExrOpen::kDeclined);
  // A data window off the origin.
  {
    Imf::Header header(Imath::Box2i({0, 0}, {7, 7}), Imath::Box2i({2, 2}, {5, 5}));
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::HALF));
    std::vector<float> storage;
    Imf::OutputFile file((dir / "window.exr").c_str(), header);
    file.setFrameBuffer(zeros_for(header, storage));
    file.writePixels(4);
  }
  EXPECT_EQ(open_exr((dir / "window.exr").string(), reader, error), ExrOpen::kDeclined);
  // Tiles.
  {
    Imf::Header header(8, 8);
    header.setTileDescription(Imf::TileDescription(4, 4));
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::HALF));
    std::vector<float> storage;
    Imf::TiledOutputFile file((dir / "tiled.exr").c_str(), header);
    file.setFrameBuffer(zeros_for(header, storage));
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  }
  EXPECT_EQ(open_exr((dir / "tiled.exr").string(), reader, error), ExrOpen::kDeclined);
  EXPECT_EQ(reader, nullptr);
  // Each still opens through the image module as before (the caller's fallback).
  for (const char* f : {"y.exr", "five.exr", "mixed.exr", "window.exr", "tiled.exr"})
    EXPECT_NO_THROW((void)read_image(dir / f)) << f;
}

TEST(ExrFile, ADamagedFileFailsOnOneLine) {
  test::TempDir dir;
  const int w = 64, h = 64;
  const std::vector<float> rgba = awkward_samples(w * h * 4, 3);
  std::string error;
  ASSERT_TRUE(write_exr_rgba_float((dir / "full.exr").string(), w, h, rgba.data(), error));
  std::ifstream in(dir / "full.exr", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
  try {
    (void)read_image(dir / "cut.exr");
    ADD_FAILURE() << "a truncated EXR was read";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cut.exr"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

// A header claiming more pixels than the limit is refused from the header, naming the size,
// before OpenEXR's reader is made (which said "invalid display window" here, the library's
// words): 2 x 2,000,000,000 pixels in a file of a few hundred bytes, its data and display
// windows patched in a written 2 x 2 EXR.
TEST(ExrFile, AHugeHeaderIsRefusedFromTheHeader) {
  test::TempDir dir;
  const std::vector<float> rgba(2 * 2 * 4, 0.5f);
  std::string error;
  ASSERT_TRUE(write_exr_rgba_float((dir / "small.exr").string(), 2, 2, rgba.data(), error));
  std::ifstream in(dir / "small.exr", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // An attribute is its name, its type name (both NUL-terminated), a 4-byte size, the value; a
  // box2i is x min, y min, x max, y max, little-endian [OpenEXR ImfBoxAttribute].
  for (const char* name : {"dataWindow", "displayWindow"}) {
    const std::string key = std::string(name) + '\0' + "box2i" + '\0';
    const size_t at = bytes.find(key);
    ASSERT_NE(at, std::string::npos) << name;
    const size_t y_max = at + key.size() + 4 + 12;
    const std::int32_t claimed = 1999999999;
    std::memcpy(&bytes[y_max], &claimed, 4);
  }
  std::ofstream(dir / "huge.exr", std::ios::binary) << bytes;
  try {
    (void)read_image(dir / "huge.exr");
    ADD_FAILURE() << "an EXR of 2 x 2,000,000,000 pixels was read";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("huge.exr"), std::string::npos) << what;
    EXPECT_NE(what.find("header claims 2x2000000000 pixels, over the limit of 16777216"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace lt
