// A scene's geometry on the GPU, shared by every GL path. Positions are uploaded relative to the
// camera eye (camera-relative rendering): world coordinates near 1e6 would lose everything below
// 0.06 in float, but their offsets from a nearby eye are small and keep full float precision.
// Transforms are done in double on the CPU first.
//
// All paths read the same conventional arrays (gl_Vertex / vertex.position, gl_Normal, gl_Color)
// and the same fixed-function MODELVIEW/PROJECTION matrices, so GLSL (ftransform), ARB programs
// (position_invariant) and fixed-function all rasterise exactly the same pixels.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "gl/gl.h"
#include "gl/pixel_rect.h"
#include "scene/scene.h"

namespace lt::gl {

// The texture coordinate set that carries a mesh's UVs (gl_MultiTexCoord1, vertex.texcoord[1]):
// unit 0's set is the combiners' per-vertex t, so a thickness map's stage takes unit 1 and its
// coordinates with it.
inline constexpr int kUvTexCoordSet = 1;

// How far, in pixels, SceneGeometry::covered_rect reaches past the projected vertices: GL
// projects them in float and snaps them to its sub-pixel grid, the bound in double; their
// difference is a small fraction of a pixel.
inline constexpr int kCoveredRectMargin = 2;

struct GpuMesh {
  GLuint positions = 0, normals = 0, colors = 0, uvs = 0, indices = 0;
  GLsizei index_count = 0;
  int material = 0;
  bool has_colors = false;
  // Every colour GL reads has red = green = blue (as floats), or the mesh has none (white): an
  // interpolated grey needs one channel where three would carry the same value (the CPU paths'
  // G-buffer packs it so; issue 39).
  bool grey_colors = true;
  bool has_uvs = false;  // uploaded only where the material samples a map (samples_uvs)
  size_t vertex_count = 0;
};

class SceneGeometry {
 public:
  // Needs a current context. `width`/`height` give the aspect ratio of the projection.
  SceneGeometry(const Scene& scene, int width, int height);
  ~SceneGeometry();
  SceneGeometry(const SceneGeometry&) = delete;
  SceneGeometry& operator=(const SceneGeometry&) = delete;

  const std::vector<GpuMesh>& meshes() const { return meshes_; }
  // The eye, subtracted from every position: lights go through to_camera_relative too.
  glm::dvec3 origin() const { return origin_; }
  glm::dvec3 to_camera_relative(const glm::dvec3& world) const { return world - origin_; }

  // Every pixel a triangle of the scene can cover lies in this rectangle (with a margin of
  // kCoveredRectMargin pixels for float against double); the whole viewport when a vertex is
  // nearer the eye than half the near plane (it may be behind the eye, where a projection no
  // longer bounds). The CPU paths clear and read back only these pixels of their G-buffer.
  PixelRect covered_rect() const { return covered_rect_; }

  // Loads PROJECTION and MODELVIEW (camera-relative view) into fixed-function state.
  void load_matrices() const;
  // Binds the conventional vertex arrays of one mesh; colours only where the mesh has them, UVs
  // (texture coordinate set kUvTexCoordSet) only where its material reads a map.
  void bind(const GpuMesh& mesh) const;
  void draw(const GpuMesh& mesh) const;
  void unbind() const;

 private:
  std::vector<GpuMesh> meshes_;
  glm::dvec3 origin_;
  glm::dmat4 projection_, view_;
  PixelRect covered_rect_;
};

// Replaces an array buffer's contents with vertex data made on the CPU every frame (the combiners
// and gx paths light per vertex there), leaving it bound.
void stream_array_buffer(GLuint buffer, const std::vector<float>& data);

}  // namespace lt::gl
