// A scene object's vertex stream as the port sends it (gx/vertex_stage.h VertexStream): its
// positions made camera-relative, its normals, its colour, the per-light t the port's CPU
// computes each frame, and its UVs. With a vertex storage (gx variant :vtx= :nrm= :clr= :uv=,
// gx/vertex_storage.h) the stream is the mesh as a port stores it: in the object's own
// coordinates, quantised as a converter does (gx/vertex_quantiser.h) and read back through the
// console's vertex loader (gx/vertex_loader.h), placed by the object's matrices.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gx/vertex_stage.h"
#include "gx/vertex_storage.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "scene/scene.h"

namespace lt::gx {

// The F32 stream: camera-relative positions, world-space normals (the camera's rotation is both
// matrices). The default variant's.
VertexStream make_vertex_stream(const Scene& scene, const SceneObject& object,
                                const SceneView& view);

// An object's mesh in its own coordinates, what a game stores: the scene's world-space mesh
// taken back through its transform (M^-1 p; normals A^T n renormalised, A the 3x3 part), in
// double, then float; and the matrices that place it: GX_PNMTX0 = R [A | t - eye] and the normal
// matrix R A^-T, in double, then float (R the camera's rotation, t the transform's move).
struct ObjectSpaceMesh {
  std::vector<glm::vec3> position, normal;
  ObjectMatrices matrices;
};
ObjectSpaceMesh object_space_mesh(const SceneObject& object, const SceneView& view);

// The stream of `object` stored as `storage` says: object-space positions and normals, the
// colour and UVs, and each light's t (one texture coordinate, its own fraction with /auto),
// each quantised, sent directly (or, `indexed`, as indices into arrays of the distinct stored
// elements, :draw=indexed, strips, list) and loaded by the vertex loader as the console does; eye
// positions and normals through the object's matrices as the XF computes them
// (gx/transform_unit.h). A value the storage cannot hold throws InputError(origin, key, ...).
VertexStream stored_vertex_stream(const Scene& scene, const SceneObject& object,
                                  const SceneView& view, const VertexStorage& storage,
                                  const std::string& origin, bool indexed = false);

// The variant's stream: make_vertex_stream for the default (F32) storage (an F32 array element
// reads back as the same float as the direct one), else stored_vertex_stream, indexed where
// :draw= sends indices (errors name "--variant").
VertexStream object_vertex_stream(const Scene& scene, const SceneObject& object,
                                  const SceneView& view, const GxVariant& variant);

// What pass `pass` sends of an object, as floats before storage, in the pass's texture
// coordinate slots: `positions` and `normals` (object space for a stored mesh), the stream's
// colours, UVs (GX_TEX_ST slots) and the pass's light's t (GX_TEX_S slots, one component).
// What the FIFO log stores and the budget counts.
VertexAttributeData pass_vertex_data(std::span<const glm::vec3> positions,
                                     std::span<const glm::vec3> normals, const VertexStream& stream,
                                     const VertexDescriptor& sent, const TexCoordFormats& formats,
                                     size_t pass);

// What a pass of `v` sends, as the pass's program declares it (plan_emitter.cpp vertex_format):
// the descriptor and texture coordinate kinds pass_vertex_data reads.
std::pair<VertexDescriptor, TexCoordFormats> planned_attributes(const VertexFormatPlan& v);

// What the generated programs declare for the scene's vertices (pass_plan.h
// VertexDeclarations): the variant's storage with each /auto fraction made the smallest any
// object and pass of `plan` gets, its t and UVs alike (a program file declares one storage a
// frame and one `uv`: the fraction that holds every one; it reads back to the /auto variant's
// frame where they all get the same), and under an indexed :draw= each array's index as
// index_attributes gives it (GX_INDEX16 where any object's array outgrows GX_INDEX8). The
// default variant's are returned without looking at the meshes. A value the storage cannot hold
// throws InputError("--variant", key, ...).
VertexDeclarations storage_declarations(const Scene& scene, const GxVariant& variant,
                                        const ScenePlan& plan);

}  // namespace lt::gx
