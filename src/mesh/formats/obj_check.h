// OBJ: checked line by line, then read by OpenMesh. Its reader indexes its arrays with the
// file's indices unchecked (index 0, or one past the end, writes outside the mesh), skips a
// vertex whose numbers it cannot parse (shifting every later index), gives normals only to
// vertices that a face corner names (isolated ones keep uninitialised memory), and sets colours
// by position in a list that skips uncoloured vertices. So indices are checked here, and the
// normals and colours OpenMesh could not be trusted with are taken from this pass. Texture
// coordinates (vt) must be finite and their indices in range, and either every face corner
// names one or none does.
#pragma once

#include <string>

#include "mesh/raw_mesh.h"

namespace lt::meshio {

// Checks an OBJ file before OpenMesh reads it; returns its vertex count, which vertices a face
// gives a normal, and the colours when every vertex has one.
FileFacts check_obj(const std::string& text, const std::string& file);

}  // namespace lt::meshio
