// The thickness bake in UV space: the same inverted-normal rays as the vertex bake
// (occlusion_tracer.h), cast from every texel centre a triangle covers, into a thickness map
// (the addendum's teapot map: "make sure your mesh is properly UV-unwrapped").
//
// Each texel centre covered in UV (uv_raster.h; v = 0 is the bottom row) gets the position and
// normal interpolated barycentrically from its triangle's corners; its rays are seeded by the
// texel's index, so the map is the same whatever the thread count. A bake margin then grows
// the covered texels across seams (uv_raster.h's dilate), and the ColorMap turns occlusion into
// translucency as for vertex colours.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "bake/bake_settings.h"
#include "image/image.h"

namespace lt::bake {

struct UvBakeResult {
  int width = 0, height = 0;
  // Per texel, row 0 at the top: occlusion in [0, 1] where filled (covered or margin), else 0.
  std::vector<double> occlusion;
  std::vector<char> filled;
  std::size_t covered = 0;                // texels a triangle covers (rays cast there)
  std::size_t margin = 0;                 // texels the margin added
  std::size_t overlapping = 0;            // texels two or more triangles cover (overlapping UVs)
  std::size_t texels_without_normal = 0;  // covered, but no usable normal: occlusion 0, no rays
  double max_distance = 0.0;
  double epsilon = 0.0;
  std::uint64_t rays_traced = 0;
  int threads = 1;
  double build_seconds = 0.0;
  double trace_seconds = 0.0;
};

// `uvs` one per vertex; width and height >= 1; margin >= 0 texels. A vertex normal that is
// zero or not finite contributes nothing to the interpolation; where the interpolated normal
// has no direction, the triangle's own (from its winding) is used, and where that has none
// either (a triangle without area in 3D) the texel is unoccluded.
UvBakeResult bake_uv(const std::vector<glm::dvec3>& positions,
                     const std::vector<glm::dvec3>& normals, const std::vector<glm::dvec2>& uvs,
                     const std::vector<glm::uvec3>& triangles, const BakeSettings& settings,
                     int width, int height, int margin, const Progress& progress = {});

// The map as an image: RGB = translucency (ColorMap) of filled texels, A = 1 there; empty
// texels are (0, 0, 0, 0).
Image thickness_image(const UvBakeResult& result, const ColorMap& map);

}  // namespace lt::bake
