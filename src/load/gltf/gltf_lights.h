// KHR_lights_punctual lights as the term's lights: directional and point, units converted, the
// extension's range falloff fitted by the GL/GX kc, kl, kq form; spot lights refused.
#pragma once

#include <glm/glm.hpp>

#include "load/gltf/gltf_document.h"
#include "load/gltf/gltf_notes.h"
#include "scene/scene.h"

namespace lt::gltf {

// The extension's lights are photometric (lux for directional, candela for point) and meant
// for a Lambert BRDF of albedo / pi (glTF 2.0 Appendix B): outgoing radiance = albedo / pi * E *
// cos. The term's diffuse is albedo * colour * cos, so the scene's linear intensity is the
// photometric value divided by pi, and an unranged point light is exactly inverse square
// (kc = kl = 0, kq = 1).
inline constexpr double kPhotometricToScene = 0.31830988618379067;  // 1 / pi

struct RangeFit {
  double kc = 0, kl = 0, kq = 1;
  double rms_window_error = 0;  // over [0, range], of |d^2 * att(d) - window(d)|
  double max_window_error = 0;  // its maximum over [0, range]
  double at_distance = 0;       // where, as a fraction of the range
};

// The extension's recommended falloff, window(d) / d^2 with window(d) = clamp(1 - (d/range)^4,
// 0, 1), approximated by 1 / (kc + kl d + kq d^2), the form GL and GX evaluate. The fit is the
// least-squares one in window units over [0, range] (the error relative to the inverse square
// law). The form is scale-free in d / range, and with kc, kl, kq >= 0 its optimum has kc = kl = 0
// (searched: any kc or kl > 0 darkens the near field, where window = 1, more than it shapes the
// fade), which leaves one constant window 1 / kq: the mean of window over [0, range], 4/5, so
// kq = 5/4. RMS error 0.27 of the inverse-square value, 0.2 near the light, 0.8 at the range;
// beyond it the spec's light is 0 and this one is not.
RangeFit fit_range_falloff(double range);

// The light /extensions/KHR_lights_punctual/lights/{index}, placed by its node's world matrix
// (the light shines down the node's -Z, §KHR_lights_punctual "Adding Light Instances to Nodes").
Light map_light(const Document& doc, int index, const glm::dmat4& world, Notes& notes);

}  // namespace lt::gltf
