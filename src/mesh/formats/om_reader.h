// OM: OpenMesh's own binary format, whose chunks describe the halfedge structure directly.
// Corrupt files make its reader abort (asserts compiled into libOpenMeshCore, double frees),
// segfault, allocate without end, or quietly write outside its arrays and leave a halfedge
// structure whose circulators crash later. Checking the format ourselves would mean
// re-implementing it, so the reader runs in a child process, which walks the faces with every
// handle checked and sends back plain arrays; this process never runs the OM reader.
#pragma once

#include <filesystem>
#include <string>

#include "mesh/openmesh_log.h"
#include "mesh/raw_mesh.h"

namespace lt::meshio {

// Reads an OM file in a sandboxed child (core/sandboxed_child.h) and returns its faces as arrays;
// a crash, hang or runaway allocation in OpenMesh's reader is an InputError naming the file.
RawMesh read_om_in_child(const std::filesystem::path& path, const std::string& file,
                         OpenMeshLogCapture& capture);

}  // namespace lt::meshio
