// PLY: our own reader. OpenMesh 9.0's PLY reader rounds coordinates to float (a sphere near
// 1e6 collapses onto a 1/16 grid), truncates float colours to 8 bits (0.5 comes back as
// 127/255), loops forever on a header without end_header, and skips list properties other than
// vertex_indices by a single value. The values are parsed here; the mesh is assembled through
// OpenMesh's ImporterT, the same face handling (non-manifold splitting) its readers use.
#pragma once

#include <string>

#include "mesh/raw_mesh.h"

namespace lt::meshio {

// Parses a PLY file (ascii or binary, either byte order) into arrays: positions in double,
// normals, colours (uchar as v/255, float as they are), faces with every index checked.
RawMesh parse_ply(const std::string& data, const std::string& file);

}  // namespace lt::meshio
