#include "gx/vertex_cost.h"

#include <algorithm>

namespace lt::gx {

DrawCost& DrawCost::operator+=(const DrawCost& o) {
  vertex_bytes = std::max(vertex_bytes, o.vertex_bytes);
  vertices += o.vertices;
  triangles += o.triangles;
  draws += o.draws;
  command_bytes += o.command_bytes;
  array_bytes += o.array_bytes;
  display_list_bytes += o.display_list_bytes;
  fifo_bytes += o.fifo_bytes;
  return *this;
}

std::size_t cache_lines_bytes(std::size_t bytes) {
  return (bytes + kCacheLineBytes - 1) / kCacheLineBytes * kCacheLineBytes;
}

std::vector<std::size_t> list_draw_counts(std::size_t vertices) {
  constexpr std::size_t most = kMaxBeginVertices / 3 * 3;
  std::vector<std::size_t> counts;
  for (std::size_t start = 0; start < vertices; start += most)
    counts.push_back(std::min(most, vertices - start));
  return counts;
}

std::vector<std::size_t> strip_draw_counts(std::size_t vertices) {
  constexpr std::size_t most =
      kMaxBeginVertices - 1;  // even: the next draw starts on an even index
  std::vector<std::size_t> counts;
  if (vertices < 3) return counts;
  // Each draw after the first starts two vertices back, on the last triangle's first two.
  for (std::size_t start = 0; start + 2 < vertices; start += most - 2)
    counts.push_back(std::min(most, vertices - start));
  return counts;
}

DrawCost immediate_list_cost(std::size_t triangles, std::size_t vertex_bytes) {
  DrawCost c;
  c.vertex_bytes = vertex_bytes;
  c.triangles = triangles;
  for (std::size_t n : list_draw_counts(3 * triangles)) {
    ++c.draws;
    c.vertices += n;
    c.command_bytes += kGxBeginBytes + n * vertex_bytes;
  }
  c.fifo_bytes = c.command_bytes;
  return c;
}

DrawCost immediate_strip_cost(std::size_t strip_vertices, std::size_t vertex_bytes) {
  DrawCost c;
  c.vertex_bytes = vertex_bytes;
  for (std::size_t n : strip_draw_counts(strip_vertices)) {
    ++c.draws;
    c.vertices += n;
    c.triangles += n - 2;
    c.command_bytes += kGxBeginBytes + n * vertex_bytes;
  }
  c.fifo_bytes = c.command_bytes;
  return c;
}

DrawCost indexed_cost(DrawCost c, const IndexedArrays& arrays) {
  for (int a : arrays.arrays)
    c.array_bytes += cache_lines_bytes(arrays.bytes[static_cast<size_t>(a)].size());
  c.fifo_bytes += 2 * kCpLoadBytes * arrays.arrays.size();
  return c;
}

DrawCost in_display_list(DrawCost c) {
  c.display_list_bytes = cache_lines_bytes(c.command_bytes);
  c.fifo_bytes = c.fifo_bytes - c.command_bytes + kCallDisplayListBytes;
  return c;
}

DrawCost display_list_strip_cost(std::size_t strip_vertices, std::size_t vertex_bytes,
                                 const IndexedArrays& arrays) {
  return indexed_cost(in_display_list(immediate_strip_cost(strip_vertices, vertex_bytes)), arrays);
}

}  // namespace lt::gx
