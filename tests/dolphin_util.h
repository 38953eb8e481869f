// Playing frames in Dolphin for the tests that hold the gx path to it (dolphin_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "image/image.h"
#include "judge/dolphin_player.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/gx_variant.h"
#include "paths/path.h"
#include "render/camera_path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::test {

// 4:3 with a width that is a multiple of 16: the size Dolphin dumps as it is (dolphin_player.h).
inline constexpr int kDolphinWidth = 320, kDolphinHeight = 240;

// Dolphin's picture of each of `frames` (all of `scene`'s objects and materials), played as one
// FIFO log: one Dolphin start for many frames. The log has a blank lead-in frame and three blank
// trailing frames (for_dolphin_judging), so Dolphin's dumps end at the log's last frame but one
// and frame k of K is dump D - 2 - K + k (dolphin_player.h). Empty, with a failure, when Dolphin
// dumped other than K + 2 or K + 3, or its blank frames are not where that count puts them.
inline std::vector<Image> dolphin_pictures(const Scene& scene,
                                           const std::vector<gx::fifo::FrameInput>& frames) {
  const gx::FrameSize size{kDolphinWidth, kDolphinHeight};
  const std::vector<std::uint8_t> log = gx::fifo::write_fifo_log(
      gx::fifo::for_dolphin_judging(gx::fifo::record_frames(scene, frames, size), size));
  judge::DolphinOptions options;
  const std::vector<Image> dumps = judge::play_fifo_log(log, options);
  const int K = static_cast<int>(frames.size()), D = static_cast<int>(dumps.size());
  if (D < K + 2 || D > K + 3) {
    ADD_FAILURE() << "Dolphin dumped " << D << " frames of a log of " << K + 4;
    return {};
  }
  // The dumps are matched to frames by their count, so a frame Dolphin showed twice or never
  // would give frame k a neighbour's picture: the blank frames must be where the count puts them.
  // The last two dumps are blank frames, each one colour; with K + 3 so is the first, the lead-in
  // (docs/textures.md "What carried over").
  const auto blank = [](const Image& image) {
    for (size_t i = 4; i < image.rgba.size(); ++i)
      if (image.rgba[i] != image.rgba[i % 4]) return false;
    return true;
  };
  if (!blank(dumps[D - 1]) || !blank(dumps[D - 2]) || (D == K + 3 && !blank(dumps[0]))) {
    ADD_FAILURE() << "Dolphin's " << D << " dumps of a log of " << K + 4
                  << " frames are out of step with its frames (a frame shown twice or never)";
    return {};
  }
  return std::vector<Image>(dumps.end() - 2 - K, dumps.end() - 2);
}

// Dolphin's picture of frame k = `scenes[k]` through `variants[k]`, all in one log (as
// dolphin_pictures; `scenes` at the Dolphin size, the first one the log's scene). A frame with a
// non-empty `program_files[k]` draws that program file instead of the generated programs, read
// as `export --format dff --program` reads it (gx_path.cpp fifo_log: scene_programs_for).
inline std::vector<Image> dolphin_pictures_of(const std::vector<Scene>& scenes,
                                              const std::vector<std::string>& variants,
                                              const std::vector<std::string>& program_files = {}) {
  std::vector<gx::ScenePrograms> programs;
  for (size_t k = 0; k < scenes.size(); ++k)
    programs.push_back(gx::scene_programs_for(scenes[k], gx::parse_gx_variant(variants[k]),
                                              program_files.empty() ? "" : program_files[k]));
  std::vector<gx::fifo::FrameInput> inputs;
  for (size_t k = 0; k < scenes.size(); ++k)
    inputs.push_back({programs[k].variant, &programs[k], &scenes[k]});
  return dolphin_pictures(scenes.front(), inputs);
}

// The gx variants a scene is judged through: every listed variant the path renders it with,
// less :out=xfb (what the others are compared through) and :colors=round / :lights=round-each,
// which model Dolphin's shader backends, not its software renderer (docs/dolphin-judge.md).
// Less :coverage=console too: it models the console's sample point as dolphin-emu/hwtests
// measured it, where Dolphin's software renderer is known to differ (gx-hardware.md §2.6), so
// Dolphin cannot judge it; gx_raster_test.cpp holds it to the hwtests' cases instead.
// Plus :base=tev (not a listed variant: advise's search picks it), which asks the hardware for
// something the listed ones do not: an unlit COLOR0 and a konst colour in the LUT stage.
inline std::vector<std::string> judged_variants(const Scene& scene) {
  const PathInfo& gx = find_path("gx");
  std::vector<std::string> out;
  for (const VariantInfo& v : gx.variants) {
    if (v.name.find("out=") != std::string::npos || v.name.find("round") != std::string::npos ||
        v.name.find("coverage=") != std::string::npos)
      continue;
    if (gx.refusal(scene, v.name).empty()) out.push_back(v.name);
  }
  if (gx.refusal(scene, "t=vertex:base=tev").empty()) out.push_back("t=vertex:base=tev");
  return out;
}

// One frame to judge: a gx variant, the program file it reads ("" for the generated ones), and
// the frame of the camera path (render/camera_path.h) the scene is moved to (0: as it is).
struct JudgedFrame {
  std::string variant, program_file;
  int path_frame = 0;
};

// What one judged frame gave: ltrender's covered pixels, and how it differs from Dolphin's.
struct JudgedRow {
  size_t covered = 0;
  PictureDifference difference;
};

// The frames of one scene in a log that may hold several (expect_dolphins_pictures below), and
// the label its table rows and failures carry.
struct JudgedScene {
  const Scene* scene = nullptr;
  std::vector<JudgedFrame> frames;
  std::string label;
};

// Plays the frames of every one of `scenes` in one Dolphin start (one FIFO log: each frame is
// self-contained, so frames of other scenes can follow each other) and holds each dump to
// ltrender's `:out=xfb` picture of the same frame: zero pixels may differ. Prints one table row
// a frame (`| label | variant | covered | differing | max |`: docs/dolphin-judge.md is made from
// them). One start for many scenes: a Dolphin start and stop is ~0.7 s of the suite's time
// whatever the log holds (docs/testing.md "Test time"). The rows of scene s are rows[s].
inline std::vector<std::vector<JudgedRow>> expect_dolphins_pictures(
    const std::vector<JudgedScene>& scenes) {
  struct Frame {
    const Scene* scene;
    const JudgedFrame* judged;
    const std::string* label;
    size_t scene_index;
  };
  // Frame k's scene: the judged scene itself at path frame 0, else a moved copy (a seeded
  // scene's meshes are megabytes: copied only where the camera moves).
  size_t moves = 0;
  for (const JudgedScene& js : scenes)
    for (const JudgedFrame& f : js.frames) moves += f.path_frame != 0;
  std::vector<Scene> moved;
  moved.reserve(moves);  // no reallocation: frames point into it
  std::vector<Frame> frames;
  for (size_t s = 0; s < scenes.size(); ++s) {
    for (const JudgedFrame& f : scenes[s].frames) {
      if (f.path_frame != 0) moved.push_back(scene_on_camera_path(*scenes[s].scene, f.path_frame));
      frames.push_back(
          {f.path_frame != 0 ? &moved.back() : scenes[s].scene, &f, &scenes[s].label, s});
    }
  }
  std::vector<gx::ScenePrograms> programs;
  programs.reserve(frames.size());
  for (const Frame& f : frames)
    programs.push_back(gx::scene_programs_for(*f.scene, gx::parse_gx_variant(f.judged->variant),
                                              f.judged->program_file));
  std::vector<gx::fifo::FrameInput> inputs;
  for (size_t k = 0; k < frames.size(); ++k)
    inputs.push_back({programs[k].variant, &programs[k], frames[k].scene});
  std::vector<std::vector<JudgedRow>> rows(scenes.size());
  if (frames.empty()) {
    ADD_FAILURE() << "no frame to judge";
    return rows;
  }
  const std::vector<Image> dolphin = dolphin_pictures(*frames.front().scene, inputs);
  if (dolphin.size() != frames.size()) {
    ADD_FAILURE() << "Dolphin gave " << dolphin.size() << " pictures for " << frames.size()
                  << " frames";
    return rows;
  }
  for (size_t k = 0; k < frames.size(); ++k) {
    const JudgedFrame& f = *frames[k].judged;
    PathOptions options;
    options.program_file = f.program_file;
    const Image ours = render_scene(*frames[k].scene, "gx", f.variant + ":out=xfb", kDolphinWidth,
                                    kDolphinHeight, options);
    const std::string name =
        f.variant + (f.program_file.empty() ? "" : " --program (edited)") +
        (f.path_frame == 0 ? "" : " (camera path frame " + std::to_string(f.path_frame) + ")");
    const JudgedRow row{covered_pixels(ours), picture_difference(ours, dolphin[k])};
    const std::string& label = *frames[k].label;
    std::printf("| %s | %s | %zu | %zu | %d |\n", label.c_str(), name.c_str(), row.covered,
                row.difference.differ, row.difference.max);
    EXPECT_EQ(row.difference.differ, 0u)
        << label << ", " << name << ": first at " << row.difference.first_x << ","
        << row.difference.first_y << ", max " << row.difference.max << " LSB";
    rows[frames[k].scene_index].push_back(row);
  }
  return rows;
}

// The same for the frames of one scene.
inline std::vector<JudgedRow> expect_dolphins_pictures(const Scene& scene,
                                                       const std::vector<JudgedFrame>& frames,
                                                       const std::string& label) {
  return expect_dolphins_pictures(std::vector<JudgedScene>{{&scene, frames, label}}).front();
}

}  // namespace lt::test
