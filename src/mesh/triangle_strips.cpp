#include "mesh/triangle_strips.h"

#include <meshoptimizer.h>

#include "core/error.h"

namespace lt {

std::vector<std::uint32_t> triangle_strip(std::span<const std::uint32_t> triangles,
                                          std::size_t vertex_count) {
  LT_CHECK(triangles.size() % 3 == 0, "a triangle list holds three indices per triangle");
  if (triangles.empty()) return {};
  // meshopt_stripify wants its input in vertex-cache order ("the index buffer being converted
  // has to be optimized for vertex cache first" [meshoptimizer.h]). The order for strip-like
  // caches, whose strips are shorter: GX keeps no transformed vertex for reuse, its XF
  // transforms every vertex the stream sends (Dolphin's software renderer transforms each index
  // of a draw [DSW SWVertexLoader.cpp DrawCurrentBatch]), so a shorter strip is fewer FIFO bytes
  // and fewer XF vertices.
  std::vector<unsigned int> cache_order(triangles.size());
  meshopt_optimizeVertexCacheStrip(cache_order.data(), triangles.data(), triangles.size(),
                                   vertex_count);
  std::vector<unsigned int> strip(meshopt_stripifyBound(triangles.size()));
  const std::size_t n =
      meshopt_stripify(strip.data(), cache_order.data(), cache_order.size(), vertex_count, 0);
  strip.resize(n);
  return {strip.begin(), strip.end()};
}

std::vector<std::array<std::uint32_t, 3>> strip_triangles(std::span<const std::uint32_t> s) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::size_t k = 0; k + 2 < s.size(); ++k) {
    if (k % 2 == 0) out.push_back({s[k], s[k + 1], s[k + 2]});
    else out.push_back({s[k], s[k + 2], s[k + 1]});
  }
  return out;
}

}  // namespace lt
