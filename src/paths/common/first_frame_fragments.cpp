#include "paths/common/first_frame_fragments.h"

#include "paths/common/nothing_drawn.h"

namespace lt {

FirstFrameFragments::FirstFrameFragments(std::string who, const gl::SceneGeometry& geometry)
    : who_(std::move(who)) {
  for (const gl::GpuMesh& m : geometry.meshes())
    triangles_ += static_cast<std::size_t>(m.index_count) / 3;
}

void FirstFrameFragments::begin() {
  if (!first_frame_) return;
  glGenQueries(1, &query_);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
}

void FirstFrameFragments::end() {
  if (!first_frame_) return;
  first_frame_ = false;
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint samples = 0;
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &samples);
  glDeleteQueries(1, &query_);
  PassOutcome o;
  o.path = who_;
  o.pass = "frame";
  o.triangles = triangles_;
  o.fragments_only = true;
  o.written = samples;
  warn_if_nothing_drawn(o);
}

}  // namespace lt
