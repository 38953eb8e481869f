#include "paths/gx/gx_path.h"

#include <algorithm>
#include <bit>

#include "core/error.h"
#include "core/simd_target.h"
#include "core/stopwatch.h"
#include "gx/pixel_stage.h"
#include "gx/program/gx_names.h"
#include "gx/program/parser.h"
#include "gx/program/printer.h"
#include "gx/setup_unit.h"
#include "gx/transform_unit.h"
#include "gx/xfb_copy.h"
#include "image/image.h"
#include "paths/common/nothing_drawn.h"
#include "paths/gx/camera_transform.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_budget.h"
#include "paths/gx/gx_export.h"
#include "paths/gx/lobe_lut.h"
#include "paths/gx/object_draw.h"
#include "paths/gx/program_check.h"
#include "paths/gx/program_storage.h"
#include "paths/gx/scene_vertices.h"

namespace lt::gx {

int ScenePrograms::passes() const {
  size_t n = 0;
  for (const auto& m : by_material) n = std::max(n, m.size());
  return static_cast<int>(n);
}

std::vector<MaterialDraw> ScenePrograms::draws(const Scene& scene) const {
  std::vector<MaterialDraw> out;
  for (int pass = 0; pass < passes(); ++pass) {
    for (size_t m = 0; m < by_material.size(); ++m) {
      if (static_cast<size_t>(pass) >= by_material[m].size()) continue;
      MaterialDraw d{pass, m, {}};
      for (size_t i = 0; i < scene.objects.size(); ++i)
        if (static_cast<size_t>(scene.objects[i].material) == m) d.objects.push_back(i);
      if (!d.objects.empty()) out.push_back(std::move(d));
    }
  }
  return out;
}

PixelFormat ScenePrograms::pixel_format(const Scene& scene) const {
  const std::vector<MaterialDraw> d = draws(scene);
  if (d.empty()) return {};
  return by_material[d.front().material][static_cast<size_t>(d.front().pass)].state.pixel_format;
}

ScenePrograms scene_programs_for(const Scene& scene, const GxVariant& variant,
                                 const std::string& program_file) {
  ScenePrograms out;
  if (program_file.empty()) {
    GeneratedPrograms g = generate_programs(scene, variant);
    out.file = std::move(g.file);
    out.file.file = "generated gx program";
    out.notes = std::move(g.notes);
    out.source = "generated";
  } else {
    out.file = load_program(program_file);
    out.source = program_file;
  }
  out.by_material = scene_programs(out.file, scene);
  const std::vector<std::string> c_names = material_c_names(scene);
  std::vector<bool> used(scene.materials.size(), false);
  for (const SceneObject& o : scene.objects) used[static_cast<size_t>(o.material)] = true;
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    if (used[m]) out.material_names.emplace_back(c_names[m], scene.materials[m].name);
  }
  for (size_t m = 0; m < out.by_material.size(); ++m) {
    // A material's programs may read UVs when every mesh drawn with it has them.
    bool has_uvs = true;
    for (const SceneObject& o : scene.objects) {
      if (static_cast<size_t>(o.material) == m && o.mesh.uvs.empty()) has_uvs = false;
    }
    for (const PassProgram& p : out.by_material[m])
      check_renderable(p, out.file.file, true, has_uvs);
  }
  // One EFB pixel format a frame: a draw in another format would read the bits the others
  // stored as that format's (Dolphin reinterprets them [DSW SWEfbInterface.cpp GetPixelColor]),
  // which the emulator does not model; a game sets its format once.
  const u8 format = out.pixel_format(scene).pixel;
  auto name = [](u8 f) {
    return std::string(GxConst<NameGroup::PixelFormat>::with_value(f).name());
  };
  for (const MaterialDraw& d : out.draws(scene)) {
    const PassProgram& p = out.by_material[d.material][static_cast<size_t>(d.pass)];
    if (p.state.pixel_format.pixel != format)
      throw InputError(out.file.file, p.name,
                       "GX_SetPixelFmt: " + name(p.state.pixel_format.pixel) +
                           " where the frame's first pass draws in " + name(format) +
                           " (one EFB format a frame is modelled)");
  }
  apply_program_declarations(scene, variant, out);
  return out;
}

namespace {

// The printed C of one pass function, for `info --source`.
std::string pass_source(const ProgramFile& file, const std::string& function) {
  ProgramFile one;
  for (const Function& f : file.functions) {
    if (f.name == function) one.functions.push_back(f);
  }
  if (file.functions.empty()) one.top_level = file.top_level;
  return print_program(one);
}

// The cull mode of `state` and where it came from, for the warning of a pass it culled whole.
std::string cull_mode_in_force(const GxState& state, const std::string& file) {
  const std::string mode = GxConst<NameGroup::CullMode>::with_value(state.cull_mode).name();
  if (state.cull_mode_line == 0)
    return mode + ", GX_Init's default (the program calls no GX_SetCullMode; GX's front faces " +
           "are clockwise, GL's counter-clockwise)";
  return mode + ", set by GX_SetCullMode at " + file + ":" + std::to_string(state.cull_mode_line);
}

// Triangles set up at a time before their pixels are drawn: bounds the memory of a large mesh
// (a Triangle is ~450 bytes) while keeping the threads' share of each batch large.
constexpr size_t kTriangleBatch = 4096;

class GxPath final : public Path {
 public:
  GxPath(const PathContext& ctx, const GxVariant& variant)
      : ctx_(ctx),
        variant_(variant),
        programs_(scene_programs_for(ctx.scene, variant_, ctx.options.program_file)),
        view_(SceneView::of(ctx.scene)),
        draws_(programs_.draws(ctx.scene)) {
    variant_ = programs_.variant;  // with a program file's declared storage and draw
    const Scene& s = ctx.scene;
    if (variant_.out == GxVariant::Output::Xfb) {
      const std::string why = xfb_size_refusal(ctx.width, ctx.height);
      if (!why.empty()) throw InputError("--variant", to_string(variant_), "gx: " + why);
    }
    for (const Material& m : s.materials)
      luts_.push_back(
          lobe_lut(m, variant_.lut_size, variant_.lut_format));  // GX_TEXMAP0's fallback (gx.md §1)
    // The camera as the FIFO log loads it (fifo/xf_registers.h write_view_xf), so every vertex
    // starts from the clip-space position Dolphin computes.
    const ViewTransform view =
        view_transform(glm::mat3(view_.view), s.camera, {ctx.width, ctx.height});
    viewport_ = view.viewport;
    scissor_ = {0, 0, ctx.width, ctx.height};
    for (const SceneObject& o : s.objects) {
      streams_.push_back(object_vertex_stream(s, o, view_, variant_));
      // A stored mesh is in object space: its own position matrix places it (scene_vertices.h).
      ViewTransform placed = view;
      if (streams_.back().object_matrices)
        placed.position = streams_.back().object_matrices->position;
      std::vector<glm::vec4> clip;
      for (const glm::vec3& p : streams_.back().position) clip.push_back(clip_position(placed, p));
      clip_.push_back(std::move(clip));
      // The triangles as the setup unit receives them under :draw= (a strip's order).
      triangles_.push_back(setup_order(o.mesh, variant_.draw));
    }
    // Per pass and material, the state and its textures (resolved once: the scene is static).
    pixel_programs_.resize(static_cast<size_t>(programs_.passes()));
    for (size_t pass = 0; pass < pixel_programs_.size(); ++pass) {
      pixel_programs_[pass].resize(s.materials.size());
      for (size_t m = 0; m < s.materials.size(); ++m) {
        const auto& passes = programs_.by_material[m];
        if (pass >= passes.size()) continue;
        PixelProgram& pp = pixel_programs_[pass][m];
        pp.state = &passes[pass].state;
        for (size_t map = 0; map < kMaxTexMaps; ++map) {
          const auto& t = pp.state->textures[map];
          pp.textures[map] = t ? &*t : (map == 0 ? &luts_[m] : nullptr);
        }
      }
    }
    const glm::dvec3 bg = s.background;
    background_ = {to_unorm8(bg.r), to_unorm8(bg.g), to_unorm8(bg.b), 255};
    pixel_format_ = programs_.pixel_format(s).pixel;
  }

  void frame() override {
    // The frame's clearing copy: the background and the far z (GX_SetCopyClear's 0xffffff).
    efb_.clear(ctx_.width, ctx_.height, background_, 0xffffff, pixel_format_);
    vertex_seconds_ = pixel_seconds_ = 0;
    stage_pixels_ = 0;
    light_vertices_ = 0;
    triangle_counts_ = {};
    VertexOutputs outputs;
    std::vector<RasterVertex> vertices;
    std::vector<Triangle> triangles;
    std::vector<PassOutcome> outcomes(pixel_programs_.size());
    for (const MaterialDraw& d : draws_) {
      const PixelProgram& pp = pixel_programs_[static_cast<size_t>(d.pass)][d.material];
      const GxState& state = *pp.state;
      const auto scales = texcoord_scales(state, pp.textures);
      TriangleCounts draw_counts;
      PixelCounts draw_pixels;
      for (size_t i : d.objects) {
        auto t0 = SteadyClock::now();
        // GX_VA_TEX0 carries the t of light `pass` (a plain one-pass program gets light 0's).
        run_vertex_stage(state, streams_[i], static_cast<size_t>(d.pass),
                         variant_.round_each_light ? LightRounding::RoundEachLight
                                                   : LightRounding::SumThenTruncate,
                         outputs);
        light_vertices_ += streams_[i].position.size() * lights_in(state);
        make_raster_vertices(clip_[i], outputs, scales, vertices);
        const auto& mesh_triangles = triangles_[i];
        vertex_seconds_ += seconds_since(t0);
        for (size_t first = 0; first < mesh_triangles.size(); first += kTriangleBatch) {
          t0 = SteadyClock::now();
          triangles.clear();
          setup_triangles(vertices, mesh_triangles, first,
                          std::min(mesh_triangles.size(), first + kTriangleBatch), state, viewport_,
                          scissor_, variant_.coverage, triangles, draw_counts);
          vertex_seconds_ += seconds_since(t0);
          t0 = SteadyClock::now();
          const PixelCounts counts = draw_triangles(triangles, pp, variant_.round_colors, efb_);
          stage_pixels_ += counts.stage_pixels;
          draw_pixels.add(counts);
          pixel_seconds_ += seconds_since(t0);
        }
      }
      triangle_counts_.add(draw_counts);
      add_outcome(d, state, draw_counts, draw_pixels, outcomes[static_cast<size_t>(d.pass)]);
    }
    // The scene is static: the first frame says what every frame would.
    if (!outcomes_checked_) {
      outcomes_checked_ = true;
      for (const PassOutcome& o : outcomes) warn_if_nothing_drawn(o);
    }
  }

  // The EFB (RGB8), or with out=xfb what the TV shows of it (xfb_copy.h); alpha = coverage (the
  // copy leaves it alone). Top row first, as the image and GX number rows.
  Image result() override {
    const int w = ctx_.width, h = ctx_.height;
    std::vector<Color8> shown = efb_.color;
    if (variant_.out == GxVariant::Output::Xfb) shown = efb_as_displayed(shown, w, h, copy_);
    Image img(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
        const Color8& c = shown[i];
        float* out = img.at(x, y);
        for (int ch = 0; ch < 3; ++ch) out[ch] = c[ch] / 255.0f;
        out[3] = efb_.covered[i] ? 1.0f : 0.0f;
      }
    }
    return img;
  }

  // Each TEV stage runs once a covered pixel, each enabled XF light once a vertex, in every pass
  // the material is drawn in: what frame_stats() counts as tev_stage_pixels and
  // xf_light_vertices as it draws.
  WorkModel work() const override {
    WorkModel w{"TEV stage", "XF light", {}, {}};
    w.by_material.resize(programs_.by_material.size());
    for (size_t m = 0; m < programs_.by_material.size(); ++m) {
      for (const PassProgram& p : programs_.by_material[m]) {
        w.by_material[m].per_pixel += p.state.tev.num_stages;
        w.by_material[m].per_vertex += static_cast<double>(lights_in(p.state));
      }
    }
    return w;
  }

  std::vector<BuiltStage> stages() const override {
    std::vector<BuiltStage> out;
    const Scene& s = ctx_.scene;
    for (size_t m = 0; m < s.materials.size(); ++m) {
      for (size_t pass = 0; pass < programs_.by_material[m].size(); ++pass) {
        const PassProgram& p = programs_.by_material[m][pass];
        std::string name =
            "material " + s.materials[m].name + ", pass " + std::to_string(pass) + ": " + p.name;
        const auto note = programs_.notes.find(p.name);
        name += note != programs_.notes.end()
                    ? " (" + note->second + ")"
                    : ", " + std::to_string(p.state.tev.num_stages) + " TEV stages";
        out.push_back({name, "gx-program", pass_source(programs_.file, p.name)});
      }
    }
    out.push_back(
        {"XF lighting, texgen and position transform per vertex on the CPU (float), each pass",
         "cpu", ""});
    out.push_back(
        {variant_.coverage == CoverageRule::Console
             ? "setup unit and rasteriser on the CPU: clipping, culling and float attribute "
               "planes as Dolphin's software renderer, coverage sampled at 7/12 of a pixel from "
               "exact vertices as the console (gx-hardware.md §2.6)"
             : "setup unit and rasteriser on the CPU: clipping, culling, 1/16-pixel edges and "
               "float attribute planes, as Dolphin's software renderer",
         "cpu", ""});
    out.push_back(
        {"depth test, texture unit, TEV and EFB per pixel on the CPU (integer; the raster "
         "values and the TEV in " +
             simd_target() + " vector lanes)",
         "cpu", ""});
    return out;
  }

  std::string cost() const override {
    int stages = 0, maps = 0;
    for (const auto& passes : programs_.by_material) {
      for (const PassProgram& p : passes) {
        stages = std::max(stages, p.state.tev.num_stages);
        int used = 0;
        for (int st = 0; st < p.state.tev.num_stages; ++st)
          used += p.state.tev.stages[static_cast<size_t>(st)].texmap != kTexMapNull;
        maps = std::max(maps, used);
      }
    }
    const int passes = programs_.passes();
    // The textures' memory (gx_budget.h frame_texture_cost): MEM1 bytes (palettes included) and
    // the most TMEM one draw's maps occupy, marked when a map is streamed through its cache or
    // two maps' regions overlap.
    const FrameTextureCost t = frame_texture_cost(ctx_.scene, programs_);
    return std::to_string(stages) + " TEV stages a pass, " + std::to_string(maps) +
           (maps == 1 ? " texture, " : " textures, ") + std::to_string(passes) +
           (passes == 1 ? " pass" : " passes") + ", " +
           std::to_string(t.texture_bytes + t.tlut_bytes) + " texture bytes, " +
           std::to_string(t.tmem_bytes) + " TMEM" + (t.fits_tmem() ? "" : " (over its regions)");
  }

  FrameStats frame_stats() const override {
    FrameStats s;
    s.cpu_vertex_seconds = vertex_seconds_;
    s.tev_seconds = pixel_seconds_;
    s.tev_stage_pixels = static_cast<double>(stage_pixels_);
    s.xf_light_vertices = static_cast<double>(light_vertices_);
    s.passes = static_cast<double>(pixel_programs_.size());
    return s;
  }

 private:
  // What the setup unit and the pixel stage did with one draw, added to its pass's outcome.
  void add_outcome(const MaterialDraw& d, const GxState& state, const TriangleCounts& t,
                   const PixelCounts& px, PassOutcome& out) const {
    if (out.path.empty()) {
      out.path = "gx";
      out.pass = "pass " + std::to_string(d.pass) + " (" + programs_.source + ")";
    }
    if (out.cull_mode.empty() && t.culled > 0)
      out.cull_mode = cull_mode_in_force(state, programs_.file.file);
    out.triangles += t.submitted;
    out.culled += t.culled;
    out.outside += t.rejected + t.clipped_away;
    out.pixels += px.covered;
    out.depth_failed += px.z_failed;
    out.alpha_failed += px.alpha_failed;
    out.written += px.written;
  }

  static size_t lights_in(const GxState& st) {
    size_t n = 0;
    for (int c = 0; c < st.lighting.num_channels; ++c) {
      const ChannelControl& ctl = st.lighting.control[static_cast<size_t>(c)];
      if (ctl.lighting) n += static_cast<size_t>(std::popcount(ctl.light_mask));
    }
    return n;
  }

  PathContext ctx_;
  GxVariant variant_;
  ScenePrograms programs_;
  SceneView view_;
  std::vector<MaterialDraw> draws_;
  Viewport viewport_;
  Scissor scissor_;
  std::vector<TextureObject> luts_;
  std::vector<VertexStream> streams_;
  std::vector<std::vector<glm::vec4>> clip_;               // per object, per vertex
  std::vector<std::vector<glm::uvec3>> triangles_;         // per object (object_draw.h)
  std::vector<std::vector<PixelProgram>> pixel_programs_;  // [pass][material]
  Efb efb_;
  TriangleCounts triangle_counts_;
  bool outcomes_checked_ = false;  // the nothing-drawn warning (paths/common/nothing_drawn.h)
  // The copy to the XFB: GX_Init's, which the exported program never changes.
  EfbCopyState copy_;
  Color8 background_;
  u8 pixel_format_ = kPixelRgb8Z24;  // the frame's (ScenePrograms::pixel_format)
  double vertex_seconds_ = 0, pixel_seconds_ = 0;
  size_t stage_pixels_ = 0, light_vertices_ = 0;
};

}  // namespace

}  // namespace lt::gx

namespace lt {

namespace {

class GxInfo final : public TypedPathInfo<gx::GxVariant> {
 public:
  GxInfo();
  gx::GxVariant parse(const std::string& v) const override { return gx::parse_gx_variant(v); }
  std::string name_of(const gx::GxVariant& v) const override { return gx::to_string(v); }
  std::unique_ptr<Path> build(const PathContext& ctx, const gx::GxVariant& v) const override {
    return std::make_unique<gx::GxPath>(ctx, v);
  }
  std::string refuse(const Scene& scene, const gx::GxVariant& v) const override {
    return gx::refusal(scene, v);
  }
  // One frame as a Dolphin FIFO log: the programs the emulator runs (generated, or the program
  // file), encoded on GX_Init's state, with the frame repeated so Dolphin dumps it.
  std::vector<std::uint8_t> fifo_log(const Scene& scene, const std::string& v,
                                     const PathOptions& options, int width,
                                     int height) const override {
    const gx::GxVariant variant = parse(v);
    const gx::ScenePrograms programs = gx::scene_programs_for(scene, variant, options.program_file);
    return gx::fifo::write_fifo_log(gx::fifo::for_dolphin(
        gx::fifo::record_frames(scene, {{programs.variant, &programs}}, {width, height})));
  }
  // TEV stages, texgens, texture maps, channels, lights, konst colours, registers and passes
  // against the Wii's GX, for generated programs and for program files alike.
  budget::Report budget(const Scene& scene, const std::string& v,
                        const std::string& profile) const override {
    return gx::gx_budget_scene(scene, v, profile);
  }
  budget::Report budget_file(const std::string& file, const std::string& profile) const override {
    return gx::gx_budget_file(file, profile);
  }
  std::string export_variant(const ExportRequest& r) const override {
    return gx::gx_export_variant(*this, r);
  }
  std::string export_scene(const ExportRequest& r, const ExportInput& in) const override {
    return gx::gx_export_scene(*this, r, in);
  }
};

GxInfo::GxInfo() {
  name = "gx";
  summary =
      "the Wii's GX pipeline emulated in its own integer arithmetic: XF lighting per vertex, "
      "8-bit channels, the power LUT as an I8 texture with 7-bit filtering, TEV stages, EFB "
      "blending; programs are libogc calls (`ltrender export gx`). Variants are a grammar: "
      "t=vertex | t=texgen with :lut=N (2..1024), or lobe=xf-spec; t=texgen and lobe=xf-spec with "
      ":view=object (V and L per object: any camera and lights); the LUT variants with :base=tev "
      "(a directional light's translucency base as a TEV konst colour, COLOR0 unlit); any with "
      ":colors=round, :lights=round-each, :map=FMT (the maps' texture format: rgb565, rgb5a3, "
      "cmpr; ia8, ia4, i4), :out=xfb (the XFB the TV shows instead of the EFB), "
      ":coverage=console (the console's sample point, not Dolphin's)";
  variants = {
      {"t=vertex",
       "t per vertex on the CPU as GX_VA_TEX0, 256-texel I8 LUT, 3 TEV stages a light (any "
       "light, any camera)"},
      {"t=vertex:lut=64", "the same with a 64-texel LUT"},
      {"t=vertex:lut=16", "the same with a 16-texel LUT", VariantRun::Story},
      {"t=vertex:colors=round",
       "the interpolated channel colours rounded, as Dolphin's shader backends do (the default "
       "truncates, as its software rasteriser does): how far that choice moves the image"},
      {"t=vertex:coverage=console",
       "t=vertex with the console's coverage as dolphin-emu/hwtests measured it (samples at 7/12 "
       "of a pixel, vertices not rounded to 1/16) instead of Dolphin's software renderer's (9/16, "
       "1/16): which pixels a silhouette holds on a Wii"},
      {"t=vertex:lights=round-each",
       "each light's XF contribution rounded before the sum (shader backends) instead of one "
       "truncation of the float sum (software renderer)"},
      {"t=texgen",
       "t from the raw normal through a 2x4 texture matrix: no CPU per-vertex work "
       "(directional lights and an orthographic camera only)",
       VariantRun::Story},
      {"t=vertex:out=xfb",
       "t=vertex as the TV shows it: the EFB copied to the XFB as YUYV 4:2:2 (BT.601, chroma "
       "filtered [1 2 1]/4 per pixel pair) and decoded again, as Dolphin's software renderer "
       "dumps the frame"},
      {"lobe=xf-spec",
       "no texture: the lobe as the XF specular attenuation, a rational fitted per material, "
       "per vertex, 2 TEV stages (directional lights and an orthographic camera only)",
       VariantRun::Story},
      {"t=texgen:view=object",
       "t=texgen under any camera and lights: V and L taken once per object at its centre "
       "(object_view.h), so the texture matrix from the raw normal is recomputed per frame and "
       "the CPU does no per-vertex work; the error is what a constant V and L cost"},
      {"lobe=xf-spec:view=object",
       "lobe=xf-spec under any camera and lights: V and L (and a point light's attenuation) taken "
       "once per object at its centre, the lobe fitted for them"},
  };
  takes_program_file = true;
  writes_fifo_log = true;
  for (const gx::GxProfile& p : gx::gx_profiles()) budget_profiles.push_back(p.name);
  program_extensions = {".c", ".gx"};
  export_target = "libogc C for the Wii / GameCube";
  export_formats = gx::gx_export_formats();
}

}  // namespace

const PathInfo& gx_path_info() {
  static const GxInfo info;
  return info;
}

}  // namespace lt
