// The combiners path's t=texgen variant: t from texgen NORMAL_MAP through the texture matrix,
// where t is affine in the normal.
#pragma once

#include <glm/glm.hpp>

#include "paths/combiners/lobe_table.h"
#include "scene/scene.h"

namespace lt {

// t = dot(V, -(L + N d)) is affine in the eye-space normal (model's rule).
bool texgen_applicable(const Scene& scene, const Material& material);

// texgen NORMAL_MAP yields the eye-space normal n (q = 1 from the current texcoord). With V
// and L constant in eye space, t = -V.L - d (V.n) is one row of the texture matrix, followed by
// the lobe table's coordinate (the power LUT's texel-centre remap u = t (N-1)/N + 0.5/N, or a
// ramp's u = t; lobe_table.h). The matrix for GL_TEXTURE of unit 0 (the caller loads it).
glm::mat4 texgen_matrix(const Scene& scene, const Material& material, const Light& light,
                        const LobeTable& table);

}  // namespace lt
