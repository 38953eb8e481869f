// STL: OpenMesh takes a file as binary when its size is 84 + 50 * (triangle count), and as
// ASCII otherwise, so a truncated binary file is parsed as text and yields nothing. Say so, and
// reject non-finite coordinates before its vertex-merging map compares NaNs.
#pragma once

#include <string>

#include "mesh/raw_mesh.h"

namespace lt::meshio {

// Checks an STL file (ascii or binary) before OpenMesh reads it.
void check_stl(const std::string& data, const std::string& file);

}  // namespace lt::meshio
