// `ltrender sweep`: a path's variants against the reference over the frames of the camera path
// (render/camera_path.h), the error a port has while the camera and lights move rather than in
// the one view of the scene file. Each frame is rendered and compared as the bench does
// (render/evaluate.h); the figures over the frames are
//   max:  the largest error of any covered channel in any frame,
//   mean: the mean over every covered channel of every frame (each frame's mean weighted by its
//         covered pixels),
//   p99:  the largest of the frames' 99th percentiles (the worst frame's).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "paths/path.h"
#include "report/bench.h"
#include "scene/scene.h"

namespace lt {

struct SweepOptions {
  std::vector<std::filesystem::path> scenes;
  std::string path = "gx";
  VariantSelection variants = VariantSelection::All;
  int frames = 8;
  int width = 0, height = 0;  // 0: the scene's
  // gx: each variant measured a second time with `:light-range=` this (gx_variant.h), the TEV
  // scales from the declared bound instead of the scan; empty: not.
  std::string light_range;
  // Called before each scene (for a progress line); may be empty.
  std::function<void(const std::string& scene)> progress;
};

struct SweepRow {
  std::string scene;  // the file's stem
  std::string variant;
  std::string refused;  // why the path refuses the variant for this scene; empty: measured
  int frames = 0;
  double max_lsb = 0, mean_lsb = 0, p99_lsb = 0;
};

// Throws InputError for an unknown path or a scene that does not load.
std::vector<SweepRow> run_sweep(const SweepOptions& options);

// The rows as a Markdown table: scene, variant, max, mean, p99 (a refused variant: its reason).
std::string sweep_markdown(const std::vector<SweepRow>& rows);

}  // namespace lt
