// After reading: the checks every format shares (a mesh with faces, finite positions and
// colours, the file's normals kept where usable and the rest recomputed, each repair counted in
// the warnings).
#pragma once

#include <cstddef>
#include <string>

#include "mesh/poly_mesh.h"
#include "mesh/raw_mesh.h"

namespace lt::meshio {

// The importer copies the vertices of a face it cannot add without breaking the manifold
// structure; the copies get the position but neither the normal nor the colour. Finds each
// copy's original by its (exactly copied) position and gives it the original's attributes.
// Returns how many copies there are.
std::size_t repair_split_vertices(PolyMesh& mesh, const OpenMesh::IO::Options& opts,
                                  FileFacts& facts);

// Throws InputError for an empty mesh, a mesh without faces, non-finite positions or colours;
// applies the colours the check parsed; normalises or recomputes normals; adds the warnings.
void finish_loaded_mesh(LoadedMesh& loaded, const std::string& file, FileFacts& facts);

}  // namespace lt::meshio
