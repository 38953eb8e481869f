#include "paths/gx/indexed_recording.h"

#include <algorithm>

#include "core/error.h"
#include "gx/fifo/cp_registers.h"
#include "gx/fifo/xf_registers.h"
#include "gx/vertex_cost.h"
#include "gx/vertex_storage.h"
#include "paths/gx/object_draw.h"

namespace lt::gx::fifo {

namespace {

// CP array registers: base of array n at 0xA0 + n, stride at 0xB0 + n [DHW CPMemory.h
// ARRAY_BASE, ARRAY_STRIDE] [OGC gx.c GX_SetArray L2283-2293].
constexpr u8 kArrayBase = 0xa0, kArrayStride = 0xb0;

// The draws of `order` (vertex numbers) as index streams: GX_TRIANGLES in draws of whole
// triangles, or one strip in draws that each start two vertices back on an even vertex
// (vertex_cost.h strip_draw_counts), so every triangle is set up as in one long strip.
void put_draws(CommandStream& out, const IndexedArrays& arrays, const std::vector<u32>& order,
               bool strip, int format) {
  size_t start = 0;
  for (size_t n : strip ? strip_draw_counts(order.size()) : list_draw_counts(order.size())) {
    out.begin(strip ? kPrimitiveTriangleStrip : kPrimitiveTriangles, static_cast<u8>(format),
              static_cast<u16>(n));
    for (u8 b : indexed_vertex_stream(arrays, std::span(order).subspan(start, n))) out.put_u8(b);
    start += strip ? n - 2 : n;
  }
}

}  // namespace

std::pair<u32, bool> VertexMemory::place(const std::vector<u8>& bytes) {
  for (const auto& [block, address] : placed_)
    if (block == bytes) return {address, false};
  const u32 address = next_;
  const size_t size = cache_lines_bytes(bytes.size());
  if (size > kVertexMemoryEnd - next_)
    throw InputError(file_, "vertices",
                     "the frame's vertex arrays and display lists need more than the " +
                         std::to_string((kVertexMemoryEnd - kVertexMemoryBase) >> 20) +
                         " MiB the FIFO log's memory map has for them");
  next_ += static_cast<u32>(size);
  placed_.emplace_back(bytes, address);
  return {address, true};
}

void draw_indexed_object(CommandStream& out, FifoFrame& frame, VertexMemory& memory,
                         const GxState& state, const VertexStream& stream,
                         const ObjectSpaceMesh* object_mesh, const TriangleMesh& mesh,
                         const GxVariant& variant, size_t pass) {
  const VertexAttributeData data =
      pass_vertex_data(object_mesh ? object_mesh->position : stream.position,
                       object_mesh ? object_mesh->normal : stream.normal, stream,
                       sent_attributes(state), sent_formats(state.texcoord_formats), pass);
  const VertexAttributeFormat format = storage_format(variant.storage, data, "--variant");
  if (object_mesh)
    write_matrices_xf(out, object_mesh->matrices.position, object_mesh->matrices.normal);
  const IndexedArrays arrays = index_attributes(quantise_attributes(data, format), "--variant");
  const std::array<u32, 2> vcd = pack_vertex_inputs(indexed_inputs(arrays));
  out.load_cp(cp::kVcdLow, vcd[0]);
  out.load_cp(cp::kVcdHigh, vcd[1]);
  if (format.normal.nbt) out.load_xf(xf::kVertexSpecs, vertex_specs(sent_attributes(state), true));
  write_vat(out, pack_vertex_format(format), variant.vat);
  auto send_block = [&](const std::vector<u8>& bytes) {
    const auto [address, is_new] = memory.place(bytes);
    if (is_new)
      frame.updates.push_back(
          {static_cast<u32>(out.position()), address, kMemoryUpdateVertexStream, bytes});
    return address;
  };
  for (int a : arrays.arrays) {
    const auto i = static_cast<size_t>(a);
    out.load_cp(static_cast<u8>(kArrayBase + a), send_block(arrays.bytes[i]));
    out.load_cp(static_cast<u8>(kArrayStride + a), arrays.stride[i]);
  }
  const std::vector<u32> order = sent_vertex_order(mesh, variant.draw);
  if (variant.draw != GxVariant::Draw::List) {
    put_draws(out, arrays, order, draws_strip(variant.draw), variant.vat);
    return;
  }
  CommandStream list;
  put_draws(list, arrays, order, true, variant.vat);
  std::vector<u8> bytes = list.bytes();
  bytes.resize(cache_lines_bytes(bytes.size()), kNop);
  const u32 address = send_block(bytes);
  out.put_u8(kCallDisplayList);
  out.put_u32(address);
  out.put_u32(static_cast<u32>(bytes.size()));
}

}  // namespace lt::gx::fifo
