// OpenMesh's log streams (omerr, omlog, omout) are process-wide and print to the terminal.
// While OpenMesh works for us they are re-routed into a buffer, so that the user sees our
// one-line error rather than its chatter; the lock serialises all our OpenMesh I/O because the
// streams (and the IOManager) are shared.
#pragma once

#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/System/mostream.hh>
#include <mutex>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/poly_mesh.h"

namespace lt::meshio {

class OpenMeshLogCapture {
 public:
  OpenMeshLogCapture();
  ~OpenMeshLogCapture();
  OpenMeshLogCapture(const OpenMeshLogCapture&) = delete;
  OpenMeshLogCapture& operator=(const OpenMeshLogCapture&) = delete;

  // The last non-empty line OpenMesh printed, for error messages.
  std::string last_line();

 private:
  struct Detached {
    OpenMesh::mostream* stream;
    std::ostream* target;
  };
  void detach(OpenMesh::mostream& stream, std::ostream& target);

  std::unique_lock<std::mutex> lock_;
  std::ostringstream buffer_;
  std::vector<Detached> detached_;
};

// What the attributes request: normals, colours and texture coordinates (per vertex, and per
// face corner, which only OBJ has: mesh/uv_seams.h makes them per vertex). ColorFloat is not
// requested: it only changes OpenMesh's binary OFF reader, and there it would misread the usual
// integer colours.
OpenMesh::IO::Options requested_options();

// OpenMesh::IO::read_mesh of `file` (or of `opened`, a copy of it, when given), with its failure
// (false or an exception) as an InputError naming `file` and OpenMesh's last log line.
void read_with_openmesh(PolyMesh& mesh, const std::string& file, OpenMesh::IO::Options& options,
                        OpenMeshLogCapture& capture, const std::string& opened = "");

}  // namespace lt::meshio
