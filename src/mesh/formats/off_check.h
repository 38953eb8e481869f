// OFF: OpenMesh reads the counts and the values token by token, colours from the rest of each
// vertex line counted by single spaces, has no comments, ignores counts on the keyword line, and
// reads `n` indices for a face whatever the line holds; a short file leaves it repeating stale
// values. Checked here line by line: one vertex or face per line, counts that match, indices in
// range. What Geomview's OFF allows and OpenMesh misreads (comments, counts on the keyword line,
// a face's colour, colours spaced otherwise) is accepted: the check hands on a copy in the form
// OpenMesh reads (FileFacts::rewritten).
#pragma once

#include <string>

#include "mesh/raw_mesh.h"

namespace lt::meshio {

// Checks an OFF file (ascii or BINARY) before OpenMesh reads it; returns its vertex count and
// the colours when every vertex has one.
FileFacts check_off(const std::string& data, const std::string& file);

}  // namespace lt::meshio
