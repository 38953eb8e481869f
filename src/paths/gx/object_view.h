// The V and L that t=texgen and lobe=xf-spec hold constant over an object (issue 26). The
// translucency factor t = dot(V, -(L + N d)) is affine in the normal N only when V and L are the
// same at every vertex; the exact variants need an orthographic camera and directional lights
// for that. With :view=object they are taken once, at the object's centre C, as Wii games that
// drove this from the hardware did:
//   V = the unit vector from C to the eye (-forward under an orthographic camera),
//   L = the unit vector from C to a point light, or -direction for a directional light,
// and a point light's distance attenuation in lobe=xf-spec (whose XF light has no distance
// term) is the one at C. Everything else stays per vertex: the diffuse, and the distance
// attenuation of the LUT variants (the XF's). The error is the bench's
// (docs/porting-to-the-wii.md).
//
// The object is what one setup draws: in ltrender's emulator and `export gx`, every mesh drawn
// with the material (their bounding box's centre); a module's setup takes the meshes it is
// given, so a game that wants a V per mesh calls it once per mesh.
#pragma once

#include <glm/glm.hpp>

#include "paths/gx/gx_variant.h"
#include "scene/scene.h"

namespace lt::gx {

// The centre of the bounding box of every mesh drawn with `material` (world space): (lo + hi)
// x 0.5, exact in the inputs' float (the module's runtime computes it alike).
glm::dvec3 material_centre(const Scene& scene, int material);

struct ConstantView {
  glm::dvec3 V, L;
  double attenuation = 1;  // the light's distance attenuation at the centre (1: directional)
};

// V and L for t affine in the normal: with view=object at `centre` as above; without it the
// exact variants' (refusal() has made sure the camera is orthographic and the light directional):
// V = -forward, L = -direction.
ConstantView constant_view(const Scene& scene, const GxVariant& variant, const glm::dvec3& centre,
                           const Light& light);

}  // namespace lt::gx
