#include "regress/golden_key.h"

#include <cctype>
#include <optional>

#include "gl/context.h"

namespace lt {

namespace {

std::string gl_text(GLenum name) {
  const char* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}

// Letters and digits in lower case, '.', '-' and '_' kept, anything else '-'.
std::string key_characters(const std::string& s) {
  std::string out;
  for (char ch : s) {
    const unsigned char u = static_cast<unsigned char>(ch);
    out += std::isalnum(u) || ch == '.' || ch == '_' ? static_cast<char>(std::tolower(u)) : '-';
  }
  return out;
}

}  // namespace

std::string golden_key_from(const std::string& gl_renderer, const std::string& gl_version) {
  // "llvmpipe (LLVM 15.0.6, 256 bits)": the driver is the first word.
  const std::string driver = gl_renderer.substr(0, gl_renderer.find_first_of(" ("));
  // "4.5 (Compatibility Profile) Mesa 22.3.6": the Mesa release, when it says one.
  const size_t mesa = gl_version.find("Mesa ");
  const std::string release =
      mesa == std::string::npos
          ? ""
          : "-mesa-" + gl_version.substr(mesa + 5, gl_version.find(' ', mesa + 5) - (mesa + 5));
  const std::string key = key_characters((driver.empty() ? "unknown" : driver) + release);
  return key;
}

std::string renderer_golden_key() {
  std::optional<gl::Context> own;
  if (!OSMesaGetCurrentContext()) own.emplace(1, 1);
  return golden_key_from(gl_text(GL_RENDERER), gl_text(GL_VERSION));
}

}  // namespace lt
