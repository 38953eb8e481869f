// The ground truth of a demo scene at its own size, shared by the bounds tests' processes.
//
// Why: Demo/Bounded is ~400 processes (one per path, variant and scene: piglit's rule, a crash
// in a GL context fails one test), and each rendered the same reference as every other test of
// its scene: half of their work, about a third of the suite (issue 28 measured it). The
// reference is deterministic, so it is rendered once per scene per ctest run.
//
// Only under ctest: the fixture test BoundsReferenceCache.Clear (tests/schedule.json) empties
// the folder at the start of every run and names it in LT_TEST_REFERENCE_CACHE for the bounds
// tests, so an image never outlives the build and the scene files it was rendered from. A test
// run without that variable renders its own reference, as before.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/fs.h"
#include "image/image.h"

namespace lt::test {

// The cached image for `key` (e.g. the scene file's stem), or `render()`'s, which is stored for
// the next test. A file is written atomically (core/fs.h), so two processes racing for the same
// scene each read a whole image; a file of the wrong size is ignored and rendered over.
inline Image cached_reference(const std::string& key, const std::function<Image()>& render) {
  const char* dir = std::getenv("LT_TEST_REFERENCE_CACHE");
  if (!dir || !*dir) return render();
  const std::filesystem::path file = std::filesystem::path(dir) / (key + ".rgba32f");
  if (std::ifstream in{file, std::ios::binary}) {
    Image img;
    in.read(reinterpret_cast<char*>(&img.width), sizeof img.width);
    in.read(reinterpret_cast<char*>(&img.height), sizeof img.height);
    if (in && img.width > 0 && img.height > 0 && img.width * 1LL * img.height <= kMaxImagePixels) {
      img.rgba.resize(img.pixel_count() * 4);
      in.read(reinterpret_cast<char*>(img.rgba.data()),
              static_cast<std::streamsize>(img.rgba.size() * sizeof(float)));
      if (in && in.peek() == std::char_traits<char>::eof()) return img;
    }
  }
  const Image img = render();
  std::filesystem::create_directories(dir);
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(&img.width), sizeof img.width);
    out.write(reinterpret_cast<const char*>(&img.height), sizeof img.height);
    out.write(reinterpret_cast<const char*>(img.rgba.data()),
              static_cast<std::streamsize>(img.rgba.size() * sizeof(float)));
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  });
  return img;
}

}  // namespace lt::test
