// A run of covered G-buffer pixels of one row and one material, laid out as structure of
// arrays: what the CPU paths' vectorised shading (Highway, issue 39) loads a vector of lanes
// from. Lanes past `count` up to the next multiple of the vector width are copies of the first
// pixel (real values: no garbage denormal or NaN slows or traps a lane), and their results are
// dropped.
#pragma once

#include <cstddef>

namespace lt {

// At most this many pixels a run: a multiple of every vector width Highway targets on x86
// (4, 8, 16 floats; 2, 4, 8 doubles), and short enough for the arrays to stay in L1.
inline constexpr std::size_t kPixelRunCapacity = 64;

// Runs are padded to a multiple of this many lanes: the widest float vector on x86 (AVX-512).
inline constexpr std::size_t kPixelRunPadding = 16;

struct PixelRun {
  int material = 0;
  std::size_t count = 0;  // covered pixels in the run, 1 .. kPixelRunCapacity
  // G-buffer values: camera-relative position, interpolated normal, vertex thickness (x, y, z
  // each an array) and a map material's (u, v); (0, 0) in a scene without maps.
  alignas(64) float position[3][kPixelRunCapacity];
  alignas(64) float normal[3][kPixelRunCapacity];
  alignas(64) float thickness[3][kPixelRunCapacity];
  alignas(64) float uv[2][kPixelRunCapacity];
};

// What a path writes for each pixel of a run: linear RGB, one array a channel.
struct ShadedRun {
  alignas(64) float rgb[3][kPixelRunCapacity];
};

// `count` rounded up to a whole number of vectors of `lanes` lanes (lanes divides the capacity).
inline std::size_t padded_count(std::size_t count, std::size_t lanes) {
  return (count + lanes - 1) / lanes * lanes;
}

}  // namespace lt
