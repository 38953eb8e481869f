// A scene object's vertex stream as the port sends it (gx/vertex_stage.h VertexStream): its
// positions made camera-relative, its normals, its colour, the per-light t the port's CPU
// computes each frame, and its UVs.
#pragma once

#include "gx/vertex_stage.h"
#include "paths/gx/generator.h"
#include "scene/scene.h"

namespace lt::gx {

VertexStream make_vertex_stream(const Scene& scene, const SceneObject& object,
                                const SceneView& view);

}  // namespace lt::gx
