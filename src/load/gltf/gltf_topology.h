// Primitive topologies (glTF 2.0 §3.7.2.1, "mode"): which modes carry a surface, and the
// triangles a list, strip or fan of vertex indices stands for.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace lt::gltf {

// "POINTS" ... "TRIANGLE_FAN" for modes 0 to 6, "unknown" otherwise.
const char* mode_name(int mode);

// TRIANGLES (4), TRIANGLE_STRIP (5) and TRIANGLE_FAN (6) carry a surface; points and lines
// (0 to 3) do not: the term shades surfaces, so those primitives are skipped, not drawn.
bool carries_surface(int mode);

// The triangles of a surface mode over `indices` (the index accessor, or 0..n-1 without one),
// in the winding the spec gives each:
//   TRIANGLES       p_i = {v_3i, v_3i+1, v_3i+2}
//   TRIANGLE_STRIP  p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}   (every other one flipped, so all
//                                                             keep the first one's winding)
//   TRIANGLE_FAN    p_i = {v_i+1, v_i+2, v_0}
// std::nullopt when the count does not fit the mode (§3.7.2.1: a multiple of 3 for TRIANGLES,
// at least 3 for strips and fans); the caller names the pointer.
std::optional<std::vector<glm::uvec3>> assemble_triangles(
    int mode, const std::vector<std::uint32_t>& indices);

// What a count that does not fit says, e.g. "35 indices, not a multiple of 3 for TRIANGLES".
std::string count_mismatch(int mode, std::size_t count, bool indexed);

}  // namespace lt::gltf
