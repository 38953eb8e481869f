#include "paths/common/gbuffer_layout.h"

#include <algorithm>

#include "gl/program.h"

namespace lt {

namespace {

bool takes_vertex_thickness(const Material& m) {
  return m.translucency && m.translucency->thickness_source == ThicknessSource::Vertex;
}

}  // namespace

GBufferLayout gbuffer_layout(const Scene& scene, const gl::SceneGeometry& geometry,
                             GreyThickness grey) {
  const auto& materials = scene.materials;
  GBufferLayout l;
  l.map_uv = std::any_of(materials.begin(), materials.end(), samples_uvs);
  const bool vertex_thickness =
      std::any_of(materials.begin(), materials.end(), takes_vertex_thickness);
  // The three channels of an interpolated grey are one computation three times over, so one
  // channel holds the same bits (tests/gbuffer_layout_test.cpp checks it). With a map the third
  // target is drawn anyway, and the thickness goes there whole.
  const bool all_grey =
      std::all_of(geometry.meshes().begin(), geometry.meshes().end(), [&](const gl::GpuMesh& m) {
        return m.grey_colors || !takes_vertex_thickness(materials[static_cast<size_t>(m.material)]);
      });
  l.grey_thickness = vertex_thickness && !l.map_uv && all_grey && grey == GreyThickness::OneChannel;
  l.rgb_thickness = vertex_thickness && !l.grey_thickness;
  return l;
}

std::string GBufferLayout::defines() const {
  return gl::glsl_define("LT_MAP_UV", map_uv) + gl::glsl_define("LT_RGB_THICKNESS", rgb_thickness) +
         gl::glsl_define("LT_GREY_THICKNESS", grey_thickness);
}

std::string GBufferLayout::description() const {
  std::string s = std::to_string(targets()) + " x RGBA32F (position + material, normal";
  if (map_uv) s += " + map u";
  if (grey_thickness) s += " + grey vertex thickness";
  if (rgb_thickness) s += ", vertex thickness";
  if (map_uv) s += rgb_thickness ? " + map v" : ", map v";
  return s + ")";
}

}  // namespace lt
