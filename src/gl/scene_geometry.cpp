#include "gl/scene_geometry.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gl/context.h"

namespace lt::gl {

namespace {
GLuint upload(GLenum target, const void* data, size_t bytes) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(target, b);
  glBufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  glBindBuffer(target, 0);
  return b;
}

std::vector<float> to_float(const std::vector<glm::dvec3>& v, const glm::dvec3& offset) {
  std::vector<float> out(v.size() * 3);
  for (size_t i = 0; i < v.size(); ++i) {
    for (int c = 0; c < 3; ++c) out[i * 3 + c] = static_cast<float>(v[i][c] - offset[c]);
  }
  return out;
}

// The pixel rectangle of every vertex projected in double (the bound of its triangles' pixels:
// a triangle's pixels lie in the projection of its vertices' hull, clipped or not, while every
// vertex is in front of the eye). `min_w`: a vertex with a smaller clip w gives the whole
// viewport.
PixelRect rect_of_vertices(const Scene& scene, const glm::dmat4& view_projection,
                           const glm::dvec3& origin, int width, int height, double min_w) {
  const PixelRect whole{0, 0, width, height};
  double lo_x = width, lo_y = height, hi_x = 0, hi_y = 0;
  for (const SceneObject& obj : scene.objects) {
    for (const glm::dvec3& p : obj.mesh.positions) {
      const glm::dvec4 c = view_projection * glm::dvec4(p - origin, 1.0);
      if (!(c.w >= min_w)) return whole;  // NaN included
      const double x = (c.x / c.w * 0.5 + 0.5) * width, y = (c.y / c.w * 0.5 + 0.5) * height;
      if (!std::isfinite(x) || !std::isfinite(y)) return whole;
      lo_x = std::min(lo_x, x);
      lo_y = std::min(lo_y, y);
      hi_x = std::max(hi_x, x);
      hi_y = std::max(hi_y, y);
    }
  }
  const double x0 = std::clamp(std::floor(lo_x) - kCoveredRectMargin, 0.0, double(width));
  const double y0 = std::clamp(std::floor(lo_y) - kCoveredRectMargin, 0.0, double(height));
  const double x1 = std::clamp(std::ceil(hi_x) + kCoveredRectMargin, x0, double(width));
  const double y1 = std::clamp(std::ceil(hi_y) + kCoveredRectMargin, y0, double(height));
  return {static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0),
          static_cast<int>(y1 - y0)};
}
}  // namespace

SceneGeometry::SceneGeometry(const Scene& scene, int width, int height)
    : origin_(scene.camera.eye) {
  const Camera& cam = scene.camera;
  const double aspect = static_cast<double>(width) / height;
  // The view looks from the origin (camera-relative), so its translation is zero.
  view_ = cam.view_from_origin();
  if (cam.projection == Camera::Projection::Perspective) {
    projection_ = glm::perspective(glm::radians(cam.fov_y_deg), aspect, cam.near, cam.far);
  } else {
    const double h = cam.height / 2, w = h * aspect;
    projection_ = glm::ortho(-w, w, -h, h, cam.near, cam.far);
  }
  // Clip w is the eye distance in perspective (half the near plane is still well in front of
  // the eye), 1 in orthographic.
  const bool perspective = cam.projection == Camera::Projection::Perspective;
  covered_rect_ = rect_of_vertices(scene, projection_ * view_, origin_, width, height,
                                   perspective ? cam.near / 2 : 0.5);
  for (const SceneObject& obj : scene.objects) {
    const TriangleMesh& m = obj.mesh;
    GpuMesh g;
    g.material = obj.material;
    g.vertex_count = m.positions.size();
    const auto pos = to_float(m.positions, origin_);
    const auto nrm = to_float(m.normals, glm::dvec3(0));
    g.positions = upload(GL_ARRAY_BUFFER, pos.data(), pos.size() * sizeof(float));
    g.normals = upload(GL_ARRAY_BUFFER, nrm.data(), nrm.size() * sizeof(float));
    if (m.has_colors()) {
      const auto col = to_float(m.colors, glm::dvec3(0));
      g.colors = upload(GL_ARRAY_BUFFER, col.data(), col.size() * sizeof(float));
      g.has_colors = true;
      // Bit for bit: -0 and +0 compare equal but need not interpolate to the same bits.
      const auto bits = [&](size_t i) { return std::bit_cast<uint32_t>(col[i]); };
      for (size_t i = 0; i < col.size(); i += 3)
        g.grey_colors = g.grey_colors && bits(i) == bits(i + 1) && bits(i) == bits(i + 2);
    }
    const Material& mat = scene.materials[static_cast<size_t>(obj.material)];
    if (samples_uvs(mat)) {
      std::vector<float> uv(m.uvs.size() * 2);
      for (size_t i = 0; i < m.uvs.size(); ++i) {
        uv[i * 2] = static_cast<float>(m.uvs[i].x);
        uv[i * 2 + 1] = static_cast<float>(m.uvs[i].y);
      }
      g.uvs = upload(GL_ARRAY_BUFFER, uv.data(), uv.size() * sizeof(float));
      g.has_uvs = true;
    }
    g.indices = upload(GL_ELEMENT_ARRAY_BUFFER, m.triangles.data(),
                       m.triangles.size() * sizeof(glm::uvec3));
    g.index_count = static_cast<GLsizei>(m.triangles.size() * 3);
    meshes_.push_back(g);
  }
  check_error("uploading scene geometry");
}

SceneGeometry::~SceneGeometry() {
  for (const GpuMesh& g : meshes_) {
    const GLuint b[] = {g.positions, g.normals, g.colors, g.uvs, g.indices};
    for (GLuint id : b) {
      if (id) glDeleteBuffers(1, &id);
    }
  }
}

void SceneGeometry::load_matrices() const {
  const glm::mat4 p(projection_), v(view_);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(glm::value_ptr(p));
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(glm::value_ptr(v));
}

void SceneGeometry::bind(const GpuMesh& g) const {
  glEnableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, g.positions);
  glVertexPointer(3, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_NORMAL_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, g.normals);
  glNormalPointer(GL_FLOAT, 0, nullptr);
  if (g.has_colors) {
    glEnableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, g.colors);
    glColorPointer(3, GL_FLOAT, 0, nullptr);
  } else {
    glDisableClientState(GL_COLOR_ARRAY);
    glColor4f(1, 1, 1, 1);
  }
  if (g.has_uvs) {
    glClientActiveTexture(GL_TEXTURE0 + kUvTexCoordSet);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, g.uvs);
    glTexCoordPointer(2, GL_FLOAT, 0, nullptr);
    glClientActiveTexture(GL_TEXTURE0);
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices);
}

void SceneGeometry::draw(const GpuMesh& g) const {
  bind(g);
  glDrawElements(GL_TRIANGLES, g.index_count, GL_UNSIGNED_INT, nullptr);
  unbind();
}

void SceneGeometry::unbind() const {
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glClientActiveTexture(GL_TEXTURE0 + kUvTexCoordSet);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE0);
}

void stream_array_buffer(GLuint buffer, const std::vector<float>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_STREAM_DRAW);
}

}  // namespace lt::gl
