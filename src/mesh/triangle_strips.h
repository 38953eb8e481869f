// An indexed triangle list as one triangle strip, the way a Wii port draws a mesh: the list is
// put in vertex-cache order, stripified and the strips joined by degenerate triangles, all by
// meshoptimizer (Debian's libmeshoptimizer-dev: meshopt_optimizeVertexCacheStrip, meshopt_stripify
// with restart index 0, "to use degenerate triangles"). GX has no primitive restart, so the
// joins are degenerate triangles, which the setup unit culls as zero-area.
//
// A strip's triangle k (starting at index k) is (s[k], s[k+1], s[k+2]) for even k and
// (s[k], s[k+2], s[k+1]) for odd k [DSW SetupUnit.cpp SetupTriStrip] [DHW IndexGenerator.cpp
// AddStrip "index + i - !wind, index + i - wind"]: every triangle keeps the list's winding, but
// its vertices may come in another rotation than the list's, so the rasteriser's planes (taken
// from vertex 0, rasteriser.h) may move a pixel by float rounding.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace lt {

// `triangles` holds three vertex indices per triangle (each below `vertex_count`); the strip's
// indices. An empty list gives an empty strip.
std::vector<std::uint32_t> triangle_strip(std::span<const std::uint32_t> triangles,
                                          std::size_t vertex_count);

// The triangles a strip draws, in order, degenerate ones (two equal indices) included.
std::vector<std::array<std::uint32_t, 3>> strip_triangles(std::span<const std::uint32_t> strip);

}  // namespace lt
