// Playing frames in Dolphin for the tests that hold the gx path to it (dolphin_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "image/image.h"
#include "judge/dolphin_player.h"
#include "paths/gx/fifo/frame_recording.h"

namespace lt::test {

// 4:3 with a width that is a multiple of 16: the size Dolphin dumps as it is (dolphin_player.h).
inline constexpr int kDolphinWidth = 320, kDolphinHeight = 240;

// Dolphin's picture of each of `frames` (all of `scene`'s objects and materials), played as one
// FIFO log: one Dolphin start for many frames. The log has a lead-in copy of the first frame and
// three trailing copies of the last (for_dolphin_animation), so Dolphin's dumps end at the log's
// last frame but one and frame k of K is dump D - 2 - K + k (dolphin_player.h). Empty, with a
// failure, when Dolphin dumped fewer than K + 2.
inline std::vector<Image> dolphin_pictures(const Scene& scene,
                                           const std::vector<gx::fifo::FrameInput>& frames) {
  const std::vector<std::uint8_t> log = gx::fifo::write_fifo_log(gx::fifo::for_dolphin_animation(
      gx::fifo::record_frames(scene, frames, {kDolphinWidth, kDolphinHeight})));
  judge::DolphinOptions options;
  const std::vector<Image> dumps = judge::play_fifo_log(log, options);
  const int K = static_cast<int>(frames.size()), D = static_cast<int>(dumps.size());
  if (D < K + 2) {
    ADD_FAILURE() << "Dolphin dumped " << D << " frames of a log of " << K + 4;
    return {};
  }
  return std::vector<Image>(dumps.end() - 2 - K, dumps.end() - 2);
}

// Pixels whose 8-bit RGB differ between two pictures of one size, and the largest difference.
struct PictureDifference {
  size_t differ = 0;
  int max = 0;
  int first_x = -1, first_y = -1;
};
inline PictureDifference picture_difference(const Image& a, const Image& b) {
  PictureDifference d;
  if (a.width != b.width || a.height != b.height) {
    ADD_FAILURE() << "pictures of " << a.width << "x" << a.height << " and " << b.width << "x"
                  << b.height;
    d.differ = a.pixel_count();
    return d;
  }
  for (size_t i = 0; i < a.pixel_count(); ++i) {
    int m = 0;
    for (size_t ch = 0; ch < 3; ++ch)
      m = std::max(m, std::abs(static_cast<int>(std::lround(a.rgba[i * 4 + ch] * 255.0f)) -
                               static_cast<int>(std::lround(b.rgba[i * 4 + ch] * 255.0f))));
    if (m == 0) continue;
    if (d.differ++ == 0) {
      d.first_x = static_cast<int>(i % static_cast<size_t>(a.width));
      d.first_y = static_cast<int>(i / static_cast<size_t>(a.width));
    }
    d.max = std::max(d.max, m);
  }
  return d;
}

}  // namespace lt::test
