// Which channel of the CPU paths' G-buffer targets (RGBA32F each) carries what: the fewest
// targets the scene's materials need, since each one costs llvmpipe 3-4 ms a frame at 1280x720
// and 14.7 MB of read-back (issue 39). legacy_shaders/glsl/gbuffer.frag writes them:
//   0: camera-relative position; material index + 1 (cleared to 0: 0 = nothing covered)
//   1: interpolated normal; map u, or a grey vertex thickness, or 0
//   2 (only with a map or a coloured vertex thickness): vertex thickness rgb (or 0); map v
// A channel no material reads is written 0 and its varying is not interpolated.
#pragma once

#include <string>

#include "gl/scene_geometry.h"
#include "scene/scene.h"

namespace lt {

// Whether a grey vertex thickness may travel in one channel (the default), or always in three:
// the tests hold the one against the three, bit for bit.
enum class GreyThickness { OneChannel, ThreeChannels };

struct GBufferLayout {
  bool map_uv = false;          // a material samples a map: u in target 1, v in target 2
  bool rgb_thickness = false;   // a material takes its thickness from the vertex colour: target 2
  bool grey_thickness = false;  // ... and every such colour is grey, with no map: target 1 alone

  int targets() const { return map_uv || rgb_thickness ? 3 : 2; }
  // The #defines gbuffer.vert and gbuffer.frag are built with.
  std::string defines() const;
  // What `info` names the targets by, e.g. "2 x RGBA32F (position + material, normal)".
  std::string description() const;
};

GBufferLayout gbuffer_layout(const Scene& scene, const gl::SceneGeometry& geometry,
                             GreyThickness grey = GreyThickness::OneChannel);

}  // namespace lt
