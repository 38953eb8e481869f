// PLY writer: double positions (see write_mesh in mesh_io.h), float normals, float or 8-bit
// colours, texture coordinates as u, v (float when they all are floats, double otherwise), then
// the vertex properties the reader kept (quality, ...) in the types they came in.
#pragma once

#include <filesystem>
#include <string>

#include "mesh/raw_mesh.h"

namespace lt::meshio {

// Writes `mesh` as PLY into `tmp` (write_atomically's temporary); errors name `target`.
void write_ply(const std::filesystem::path& tmp, const std::filesystem::path& target,
               const PolyMesh& mesh, const OpenMesh::IO::Options& options,
               const std::vector<ExtraVertexProperty>& extras);

}  // namespace lt::meshio
