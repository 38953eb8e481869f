#include "paths/reference/reference_path.h"

#include <chrono>
#include <thread>

#include "gl/program.h"
#include "model/translucency.h"

namespace lt {

namespace {

class ReferencePath final : public Path {
 public:
  explicit ReferencePath(const PathContext& ctx)
      : ctx_(ctx),
        program_(gl::read_shader_source("legacy_shaders/glsl/gbuffer.vert"),
                 gl::read_shader_source("legacy_shaders/glsl/gbuffer.frag"), "gbuffer"),
        target_(ctx.width, ctx.height, 3),
        relative_scene_(ctx.scene) {
    ctx.gl.require_extension("GL_ARB_texture_float", "the reference G-buffer");
    ctx.gl.require_extension("GL_ARB_draw_buffers", "the reference G-buffer");
    // The CPU shades in the same camera-relative space the G-buffer holds.
    for (Light& l : relative_scene_.lights)
      l.position = ctx.geometry.to_camera_relative(l.position);
    relative_scene_.objects.clear();  // shading needs lights and materials, not meshes
  }

  void frame() override {
    rasterise();
    const auto t0 = std::chrono::steady_clock::now();
    shade();
    shading_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  Image result() override { return image_; }
  bool float_output() const override { return true; }

  std::vector<BuiltStage> stages() const override {
    return {{"G-buffer: 3 x RGBA32F (position, normal + material, thickness)", "glsl-vertex",
             program_.vertex_source()},
            {"G-buffer fragment", "glsl-fragment", program_.fragment_source()},
            {"shading: model::shade in double on " + std::to_string(threads()) + " threads", "cpu",
             ""}};
  }

  std::map<std::string, double> frame_stats() const override {
    return {{"shading_seconds", shading_seconds_},
            {"covered_pixels", static_cast<double>(covered_)},
            {"threads", static_cast<double>(threads())}};
  }

 private:
  static unsigned threads() { return std::max(1u, std::thread::hardware_concurrency()); }

  void rasterise() {
    target_.bind();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program_.id());
    ctx_.geometry.load_matrices();
    for (const gl::GpuMesh& m : ctx_.geometry.meshes()) {
      glUniform1f(program_.uniform("u_material"), static_cast<float>(m.material));
      ctx_.geometry.draw(m);
    }
    glUseProgram(0);
    target_.unbind();
    target_.read(0, position_);
    target_.read(1, normal_);
    target_.read(2, thickness_);
    gl::check_error("reference G-buffer");
  }

  void shade() {
    const int w = ctx_.width, h = ctx_.height;
    image_ = Image(w, h);
    const Scene& s = relative_scene_;
    std::vector<size_t> covered(threads(), 0);
    auto work = [&](unsigned worker) {
      // Interleaved rows balance the load: geometry is rarely spread evenly down the image.
      for (int gy = static_cast<int>(worker); gy < h; gy += static_cast<int>(threads())) {
        for (int x = 0; x < w; ++x) {
          const size_t g = (static_cast<size_t>(gy) * w + x) * 4;  // G-buffer row gy, bottom-up
          float* out = image_.at(x, h - 1 - gy);
          if (!(position_[g + 3] > 0.5f)) {
            out[0] = static_cast<float>(s.background.r);
            out[1] = static_cast<float>(s.background.g);
            out[2] = static_cast<float>(s.background.b);
            out[3] = 0;
            continue;
          }
          ++covered[worker];
          const glm::dvec3 P(position_[g], position_[g + 1], position_[g + 2]);
          model::SurfacePoint sp;
          sp.P = P;
          sp.N = glm::dvec3(normal_[g], normal_[g + 1], normal_[g + 2]);
          sp.V = model::view_vector(s.camera, P);
          sp.vertex_thickness = glm::dvec3(thickness_[g], thickness_[g + 1], thickness_[g + 2]);
          const int mat = static_cast<int>(normal_[g + 3] + 0.5f);
          const glm::dvec3 c = model::shade(s, s.materials[mat], sp);
          out[0] = static_cast<float>(c.r);
          out[1] = static_cast<float>(c.g);
          out[2] = static_cast<float>(c.b);
          out[3] = 1;
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads(); ++t) pool.emplace_back(work, t);
    work(0);
    for (auto& t : pool) t.join();
    covered_ = 0;
    for (size_t c : covered) covered_ += c;
  }

  PathContext ctx_;
  gl::GlslProgram program_;
  gl::FloatTarget target_;
  Scene relative_scene_;
  std::vector<float> position_, normal_, thickness_;
  Image image_;
  double shading_seconds_ = 0;
  size_t covered_ = 0;
};

}  // namespace

PathInfo reference_path_info() {
  return {"reference",
          "double precision on the CPU over a float G-buffer: the ground truth",
          {{"exact", "std::pow in double; the only variant"}},
          [](const PathContext& ctx, const std::string&) -> std::unique_ptr<Path> {
            return std::make_unique<ReferencePath>(ctx);
          }};
}

}  // namespace lt
