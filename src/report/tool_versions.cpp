#include "report/tool_versions.h"

#include <embree3/rtcore.h>

#include <chrono>
#include <csignal>
#include <exception>
#include <optional>

#include "core/child_process.h"
#include "core/fs.h"
#include "core/temp_file.h"
#include "core/version.h"
#include "gl/context.h"
#include "image/image_codec.h"
#include "judge/dolphin_player.h"

namespace lt {

namespace {

std::string gl_string(GLenum name) {
  const char* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "?";
}

// From the context current now (a command that renders has one), else from one made for it.
void read_gl(ToolVersions& v) {
  std::optional<gl::Context> own;
  if (!OSMesaGetCurrentContext()) own.emplace(1, 1);
  v.gl_version = gl_string(GL_VERSION);
  v.gl_renderer = gl_string(GL_RENDERER);
}

std::string embree_version() {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) return "? (no device)";
  // major * 10000 + minor * 100 + patch, as the library reports it.
  const auto v = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION);
  rtcReleaseDevice(device);
  return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
         std::to_string(v % 100);
}

// The first line of `dolphin-emu-nogui --version` ("Dolphin 5.0-17995-g8bad821019") without
// its "Dolphin "; empty when Dolphin is not installed or says nothing within its deadline.
std::string dolphin_version() {
  const std::filesystem::path exe = find_executable(judge::DolphinOptions{}.executable);
  if (exe.empty()) return "";
  const TempFile output("dolphin-version", ".txt", "", 0);
  if (!output.written()) return "";
  ChildProcess child({exe, {"--version"}, {}, output.path()});
  child.wait_until(ChildProcess::Clock::now() + std::chrono::seconds(5));
  child.stop(SIGTERM, std::chrono::milliseconds(200));
  std::string text = read_text_file(output.path());
  text = text.substr(0, text.find('\n'));
  const std::string prefix = "Dolphin ";
  return text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
}

ToolVersions measure() {
  ToolVersions v;
  v.ltrender = ltrender_version();
  // Each part on its own: a missing library says so in its place, never ends the line (or
  // --version, whose callback runs inside CLI11's parse).
  try {
    read_gl(v);
  } catch (const std::exception& e) {
    v.gl_version = std::string("? (") + e.what() + ")";
    v.gl_renderer = "?";
  }
  try {
    v.openimageio = image_codec().library_version();
  } catch (const std::exception& e) {
    v.openimageio = std::string("not loaded (") + e.what() + ")";
  }
  v.embree = embree_version();
  try {
    v.dolphin = dolphin_version();
  } catch (const std::exception&) {
    v.dolphin = "";  // could not be started: as good as not there
  }
  return v;
}

}  // namespace

const ToolVersions& tool_versions() {
  static const ToolVersions versions = measure();
  return versions;
}

std::string tool_versions_line(const ToolVersions& v) {
  return "ltrender " + v.ltrender + "; GL " + v.gl_version + " on " + v.gl_renderer +
         "; OpenImageIO " + v.openimageio + "; Embree " + v.embree + "; " +
         (v.dolphin.empty() ? "Dolphin not found" : "Dolphin " + v.dolphin);
}

}  // namespace lt
