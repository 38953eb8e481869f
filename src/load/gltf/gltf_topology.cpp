#include "load/gltf/gltf_topology.h"

#include <tiny_gltf.h>

namespace lt::gltf {

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "POINTS";
    case TINYGLTF_MODE_LINE:
      return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
      return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
      return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES:
      return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN:
      return "TRIANGLE_FAN";
  }
  return "unknown";
}

bool carries_surface(int mode) {
  return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

std::optional<std::vector<glm::uvec3>> assemble_triangles(int mode,
                                                          const std::vector<std::uint32_t>& v) {
  const std::size_t n = v.size();
  std::vector<glm::uvec3> out;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (n % 3 != 0) return std::nullopt;
    for (std::size_t i = 0; i + 2 < n; i += 3) out.emplace_back(v[i], v[i + 1], v[i + 2]);
    return out;
  }
  if (n < 3) return std::nullopt;
  // glTF 2.0 §3.7.2.1, the table of primitive topologies (the formulas in the header): a strip's
  // odd triangles swap their last two vertices so every triangle winds as the first does, which
  // is also OpenGL's GL_TRIANGLE_STRIP order (GL 4.6 core §10.1.8).
  for (std::size_t i = 0; i + 2 < n; ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      out.emplace_back(v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]);
    } else {
      out.emplace_back(v[i + 1], v[i + 2], v[0]);
    }
  }
  return out;
}

std::string count_mismatch(int mode, std::size_t count, bool indexed) {
  const std::string what = std::to_string(count) + (indexed ? " indices" : " vertices");
  if (mode == TINYGLTF_MODE_TRIANGLES) return what + ", not a multiple of 3 for TRIANGLES";
  return what + ", fewer than the 3 a " + mode_name(mode) + " needs";
}

}  // namespace lt::gltf
