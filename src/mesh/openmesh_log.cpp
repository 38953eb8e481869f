#include "mesh/openmesh_log.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <iostream>

#include "core/error.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

using OpenMesh::IO::Options;

namespace {

std::mutex& openmesh_io_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

OpenMeshLogCapture::OpenMeshLogCapture() : lock_(openmesh_io_mutex()) {
  detach(omerr(), std::cerr);
  detach(omlog(), std::clog);
  detach(omout(), std::cout);
  for (auto* s : {&omerr(), &omlog(), &omout()}) s->connect(buffer_);
}

OpenMeshLogCapture::~OpenMeshLogCapture() {
  for (auto* s : {&omerr(), &omlog(), &omout()}) {
    // Flush first: a message without a final '\n' would otherwise surface on the terminal
    // later, once the terminal is connected again.
    s->flush();
    s->disconnect(buffer_);
  }
  for (auto& d : detached_) d.stream->connect(*d.target);
}

std::string OpenMeshLogCapture::last_line() {
  for (auto* s : {&omerr(), &omlog(), &omout()}) s->flush();
  // split_lines returns views into its argument: the text must outlive the loop (a
  // temporary from str() dies before the loop body runs, and the views would read freed
  // memory).
  const std::string text = buffer_.str();
  std::string last;
  for (auto line : split_lines(text)) {
    auto t = trim(line);
    if (!t.empty()) last = std::string(t);
  }
  return last;
}

void OpenMeshLogCapture::detach(OpenMesh::mostream& stream, std::ostream& target) {
  if (stream.disconnect(target)) detached_.push_back({&stream, &target});
}

Options requested_options() {
  return Options(Options::VertexNormal | Options::VertexColor | Options::VertexTexCoord |
                 Options::FaceTexCoord);
}

void read_with_openmesh(PolyMesh& mesh, const std::string& file, Options& options,
                        OpenMeshLogCapture& capture, const std::string& opened) {
  bool ok = false;
  try {
    ok = OpenMesh::IO::read_mesh(mesh, opened.empty() ? file : opened, options);
  } catch (const std::exception& e) {
    // e.g. std::bad_alloc from a reserve() sized by a corrupt count.
    throw InputError(file, "", std::string("OpenMesh could not read it: ") + e.what());
  }
  if (!ok) {
    const std::string why = capture.last_line();
    throw InputError(file, "",
                     "OpenMesh could not read it" + (why.empty() ? std::string() : ": " + why));
  }
}

}  // namespace lt::meshio
