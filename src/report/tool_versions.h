// Which ltrender made a figure, and with what: its version and the versions of the libraries
// and programs it runs with, as they report themselves at run time (not the headers it was
// built against: the Debian package follows the machine's Mesa). One line, the same in
// `ltrender --version`, the bench report, the regress page and the JUnit XML's properties, so a
// CI log says which ltrender and which Mesa made a golden or a budget figure.
#pragma once

#include <string>

namespace lt {

struct ToolVersions {
  std::string ltrender;     // "0.1.0 (git 6831d86)" (core/version.h)
  std::string gl_version;   // OSMesa's GL_VERSION: "4.5 (Compatibility Profile) Mesa 22.3.6"
  std::string gl_renderer;  // OSMesa's GL_RENDERER: "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string openimageio;  // "2.4.7", or why the image module did not load
  std::string embree;       // "3.13.5"
  std::string dolphin;      // "5.0-17995-g8bad821019"; empty: not found
};

// Measured once a process (a GL context, the image module, an Embree device, `dolphin-emu-nogui
// --version` bounded to a few seconds) and kept.
const ToolVersions& tool_versions();

// "ltrender 0.1.0 (git 6831d86); GL 4.5 (...) Mesa 22.3.6 on llvmpipe (...); OpenImageIO 2.4.7;
// Embree 3.13.5; Dolphin 5.0-17995-g8bad821019" ("Dolphin not found" without it).
std::string tool_versions_line(const ToolVersions& versions);
inline std::string tool_versions_line() {
  return tool_versions_line(tool_versions());
}

}  // namespace lt
