// From the XF's vertices to set-up triangles (gx-hardware.md §2.6): each vertex gets its
// clip-space position and its texture coordinates scaled by their texture's size, then each
// triangle of the draw, in the order the console receives it (GX_TRIANGLES: three vertices a
// triangle [DSW SetupUnit.cpp SetupTriangle]), is rejected, culled or clipped (clipper.h) and
// what is left set up for the rasteriser (rasteriser.h).
#pragma once

#include <vector>

#include "gx/gx_state.h"
#include "gx/rasteriser.h"
#include "gx/vertex_stage.h"

namespace lt::gx {

// What became of a draw's triangles (clipper.h TriangleFate), for the frame's warnings.
struct TriangleCounts {
  size_t submitted = 0, rejected = 0, culled = 0, clipped_away = 0;
  size_t set_up = 0;  // triangles handed to the rasteriser (after clipping, with any pixels)
  void add(const TriangleCounts& o);
};

// The vertices of one object in one pass as the setup unit receives them: `clip` from the
// transform unit (transform_unit.h), colours and texture coordinates from the XF (`outputs`),
// s and t multiplied by their coordinate's size [DSW TransformUnit.cpp TransformTexCoord,
// "*= (scale_minus_1 + 1)"] (a coordinate no stage sizes keeps the register's reset value,
// scale 1).
void make_raster_vertices(const std::vector<glm::vec4>& clip, const VertexOutputs& outputs,
                          const std::array<TexCoordScale, kMaxTexGens>& scales,
                          std::vector<RasterVertex>& out);

// Appends to `out` the set-up triangles of mesh triangles [first, last) under `state`'s cull
// mode, colour channel and texgen counts, their coverage under `rule` (rasteriser.h).
void setup_triangles(const std::vector<RasterVertex>& vertices,
                     const std::vector<glm::uvec3>& triangles, size_t first, size_t last,
                     const GxState& state, const Viewport& viewport, const Scissor& scissor,
                     CoverageRule rule, std::vector<Triangle>& out, TriangleCounts& counts);

}  // namespace lt::gx
