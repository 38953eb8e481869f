// The rasteriser's per-pixel values (rasteriser.h raster_pixel, the definition) for a run of up
// to kPixelLanes covered pixels of one triangle at once, a pixel a float vector lane
// (raster_run_lanes.cpp, Highway, the best target the CPU has). A run may span rows (the pixel
// stage fills it from the triangle's rows of a band, so a small triangle's few pixels a row share
// one run). Each lane computes its pixel's value with the scalar's float operations in the
// scalar's order (the build contracts no multiply-add), and the conversions keep x86's truncation
// and its INT_MIN for NaN and out-of-range values, so every value is the scalar function's to the
// bit; tests/gx_raster_run_test.cpp holds the two together on every target.
#pragma once

#include "gx/rasteriser.h"

namespace lt::gx {

// The pixels of a run: lane i is pixel (x[i], y[i]). Lanes from `count` on hold any pixel (the
// last one repeated): they are computed like the others, and the caller ignores them.
struct RunPixels {
  alignas(64) s32 x[kPixelLanes] = {};
  alignas(64) s32 y[kPixelLanes] = {};
  int count = 0;
  bool full() const { return count == kPixelLanes; }
  void add(s32 px, s32 py) {
    x[count] = px;
    y[count] = py;
    ++count;
  }
  // Fills the lanes past `count` with the last pixel (count > 0).
  void pad() {
    for (int i = count; i < kPixelLanes; ++i) {
      x[i] = x[count - 1];
      y[i] = y[count - 1];
    }
  }
};

// What raster_pixel gives each lane's pixel.
struct RunValues {
  alignas(64) u32 z[kPixelLanes] = {};
  alignas(64) s32 color[kMaxChannels][4][kPixelLanes] = {};  // 0..255
  alignas(64) s32 uv[kMaxTexGens][2][kPixelLanes] = {};      // s17.7
};

// The depth of each lane's pixel: raster_pixel's z.
void run_depths(const Triangle& t, const RunPixels& pixels, RunValues& out);
// The colours and texture coordinates of each lane's pixel: the rest of raster_pixel. Like it,
// leaves the channels and texture coordinates beyond the triangle's counts as they were.
void run_attributes(const Triangle& t, const RunPixels& pixels, bool round_colors, RunValues& out);

}  // namespace lt::gx
