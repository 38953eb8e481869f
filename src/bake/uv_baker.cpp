#include "bake/uv_baker.h"

#include "bake/occlusion_tracer.h"
#include "bake/thickness_baker.h"
#include "bake/uv_raster.h"
#include "core/error.h"

namespace lt::bake {

UvBakeResult bake_uv(const std::vector<glm::dvec3>& positions,
                     const std::vector<glm::dvec3>& normals, const std::vector<glm::dvec2>& uvs,
                     const std::vector<glm::uvec3>& triangles, const BakeSettings& settings,
                     int width, int height, int margin, const Progress& progress) {
  validate(settings);
  LT_CHECK(normals.size() == positions.size() && uvs.size() == positions.size(),
           "one normal and one UV per vertex");
  LT_CHECK(width > 0 && height > 0 && margin >= 0, "texture size and margin");
  for (const auto& t : triangles) {
    LT_CHECK(t.x < positions.size() && t.y < positions.size() && t.z < positions.size(),
             "triangle index out of range");
  }
  const UvCoverage coverage = rasterize_uv(uvs, triangles, width, height);
  UvBakeResult result;
  result.width = width;
  result.height = height;
  result.covered = coverage.covered;
  result.overlapping = coverage.overlapping;

  // Unit normals, zero where the file has none (they then add nothing to the blend).
  std::vector<glm::dvec3> unit(normals.size(), glm::dvec3(0.0));
  for (std::size_t v = 0; v < normals.size(); ++v) {
    if (usable_normal(normals[v])) unit[v] = glm::normalize(normals[v]);
  }
  std::vector<RayOrigin> origins;
  std::vector<std::size_t> texel_of;  // per origin
  origins.reserve(coverage.covered);
  texel_of.reserve(coverage.covered);
  for (std::size_t i = 0; i < coverage.triangle.size(); ++i) {
    if (coverage.triangle[i] < 0) continue;
    const glm::uvec3& t = triangles[static_cast<std::size_t>(coverage.triangle[i])];
    const glm::dvec3& b = coverage.barycentric[i];
    const glm::dvec3 p = b.x * positions[t.x] + b.y * positions[t.y] + b.z * positions[t.z];
    glm::dvec3 n = b.x * unit[t.x] + b.y * unit[t.y] + b.z * unit[t.z];
    if (!usable_normal(n)) {
      n = glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
    }
    if (!usable_normal(n)) {
      ++result.texels_without_normal;
      continue;
    }
    origins.push_back({p, -glm::normalize(n), static_cast<std::uint64_t>(i)});
    texel_of.push_back(i);
  }

  OcclusionTracer tracer(positions, triangles, settings);
  const std::vector<double> occlusion = tracer.trace(origins, progress);
  result.max_distance = tracer.max_distance();
  result.epsilon = tracer.epsilon();
  result.threads = tracer.threads();
  result.build_seconds = tracer.build_seconds();
  result.trace_seconds = tracer.trace_seconds();
  if (tracer.casts_rays()) {
    result.rays_traced =
        static_cast<std::uint64_t>(origins.size()) * static_cast<std::uint64_t>(settings.rays);
  }

  result.occlusion.assign(coverage.triangle.size(), 0.0);
  result.filled.assign(coverage.triangle.size(), 0);
  for (std::size_t i = 0; i < coverage.triangle.size(); ++i) {
    result.filled[i] = coverage.triangle[i] >= 0 ? 1 : 0;
  }
  for (std::size_t k = 0; k < origins.size(); ++k) result.occlusion[texel_of[k]] = occlusion[k];
  result.margin = dilate(result.occlusion, result.filled, width, height, margin);
  return result;
}

Image thickness_image(const UvBakeResult& result, const ColorMap& map) {
  validate(map);
  Image image(result.width, result.height);
  for (std::size_t i = 0; i < result.occlusion.size(); ++i) {
    if (!result.filled[i]) continue;
    // The ColorMap is affine in the occlusion (lerp, then tint), so the margin's means of
    // occlusion are the means of the colours.
    const glm::dvec3 c = translucency(result.occlusion[i], map);
    float* px = &image.rgba[4 * i];
    px[0] = static_cast<float>(c.x);
    px[1] = static_cast<float>(c.y);
    px[2] = static_cast<float>(c.z);
    px[3] = 1.0f;
  }
  return image;
}

}  // namespace lt::bake
