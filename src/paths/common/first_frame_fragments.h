// nothing_drawn.h for the paths GL rasterises (glsl, arbfp, combiners, flat, and the G-buffer of
// reference and half). They enable no face culling (nothing calls glEnable(GL_CULL_FACE)), so
// what leaves their frame empty is clipping: every triangle outside the view volume, or too
// small to cover a pixel centre. Their later passes test depth EQUAL against pass 0's, so they
// draw where pass 0 drew: the frame is empty exactly when pass 0 is.
//
// Measured with an occlusion query (GL_SAMPLES_PASSED, GL 1.5, which OSMesa has) around the
// first frame's draws, not by counting covered pixels afterwards: the query counts what GL
// itself let through clipping, rasterisation and the depth test, fragment by fragment, whatever
// colour each wrote, with no read-back and no notion of coverage a path would have to agree
// on. Only the first frame: reading the count waits for the rasteriser, which no timed frame may
// do, and the scene is static.
#pragma once

#include <cstddef>
#include <string>

#include "gl/gl.h"
#include "gl/scene_geometry.h"

namespace lt {

class FirstFrameFragments {
 public:
  // `who` names the path in the warning ("glsl", "the reference G-buffer").
  FirstFrameFragments(std::string who, const gl::SceneGeometry& geometry);
  // Around the draws of a frame: on the first, begin() starts the query and end() reads it and
  // warns (nothing_drawn.h) if no fragment passed. Later frames: no-ops.
  void begin();
  void end();

 private:
  std::string who_;
  std::size_t triangles_ = 0;
  GLuint query_ = 0;
  bool first_frame_ = true;
};

}  // namespace lt
