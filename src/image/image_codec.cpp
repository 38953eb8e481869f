#include "image/image_codec.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "core/run_time_files.h"

namespace lt {

namespace {

constexpr const char* kModuleName = "libltrender_imageio.so";

// Where to look: the build directory for a binary of this build, the installed module folder
// for an installed one (core/run_time_files.h).
std::vector<std::filesystem::path> module_candidates() {
  return {run_time_files::module_dir() / kModuleName};
}

const ImageCodec* load_codec() {
  std::string tried;
  for (const std::filesystem::path& candidate : module_candidates()) {
    std::error_code ec;
    if (!std::filesystem::exists(candidate, ec)) {
      tried += (tried.empty() ? "" : ", ") + candidate.string() + " (missing)";
      continue;
    }
    // RTLD_LOCAL: OpenImageIO's symbols stay inside the module. Never closed: the codec is a
    // static inside it, used until exit.
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      tried += (tried.empty() ? "" : ", ") + candidate.string() + " (" + (why ? why : "?") + ")";
      continue;
    }
    auto entry = reinterpret_cast<ImageCodecEntry>(dlsym(handle, kImageCodecEntry));
    if (entry) return entry();
    tried += (tried.empty() ? "" : ", ") + candidate.string() + " (no " + kImageCodecEntry + ")";
  }
  throw std::runtime_error(std::string("cannot load the image module ") + kModuleName + ": tried " +
                           tried);
}

}  // namespace

const ImageCodec& image_codec() {
  static const ImageCodec* codec = load_codec();  // a failed load throws again next time
  return *codec;
}

}  // namespace lt
