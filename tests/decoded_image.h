// An image file's spec and samples, read by OpenImageIO itself (the judge the in-process readers
// image/png_file.h and image/exr_file.h are held to) or by one of those readers.
#pragma once

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "image/image_codec.h"

namespace lt::test {

struct DecodedImage {
  ImageFileSpec spec;          // width, height, channels, alpha_channel, bits as OpenImageIO says
  std::vector<float> samples;  // every channel, row-major
};

// OpenImageIO's reading as floats; `unassociated_alpha`: its oiio:UnassociatedAlpha (colour as
// stored).
inline DecodedImage read_with_oiio(const std::filesystem::path& path, bool unassociated_alpha) {
  OIIO::ImageSpec config;
  if (unassociated_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
  DecodedImage d;
  if (!in) return d;
  const OIIO::ImageSpec& s = in->spec();
  d.spec.width = s.width, d.spec.height = s.height, d.spec.channels = s.nchannels;
  d.spec.alpha_channel = s.alpha_channel;
  d.spec.bits = static_cast<int>(s.format.size()) * 8;
  d.samples.resize(static_cast<size_t>(s.width) * s.height * s.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, s.nchannels, OIIO::TypeDesc::FLOAT, d.samples.data()));
  return d;
}

// Every channel of an opened reader (null: an empty result, the caller's expectation failed).
inline DecodedImage read_all_channels(ImageFileReader* reader) {
  DecodedImage d;
  if (!reader) return d;
  d.spec = reader->spec();
  d.samples.resize(static_cast<size_t>(d.spec.width) * d.spec.height * d.spec.channels);
  std::string error;
  EXPECT_TRUE(reader->read_channels(0, d.spec.channels, d.samples.data(), error)) << error;
  return d;
}

}  // namespace lt::test
