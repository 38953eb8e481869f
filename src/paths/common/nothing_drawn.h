// A frame with nothing drawn is never silent (issue 40). A GX program that sets no cull mode
// keeps GX_Init's GX_CULL_BACK, which removes the faces GL calls front (gx_state.h): the
// console shows the background and says nothing, and so did ltrender, so a porter saw a black
// frame and no reason. When every triangle a pass submitted is culled, outside the view, or every
// pixel it covered fails the depth or alpha test, one warning on stderr names the path, the
// pass, the count and the cause (for culling: the mode in force and where it came from).
#pragma once

#include <cstddef>
#include <string>

namespace lt {

// What became of one pass's triangles and pixels in one frame.
struct PassOutcome {
  std::string path;              // "gx"
  std::string pass;              // "pass 0 (material jade: generated)"
  std::size_t triangles = 0;     // submitted
  std::size_t culled = 0;        // removed by the cull mode
  std::size_t outside = 0;       // rejected or clipped away: wholly outside the view volume
  std::size_t pixels = 0;        // covered by the triangles left
  std::size_t depth_failed = 0;  // of those, failed the depth test
  std::size_t alpha_failed = 0;  // passed it, failed the alpha test
  std::size_t written = 0;       // reached the framebuffer
  std::string cull_mode;         // the mode in force and its source, for the culled cause
  // GL's paths count fragments alone (first_frame_fragments.h): `written` is the samples that
  // passed, the triangles' fates are GL's and unknown.
  bool fragments_only = false;
};

// The warning for a pass that submitted triangles and wrote no pixel, without the
// "ltrender: warning: " prefix; empty when the pass drew something or had nothing to draw.
std::string nothing_drawn_warning(const PassOutcome& pass);

// Prints nothing_drawn_warning(pass) on stderr, if there is one; true if it printed.
bool warn_if_nothing_drawn(const PassOutcome& pass);

}  // namespace lt
