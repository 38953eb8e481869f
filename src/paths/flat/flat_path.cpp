#include "paths/flat/flat_path.h"

#include "paths/common/first_frame_fragments.h"
#include "paths/common/frame.h"

namespace lt {

namespace {

class FlatPath final : public Path {
 public:
  explicit FlatPath(const PathContext& ctx) : ctx_(ctx), fragments_("flat", ctx.geometry) {}

  void frame() override {
    begin_frame(ctx_);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    fragments_.begin();
    for (const gl::GpuMesh& m : ctx_.geometry.meshes()) {
      const glm::dvec3 a = ctx_.scene.materials[m.material].albedo;
      ctx_.geometry.bind(m);
      // Colour arrays off: the albedo is the one constant colour, whatever the mesh carries.
      glDisableClientState(GL_COLOR_ARRAY);
      glColor4f(static_cast<float>(a.r), static_cast<float>(a.g), static_cast<float>(a.b), 1);
      glDrawElements(GL_TRIANGLES, m.index_count, GL_UNSIGNED_INT, nullptr);
      ctx_.geometry.unbind();
    }
    fragments_.end();
  }

  Image result() override { return read_framebuffer(ctx_.gl); }

  // One constant colour a covered pixel, no lighting: the floor every path's work is above.
  WorkModel work() const override {
    WorkModel w{"fixed-function fragment", "", {}, {}};
    w.by_material.assign(ctx_.scene.materials.size(), MaterialWork{1, 0});
    return w;
  }

  std::vector<BuiltStage> stages() const override {
    return {{"fixed-function: constant colour per material, no lighting", "fixed-function", ""}};
  }

 private:
  PathContext ctx_;
  FirstFrameFragments fragments_;  // the warning of an empty frame
};

}  // namespace

const PathInfo& flat_path_info() {
  static const SingleVariantInfo<FlatPath> info(
      "flat", "timing baseline: same geometry in one constant colour (not an approximation)",
      {"constant", "albedo as a constant colour"}, PathRole::Baseline);
  return info;
}

}  // namespace lt
