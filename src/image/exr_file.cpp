#include "image/exr_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfTestFile.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <exception>
#include <fstream>
#include <vector>

#include "image/image.h"

namespace lt {

namespace {

// The channels in the order OpenImageIO gives them, R, G, B, then A (its exrinput.cpp orders
// the colour and alpha channels first; ExrFile.* holds this reader to its spec and samples).
constexpr std::array<const char*, 4> kChannelOrder = {"R", "G", "B", "A"};

class ExrReader final : public ImageFileReader {
 public:
  ExrReader(std::unique_ptr<Imf::InputFile> file, ImageFileSpec spec)
      : file_(std::move(file)), spec_(spec) {}
  ~ExrReader() override { close(); }

  const ImageFileSpec& spec() const override { return spec_; }

  bool read_channels(int begin, int end, float* out, std::string& error) override {
    if (!file_) {
      error = "EXR read error: the file is closed";
      return false;
    }
    const Imath::Box2i window = file_->header().dataWindow();
    const size_t pixel_step = sizeof(float) * static_cast<size_t>(end - begin);
    const size_t row_step = pixel_step * static_cast<size_t>(spec_.width);
    // A slice's base is where pixel (0, 0) of the data window would be; the window is at the
    // origin here (open_exr declines any other), so it is `out` itself.
    Imf::FrameBuffer frame;
    for (int c = begin; c < end; ++c) {
      char* base = reinterpret_cast<char*>(out + (c - begin));
      frame.insert(kChannelOrder[static_cast<size_t>(c)],
                   Imf::Slice(Imf::FLOAT, base, pixel_step, row_step));
    }
    try {
      file_->setFrameBuffer(frame);
      file_->readPixels(window.min.y, window.max.y);
    } catch (const std::exception& e) {
      error = std::string("EXR read error: ") + e.what();
      return false;
    }
    return true;
  }

  void close() override { file_.reset(); }

 private:
  std::unique_ptr<Imf::InputFile> file_;
  ImageFileSpec spec_;
};

// Fills `spec` as OpenImageIO reports the same file; false when this reader leaves the file to
// OpenImageIO (exr_file.h).
bool plain_rgb_spec(const Imf::Header& header, ImageFileSpec& spec) {
  if (header.hasTileDescription()) return false;
  const Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
  if (data != display || data.min != Imath::V2i(0, 0)) return false;
  const Imf::ChannelList& channels = header.channels();
  int count = 0;
  for (auto it = channels.begin(); it != channels.end(); ++it) ++count;
  if (count != 3 && count != 4) return false;
  const Imf::Channel* red = channels.findChannel("R");
  if (!red) return false;
  for (int c = 0; c < count; ++c) {
    const Imf::Channel* ch = channels.findChannel(kChannelOrder[static_cast<size_t>(c)]);
    if (!ch || ch->type != red->type || ch->xSampling != 1 || ch->ySampling != 1) return false;
  }
  if (red->type != Imf::HALF && red->type != Imf::FLOAT) return false;
  spec.width = data.max.x - data.min.x + 1;
  spec.height = data.max.y - data.min.y + 1;
  spec.depth = 1;
  spec.channels = count;
  spec.alpha_channel = count == 4 ? 3 : -1;
  spec.is_8bit = false;
  spec.bits = red->type == Imf::HALF ? 16 : 32;
  spec.floating = true;
  return true;
}

// The data window's size from the header alone, before the library's InputFile (or OpenImageIO's)
// is made, so that no reader is ever sized by a header over the pixel limit. Measured with
// Debian's OpenEXR 3.1.5: a 2 x 2 file whose windows claim 10^9 rows made InputFile fail reading
// its chunk table ("Early end of file"; a scratch probe, not kept, saw little memory taken), so a
// short file did end in one line before, but with the library's words, and how much it reserves
// first is the library's choice; a header claiming more than 2^30 rows it refused as an "invalid
// display window". Empty when the window is within kMaxImagePixels (image.h), else what is wrong;
// throws as OpenEXR does on a header it cannot read.
std::string oversized_header(const std::string& path) {
  Imf::StdIFStream stream(path.c_str());
  // The magic number and the version field, 4 bytes each, little-endian [OpenEXR ImfVersion.h].
  char head[8];
  stream.read(head, 8);
  const int version = static_cast<int>(
      static_cast<unsigned char>(head[4]) | static_cast<unsigned char>(head[5]) << 8 |
      static_cast<unsigned char>(head[6]) << 16 |
      static_cast<unsigned>(static_cast<unsigned char>(head[7])) << 24);
  Imf::Header header;
  int read_version = version;
  header.readFrom(stream, read_version);
  const Imath::Box2i data = header.dataWindow();
  const long long width = static_cast<long long>(data.max.x) - data.min.x + 1;
  const long long height = static_cast<long long>(data.max.y) - data.min.y + 1;
  // An empty window is left to the caller's "image has no pixels".
  if (width <= 0 || height <= 0 || width <= kMaxImagePixels / height) return "";
  return "header claims " + std::to_string(width) + "x" + std::to_string(height) +
         " pixels, over the limit of " + std::to_string(kMaxImagePixels) + " (4096^2) pixels";
}

}  // namespace

bool has_exr_signature(const std::filesystem::path& path) {
  // 20000630 little-endian [OpenEXR ImfHeader.h MAGIC].
  constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
  std::ifstream in(path, std::ios::binary);
  unsigned char head[4] = {};
  if (!in.read(reinterpret_cast<char*>(head), 4)) return false;
  return std::equal(head, head + 4, kMagic);
}

ExrOpen open_exr(const std::string& path, std::unique_ptr<ImageFileReader>& reader,
                 std::string& error) {
  reader.reset();
  bool tiled = false, deep = false, multipart = false;
  if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multipart)) return ExrOpen::kDeclined;
  try {
    // Before any reader of either library is made, whatever kind of EXR this is.
    error = oversized_header(path);
    if (!error.empty()) return ExrOpen::kFailed;
    if (tiled || deep || multipart) return ExrOpen::kDeclined;
    auto file = std::make_unique<Imf::InputFile>(path.c_str());
    ImageFileSpec spec;
    if (!plain_rgb_spec(file->header(), spec)) return ExrOpen::kDeclined;
    reader = std::make_unique<ExrReader>(std::move(file), spec);
    return ExrOpen::kOpened;
  } catch (const std::exception& e) {
    error = std::string("EXR read error: ") + e.what();
    return ExrOpen::kFailed;
  }
}

bool write_exr_rgba_float(const std::string& path, int width, int height, const float* rgba,
                          std::string& error) {
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    const size_t pixel_step = 4 * sizeof(float), row_step = pixel_step * width;
    for (size_t c = 0; c < kChannelOrder.size(); ++c) {
      header.channels().insert(kChannelOrder[c], Imf::Channel(Imf::FLOAT));
      char* base = const_cast<char*>(reinterpret_cast<const char*>(rgba + c));
      frame.insert(kChannelOrder[c], Imf::Slice(Imf::FLOAT, base, pixel_step, row_step));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
  } catch (const std::exception& e) {
    error = std::string("EXR write error: ") + e.what();
    return false;
  }
  return true;
}

}  // namespace lt
