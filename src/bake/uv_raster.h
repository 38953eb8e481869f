// Triangles rasterised in UV space, as a GPU would draw them into a texture: which triangle
// covers each texel centre, with the centre's barycentric coordinates; and the bake margin that
// grows the covered texels outwards across seams.
//
// The texel grid follows OpenGL (glTexImage2D's first row is t = 0): v = 0 is the BOTTOM row
// of the image. (glTF puts v = 0 at the top; its TEXCOORD_0 would need v -> 1 - v.) Texel (x, y),
// image row y counted from the top, has its centre at u = (x + 0.5) / W, v = 1 - (y + 0.5) / H;
// equivalently a point (u, v) lies in column u * W and row (1 - v) * H.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lt::bake {

struct UvCoverage {
  int width = 0, height = 0;
  // Per texel, row-major with row 0 at the top: the triangle that covers its centre (the lowest
  // index where several do), or -1.
  std::vector<std::int32_t> triangle;
  std::vector<glm::dvec3> barycentric;  // per texel, weights of the triangle's three corners
  std::size_t covered = 0;              // texels with a triangle
  std::size_t overlapping = 0;          // texels whose centre two or more triangles cover
  std::size_t degenerate_in_uv = 0;     // triangles without area in UV, covering nothing
};

// A texel centre is covered when it is inside the triangle or on an edge that is a top or left
// edge (the rule of D3D and OpenGL rasterisers): a centre on an edge shared by two triangles is
// drawn exactly once, so only genuinely overlapping UVs count as overlapping. Coordinates are
// snapped to 1/256 texel and the edge tests are exact integer arithmetic. Either winding.
UvCoverage rasterize_uv(const std::vector<glm::dvec2>& uvs,
                        const std::vector<glm::uvec3>& triangles, int width, int height);

// Blender's bake margin: `passes` times, every empty texel with a filled neighbour (of its 8)
// takes the mean of those neighbours' values from the previous pass, and is filled from then
// on. After N passes exactly the texels within N steps (Chebyshev distance) of the original
// ones are filled. Returns how many texels were added.
std::size_t dilate(std::vector<double>& values, std::vector<char>& filled, int width, int height,
                   int passes);

}  // namespace lt::bake
