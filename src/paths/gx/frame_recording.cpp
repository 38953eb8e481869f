#include "paths/gx/frame_recording.h"

#include <algorithm>
#include <optional>

#include "core/error.h"
#include "gx/fifo/cp_registers.h"
#include "gx/fifo/xf_registers.h"
#include "gx/vertex_format.h"
#include "gx/vertex_quantiser.h"
#include "image/image.h"
#include "paths/gx/camera_transform.h"
#include "paths/gx/indexed_recording.h"
#include "paths/gx/lobe_lut.h"
#include "paths/gx/scene_vertices.h"

namespace lt::gx::fifo {

namespace {

constexpr int kEfbWidth = 640, kEfbHeight = 528;

// The textures of one frame at their addresses: each distinct texture once.
class TextureMemory {
 public:
  explicit TextureMemory(const std::string& file) : file_(file) {}
  // The address of `t`, and whether it is new to the frame (its bytes must be sent).
  std::pair<u32, bool> place_texture(const TextureObject& t) { return place(t.data); }
  // The same for a block of bytes (a colour-indexed texture's palette).
  std::pair<u32, bool> place(const std::vector<u8>& data) {
    for (const auto& [placed, address] : placed_)
      if (*placed == data) return {address, false};
    const u32 address = next_;
    const size_t bytes = (data.size() + 31) & ~size_t{31};
    if (bytes > kTextureEnd - next_)
      throw InputError(file_, "textures",
                       "the frame's textures need more than the " +
                           std::to_string((kTextureEnd - kTextureBase) >> 20) +
                           " MiB the FIFO log's memory map has for them");
    next_ += static_cast<u32>(bytes);
    placed_.emplace_back(&data, address);
    return {address, true};
  }

 private:
  std::string file_;
  u32 next_ = kTextureBase;
  std::vector<std::pair<const std::vector<u8>*, u32>> placed_;
};

// The triangles of `mesh` expanded to a vertex list.
std::vector<u32> triangle_vertices(const TriangleMesh& mesh) {
  std::vector<u32> indices;
  for (const glm::uvec3& tri : mesh.triangles)
    for (int c = 0; c < 3; ++c) indices.push_back(tri[c]);
  return indices;
}

// The vertices of one object as the pass's descriptor sends them (vertex_stage.h: what the
// emulator's XF reads), triangles expanded, in draws of at most 65,535 vertices (a multiple
// of 3, so no triangle is split).
void draw_object(CommandStream& out, const GxState& s, const VertexStream& stream,
                 const TriangleMesh& mesh, size_t pass, int format) {
  const VertexDescriptor v = sent_attributes(s);
  const TexCoordFormats f = sent_formats(s.texcoord_formats);
  const std::vector<float>* t =
      pass < stream.t_per_light.size() ? &stream.t_per_light[pass] : nullptr;
  const std::vector<u32> indices = triangle_vertices(mesh);
  static_assert(kMaxDrawVertices % 3 == 0);
  for (size_t start = 0; start < indices.size(); start += kMaxDrawVertices) {
    const size_t n = std::min(kMaxDrawVertices, indices.size() - start);
    out.begin(kPrimitiveTriangles, static_cast<u8>(format), static_cast<u16>(n));
    for (size_t k = start; k < start + n; ++k) {
      const u32 i = indices[k];
      auto vec3 = [&](const glm::vec3& p) {
        for (int c = 0; c < 3; ++c) out.put_f32(p[c]);
      };
      auto color = [&](const Color8& c) {
        for (int ch = 0; ch < 4; ++ch) out.put_u8(c[ch]);
      };
      vec3(stream.position[i]);
      if (v.has(kVaNrm)) vec3(stream.normal[i]);
      if (v.has(kVaClr0)) color(stream.color[i]);
      if (v.has(kVaClr1)) color(stream.color[i]);
      for (int n_ = 0; n_ < kMaxTexGens; ++n_) {
        if (!v.has(kVaTex0 + n_)) continue;
        if (f.kind[static_cast<size_t>(n_)] == TexCoordFormats::ST) {
          const glm::vec2 uv = i < stream.uv.size() ? stream.uv[i] : glm::vec2(0.0f);
          out.put_f32(uv.x);
          out.put_f32(uv.y);
        } else {
          out.put_f32(t ? (*t)[i] : 0.0f);
        }
      }
    }
  }
}

// One object of a variant with a vertex storage (scene_vertices.h): its matrices (it arrives in
// its own coordinates), the pass's VAT for the storage (GX_SetVtxAttrFmt of every attribute the
// pass sends, ByteDequant set as libogc leaves it: vertex_format.h pack_vertex_format), and the
// stored bytes of each vertex sent directly, triangles expanded as draw_object's.
void draw_stored_object(CommandStream& out, const GxState& s, const VertexStream& f32,
                        const ObjectSpaceMesh& mesh, const TriangleMesh& triangles,
                        const VertexStorage& storage, size_t pass, int vertex_format) {
  const VertexAttributeData data = pass_vertex_data(
      mesh.position, mesh.normal, f32, sent_attributes(s), sent_formats(s.texcoord_formats), pass);
  const VertexAttributeFormat format = storage_format(storage, data, "--variant");
  write_matrices_xf(out, mesh.matrices.position, mesh.matrices.normal);
  if (format.normal.nbt) out.load_xf(xf::kVertexSpecs, vertex_specs(sent_attributes(s), true));
  write_vat(out, pack_vertex_format(format), vertex_format);
  const std::vector<AttributeElements> elements = quantise_attributes(data, format);
  const std::vector<u32> indices = triangle_vertices(triangles);
  for (size_t start = 0; start < indices.size(); start += kMaxDrawVertices) {
    const size_t n = std::min(kMaxDrawVertices, indices.size() - start);
    out.begin(kPrimitiveTriangles, static_cast<u8>(vertex_format), static_cast<u16>(n));
    for (u8 b : direct_vertex_stream(elements, std::span(indices).subspan(start, n))) out.put_u8(b);
  }
}

// The clear colour GX_Init sets: GX_DEFAULT_BG [OGC gx.c L66].
constexpr Color8 kGxDefaultBackground{64, 64, 64, 255};

void write_gx_init(CommandStream& out, FrameSize size) {
  write_gx_init_bp(out, size);
  write_gx_init_xf(out);
}

}  // namespace

void check_frame_size(FrameSize size, const std::string& file, const std::string& width_key,
                      const std::string& height_key) {
  if (size.width < 16 || size.width > kEfbWidth || size.width % 16 != 0)
    throw InputError(file, width_key,
                     std::to_string(size.width) +
                         ": the XFB copy needs a width that is a multiple of 16 from 16 to " +
                         std::to_string(kEfbWidth) + " (the EFB's width)");
  if (size.height < 1 || size.height > kEfbHeight)
    throw InputError(file, height_key,
                     std::to_string(size.height) + ": the EFB holds 1 to " +
                         std::to_string(kEfbHeight) + " rows");
}

FifoLog record_frames(const Scene& first_scene, const std::vector<FrameInput>& frames,
                      FrameSize size) {
  check_frame_size(size, first_scene.file.string());
  FifoLog log;
  {
    // The header snapshot: GX_Init's registers, then GxState{}'s, then the camera.
    CommandStream init;
    write_gx_init(init, size);
    const GxState gx_init;
    write_pass_cp(init, gx_init);
    write_pass_xf(init, gx_init);
    write_pass_bp(init, gx_init, {}, {});
    write_copy_clear(init, kGxDefaultBackground);
    log.bp = init.bp;
    // BP 0xFE, the mask of the next BP write, reads all ones: the hardware resets it after every
    // write [DHW BPMemory.h BPMEM_BP_MASK].
    log.bp[0xfe] = 0xffffff;
    log.cp = init.cp;
    log.xf_memory = init.xf_memory;
    log.xf_registers = init.xf_registers;
  }
  for (const FrameInput& in : frames) {
    // Any scene: the frame writes everything it draws with (GX_Init's state, the camera, every
    // pass's registers, its own texture and vertex memory), so frames of other scenes can follow
    // each other (the Dolphin tests play many scenes in one log).
    const Scene& scene = in.scene ? *in.scene : first_scene;
    // The vertices as this frame's view sends them (eye-relative positions, per-light t).
    const SceneView view = SceneView::of(scene);
    std::vector<VertexStream> streams;
    for (const SceneObject& o : scene.objects)
      streams.push_back(make_vertex_stream(scene, o, view));
    // A stored mesh (a vertex storage axis) is sent in each object's own coordinates.
    const bool stored = !in.variant.storage.is_default();
    std::vector<ObjectSpaceMesh> object_meshes;
    for (const SceneObject& o : scene.objects)
      if (stored) object_meshes.push_back(object_space_mesh(o, view));
    const glm::dvec3 bg = scene.background;
    const Color8 background{to_unorm8(bg.r), to_unorm8(bg.g), to_unorm8(bg.b), 255};
    const ScenePrograms& programs = *in.programs;
    std::vector<TextureObject> luts;  // GX_TEXMAP0's fallback (gx.md §1), as the emulator's
    for (const Material& m : scene.materials)
      luts.push_back(lobe_lut(m, in.variant.lut_size, in.variant.lut_format));
    CommandStream out;
    FifoFrame frame;
    TextureMemory memory(scene.file.string());
    VertexMemory vertex_memory(scene.file.string());  // :draw=indexed, strips, list
    write_gx_init(out, size);
    write_view_xf(out, view_transform(glm::mat3(view.view), scene.camera, size), size);
    // The frame's pixel format before its clearing copy, as a game sets it once at start-up:
    // the clear then stores the background in the format the draws read it in (gx_path.h
    // ScenePrograms::pixel_format; efb.h).
    const PixelFormat format = programs.pixel_format(scene);
    if (!(format == PixelFormat{})) out.load_bp(bp::kPixelControl, pixel_control(format));
    write_copy_clear(out, background);
    write_clearing_texture_copy(out, size, kClearCopyAddress);
    for (const MaterialDraw& d : programs.draws(scene)) {
      const GxState& state = programs.by_material[d.material][static_cast<size_t>(d.pass)].state;
      std::array<const TextureObject*, kMaxTexMaps> textures{};
      std::array<u32, kMaxTexMaps> addresses{}, tlut_addresses{};
      for (size_t map = 0; map < kMaxTexMaps; ++map) {
        const auto& t = state.textures[map];
        textures[map] = t ? &*t : (map == 0 ? &luts[d.material] : nullptr);
        if (!textures[map]) continue;
        const auto [address, is_new] = memory.place_texture(*textures[map]);
        addresses[map] = address;
        if (is_new)
          frame.updates.push_back({static_cast<u32>(out.position()), address, kMemoryUpdateTexture,
                                   textures[map]->data});
        if (textures[map]->tlut.empty()) continue;
        // A colour-indexed map's palette, which BP_LOADTLUT1 copies into TMEM (bp_registers.h).
        const auto [tlut_address, tlut_new] = memory.place(textures[map]->tlut);
        tlut_addresses[map] = tlut_address;
        if (tlut_new)
          frame.updates.push_back({static_cast<u32>(out.position()), tlut_address,
                                   kMemoryUpdateTmem, textures[map]->tlut});
      }
      write_pass_cp(out, state, in.variant.vat);
      write_pass_xf(out, state);
      write_pass_bp(out, state, textures, addresses, tlut_addresses);
      for (size_t i : d.objects) {
        if (in.variant.draw != GxVariant::Draw::Direct)
          draw_indexed_object(out, frame, vertex_memory, state, streams[i],
                              stored ? &object_meshes[i] : nullptr, scene.objects[i].mesh,
                              in.variant, static_cast<size_t>(d.pass));
        else if (stored)
          draw_stored_object(out, state, streams[i], object_meshes[i], scene.objects[i].mesh,
                             in.variant.storage, static_cast<size_t>(d.pass), in.variant.vat);
        else
          draw_object(out, state, streams[i], scene.objects[i].mesh, static_cast<size_t>(d.pass),
                      in.variant.vat);
      }
    }
    write_display_copy(out, size, kXfbAddress);
    frame.fifo = std::move(out).take_bytes();
    log.frames.push_back(std::move(frame));
  }
  return log;
}

namespace {

// `log` with `lead_in` (if any) in front and kDolphinTrailingCopies of `trailing` behind.
FifoLog padded(FifoLog log, const std::optional<FifoFrame>& lead_in, const FifoFrame& trailing) {
  if (lead_in) log.frames.insert(log.frames.begin(), *lead_in);
  log.frames.insert(log.frames.end(), kDolphinTrailingCopies, trailing);
  return log;
}

// GX_Init's registers, the clear colour GX_Init sets and the display copy that ends a frame.
FifoFrame blank_frame(FrameSize size) {
  CommandStream out;
  write_gx_init(out, size);
  write_copy_clear(out, kGxDefaultBackground);
  write_display_copy(out, size, kXfbAddress);
  return FifoFrame{std::move(out).take_bytes(), {}};
}

}  // namespace

FifoLog for_dolphin(FifoLog log) {
  if (log.frames.empty()) return log;
  const FifoFrame last = log.frames.back();
  return padded(std::move(log), std::nullopt, last);
}

FifoLog for_dolphin_animation(FifoLog log) {
  if (log.frames.empty()) return log;
  const FifoFrame first = log.frames.front(), last = log.frames.back();
  return padded(std::move(log), first, last);
}

FifoLog for_dolphin_judging(FifoLog log, FrameSize size) {
  if (log.frames.empty()) return log;
  const FifoFrame blank = blank_frame(size);
  return padded(std::move(log), blank, blank);
}

}  // namespace lt::gx::fifo
