#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "scene/scene_limits.h"

namespace lt {

glm::dmat4 Camera::view_from_origin() const {
  return glm::lookAt(glm::dvec3(0), forward(), up);
}

std::string over_limit_message(std::size_t count, const char* noun, std::size_t limit) {
  return std::to_string(count) + " " + noun + ", more than the limit of " + std::to_string(limit);
}

void check_vertex_thickness(const TriangleMesh& mesh, const std::string& file,
                            const std::string& where, const std::string& mesh_name) {
  for (size_t v = 0; v < mesh.colors.size(); ++v) {
    for (int c = 0; c < 3; ++c) {
      const double x = mesh.colors[v][c];
      if (x >= 0 && x <= kMaxColour) continue;
      std::string what = "vertex ";
      what.append(std::to_string(v))
          .append(" of ")
          .append(mesh_name)
          .append(" has colour component ")
          .append(nlohmann::json(x).dump())
          .append(", out of range for \"thickness\": \"vertex\" (allowed [")
          .append(nlohmann::json(0.0).dump())
          .append(", ")
          .append(nlohmann::json(kMaxColour).dump())
          .append("])");
      throw InputError(file, where, what);
    }
  }
}

bool samples_uvs(const Material& material) {
  return material.albedo_map || (material.translucency && material.translucency->thickness_source ==
                                                              ThicknessSource::Texture);
}

void check_uvs_for_material(const TriangleMesh& mesh, const Material& material,
                            const std::string& file, const std::string& where,
                            const std::string& mesh_name, const std::string& why_no_uvs) {
  if (!samples_uvs(material) || !mesh.uvs.empty()) return;
  const bool thickness = material.translucency && material.translucency->thickness_map;
  throw InputError(
      file, where,
      "material \"" + material.name + "\" samples the " +
          (thickness ? "thickness map " + material.translucency->thickness_map->file.string()
                     : "albedo map " + material.albedo_map->file.string()) +
          " but " + mesh_name + " has no texture coordinates (UVs)" +
          (why_no_uvs.empty() ? "" : ": " + why_no_uvs));
}

glm::dmat4 Transform::matrix() const {
  glm::dmat4 m(1.0);
  m = glm::translate(m, translate);
  m = glm::rotate(m, glm::radians(rotate_deg.z), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotate_deg.y), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotate_deg.x), glm::dvec3(1, 0, 0));
  m = glm::scale(m, scale);
  return m;
}

SceneNeeds scene_needs(const Scene& scene) {
  SceneNeeds n;
  for (const Light& l : scene.lights) {
    (l.type == Light::Type::Directional ? n.directional_lights : n.point_lights)++;
  }
  for (const SceneObject& o : scene.objects) {
    const Material& m = scene.materials[o.material];
    n.any_albedo_map |= m.albedo_map != nullptr;
    if (!m.translucency) continue;
    n.any_translucency = true;
    n.any_vertex_thickness |= m.translucency->thickness_source == ThicknessSource::Vertex;
    n.any_thickness_map |= m.translucency->thickness_source == ThicknessSource::Texture;
    n.any_ramp |= m.translucency->ramp != nullptr;
    n.any_normalized_h |= m.translucency->normalize_distorted_light;
  }
  n.ambient_light = scene.ambient_light != glm::dvec3(0);
  return n;
}

}  // namespace lt
