// Generates the GX program of every material and pass of a scene, as libogc calls (the one
// program representation, program/program_file.h): what a porter pastes into the game, what the
// emulator runs and what the budget counts. Three steps over one typed plan (pass_plan.h):
// plan_scene chooses, emit_programs writes the calls, describe_pass writes the note. Only what the
// scene uses is generated: a material without translucency gets one diffuse stage, a constant
// thickness needs no vertex colour, a flat lobe (power 0 or scale 0) no texture.
//
// One light's term in one pass (gx-hardware.md §5.2, with the scales made explicit):
//   COLOR0A0 = T' x clamp(att' * LC')       thickness x light colour x albedo (x tint), XF
//   COLOR1A1 = albedo x clamp(amb' + att'' * max(N.L, 0) * C'')   diffuse, XF
//   stage 0:  w  = lerp(a', 255, lobe)      a' = 255 a/(a+s): (a + s lobe)/(a+s), from the LUT
//   stage 1:  tr = w * COLOR0 << log2(st/sd)
//   stage 2:  out = (tr + COLOR1) << log2(sd)
// Every 8-bit quantity is scaled to use its full range: light colours are normalised to a
// maximum of 255, the rest of their magnitude moves into the XF distance attenuation (k / f),
// and the TEV scales (x1, x2, x4) restore it, so nothing saturates before the output does unless
// the scene needs more than x4 (reported per pass). Lights beyond the first add in further
// passes through the EFB blend (ONE, ONE).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gx/program/program_file.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/pass_plan.h"
#include "scene/scene.h"

namespace lt::gx {

// What the XF sees: positions relative to the eye (the camera-relative upload every path
// shares) and the world-to-eye rotation as the position and normal matrix.
struct SceneView {
  glm::dvec3 eye{0};
  glm::dmat3 view{1};  // world -> eye rotation

  static SceneView of(const Scene& scene);
  glm::dvec3 to_eye(const glm::dvec3& world_point) const { return view * (world_point - eye); }
};

struct GeneratedPrograms {
  ProgramFile file;  // top level: the LUT arrays; one function per material and pass
  // By function name: its light, stages and scales, and what saturates.
  std::map<std::string, std::string> notes;
};

// The choices for every material some object uses (pass_planner.cpp). Throws
// InputError("--variant", ...) where refusal() says the variant cannot be exact, and InputError
// naming the scene key for a ramp or thickness map GX cannot hold.
ScenePlan plan_scene(const Scene& scene, const GxVariant& variant);
// The plan as libogc calls (plan_emitter.cpp): the LUT and map arrays at the top, one function
// per material and pass, each commented with its note.
GeneratedPrograms emit_programs(const ScenePlan& plan);
// One pass's note (plan_notes.cpp): its light, stages, textures, scales and what saturates.
std::string describe_pass(const PassPlan& pass);

// emit_programs(plan_scene(scene, variant)).
GeneratedPrograms generate_programs(const Scene& scene, const GxVariant& variant);

}  // namespace lt::gx
