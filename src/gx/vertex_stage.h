// What the vertex stage of the GX pipeline produces for one object in one pass: the XF's two
// channel colours and its generated texture coordinates, per vertex. The inputs are what the
// port sends as the vertex stream (gx.md §2: the scene supplies geometry, normals, vertex colours
// and matrices; paths/gx/scene_vertices.h makes a scene object's): camera-relative positions and
// world-space normals as GX_F32, the mesh's colour as GX_RGBA8 CLR0, and in its texture
// coordinates the pass's t (GX_TEX_S) or the mesh's UV (GX_TEX_ST), as the program's vertex
// format names them (gx_state.h TexCoordFormats); or, for a stored mesh, what the vertex loader
// read of each object's own coordinates, with the object's matrices (ObjectMatrices).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "gx/gx_state.h"

namespace lt::gx {

// GX_PNMTX0 and its normal matrix as a port loads them for one object whose vertices are sent in
// its own coordinates (a stored mesh, paths/gx/scene_vertices.h stored_vertex_stream).
struct ObjectMatrices {
  std::array<float, 12> position{};  // 3 rows of 4: object to eye
  std::array<float, 9> normal{};     // 3 rows of 3: the inverse transpose of its 3x3 part
};

// The vertex stream of one object, fixed for the scene (built once).
struct VertexStream {
  std::vector<glm::vec3> position;                  // camera-relative (what GX_VA_POS sends)
  std::vector<glm::vec3> normal;                    // world space, as the mesh has it (GX_VA_NRM)
  std::vector<glm::vec3> eye_position, eye_normal;  // after the position / normal matrix
  std::vector<Color8> color;  // GX_VA_CLR0: the mesh colour, white where it has none
  // GX_VA_TEX0 per light: t = dot(V, -H) unsaturated, computed on the CPU in double (the part
  // of the term that stays on the CPU in a port; the sampler's clamp saturates it per pixel).
  std::vector<std::vector<float>> t_per_light;
  // The mesh's UVs as GX_F32 (v = 0 at the map's bottom row); empty when the mesh has none.
  std::vector<glm::vec2> uv;
  // Set when the stream is in object space (a stored mesh): the matrices that place it, from
  // which eye_position and eye_normal are computed. Unset: the camera's rotation (positions
  // camera-relative, the F32 stream).
  std::optional<ObjectMatrices> object_matrices;
};

struct VertexOutputs {
  std::vector<std::array<Color8, kMaxChannels>> colors;
  std::vector<std::array<glm::vec3, kMaxTexGens>> texcoords;  // (s, t, q)
  int num_texgens = 0;
};

// Runs the XF (lighting and texgen) of `state` on every vertex; `light` picks GX_VA_TEX0's t.
void run_vertex_stage(const GxState& state, const VertexStream& stream, size_t light,
                      LightRounding rounding, VertexOutputs& out);

}  // namespace lt::gx
