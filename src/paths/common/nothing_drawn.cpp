#include "paths/common/nothing_drawn.h"

#include "core/error.h"

namespace lt {

namespace {

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Why no pixel was written, from the first stage that removed everything.
std::string cause(const PassOutcome& p) {
  if (p.fragments_only)
    return "no fragment of its " + count(p.triangles, "triangle", "triangles") +
           " passed (GL_SAMPLES_PASSED 0; no face culling is enabled): all outside the view "
           "volume (clipped away) or covering no pixel centre";
  if (p.culled == p.triangles)
    return "all " + count(p.triangles, "triangle", "triangles") + " culled by " + p.cull_mode;
  if (p.culled + p.outside == p.triangles) {
    if (p.culled == 0)
      return "all " + count(p.triangles, "triangle", "triangles") +
             " outside the view volume (clipped away)";
    return "all " + count(p.triangles, "triangle", "triangles") + " culled (" +
           std::to_string(p.culled) + ", by " + p.cull_mode + ") or outside the view volume (" +
           std::to_string(p.outside) + ")";
  }
  if (p.pixels == 0)
    return count(p.triangles - p.culled - p.outside, "triangle", "triangles") +
           " left after culling and clipping covered no pixel centre";
  if (p.alpha_failed == 0)
    return "all " + count(p.pixels, "covered pixel", "covered pixels") + " failed the depth test";
  if (p.depth_failed == 0)
    return "all " + count(p.pixels, "covered pixel", "covered pixels") + " failed the alpha test";
  return "all " + count(p.pixels, "covered pixel", "covered pixels") + " failed the depth test (" +
         std::to_string(p.depth_failed) + ") or the alpha test (" + std::to_string(p.alpha_failed) +
         ")";
}

}  // namespace

std::string nothing_drawn_warning(const PassOutcome& p) {
  if (p.triangles == 0 || p.written > 0) return "";
  return p.path + " " + p.pass + " drew nothing: " + cause(p);
}

bool warn_if_nothing_drawn(const PassOutcome& pass) {
  const std::string warning = nothing_drawn_warning(pass);
  if (warning.empty()) return false;
  print_warning(warning);
  return true;
}

}  // namespace lt
