#include "paths/combiners/texgen_matrix.h"

#include "model/translucency.h"

namespace lt {

bool texgen_applicable(const Scene& scene, const Material& material) {
  return model::why_t_is_not_affine_in_the_normal(scene, material).empty();
}

glm::mat4 texgen_matrix(const Scene& scene, const Material& mat, const Light& light,
                        const LobeTable& table) {
  const glm::dmat3 view(scene.camera.view_from_origin());
  const glm::dvec3 V_eye = view * -scene.camera.forward();  // (0, 0, 1)
  const glm::dvec3 L_eye = view * -light.direction;
  const double d = mat.translucency->distortion;
  const double a = table.scale, b = table.offset;
  glm::dmat4 m(0.0);  // column-major: m[col][row]
  for (int c = 0; c < 3; ++c) m[c][0] = -d * V_eye[c] * a;
  m[3][0] = -glm::dot(V_eye, L_eye) * a + b;
  m[3][3] = 1;
  return glm::mat4(m);
}

}  // namespace lt
