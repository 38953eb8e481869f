// The rasteriser's per-pixel values (rasteriser.h raster_pixel, the definition) for kPixelLanes
// pixels of one row at once, a pixel a float vector lane (raster_span_lanes.cpp, Highway, the best
// target the CPU has). Each lane computes its pixel's value with the scalar's float operations in
// the scalar's order (the build contracts no multiply-add), and the conversions keep x86's
// truncation and its INT_MIN for NaN and out-of-range values, so every value is the scalar
// function's to the bit; tests/gx_raster_span_test.cpp holds the two together on every target.
#pragma once

#include "paths/gx/rasteriser.h"

namespace lt::gx {

// Pixels x .. x + kPixelLanes - 1 of row y, a lane each; lanes past the triangle's span are
// computed like the others, and a caller ignores them.
struct SpanValues {
  alignas(64) u32 z[kPixelLanes] = {};
  alignas(64) s32 color[kMaxChannels][4][kPixelLanes] = {};  // 0..255
  alignas(64) s32 uv[kMaxTexGens][2][kPixelLanes] = {};      // s17.7
};

// The depth of each lane's pixel: raster_pixel's z.
void span_depths(const Triangle& t, s32 x, s32 y, SpanValues& out);
// The colours and texture coordinates of each lane's pixel: the rest of raster_pixel. Like it,
// leaves the channels and texture coordinates beyond the triangle's counts as they were.
void span_attributes(const Triangle& t, s32 x, s32 y, bool round_colors, SpanValues& out);

}  // namespace lt::gx
