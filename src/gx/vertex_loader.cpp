#include "gx/vertex_loader.h"

#include <bit>
#include <cmath>

#include "core/error.h"

namespace lt::gx {

namespace {

u32 read_big_endian(std::span<const u8> bytes, size_t at, int size) {
  u32 v = 0;
  for (int i = 0; i < size; ++i) v = (v << 8) | bytes[at + static_cast<size_t>(i)];
  return v;
}

// One component of `type` from its big-endian bytes, as a float before any scaling: integers
// exactly (every u16/s16 is a float), F32 by its bits.
float component_value(ComponentType type, u32 raw) {
  switch (type) {
    case ComponentType::U8:
      return static_cast<float>(static_cast<u8>(raw));
    case ComponentType::S8:
      return static_cast<float>(static_cast<std::int8_t>(static_cast<u8>(raw)));
    case ComponentType::U16:
      return static_cast<float>(static_cast<u16>(raw));
    case ComponentType::S16:
      return static_cast<float>(static_cast<s16>(static_cast<u16>(raw)));
    default:
      return std::bit_cast<float>(raw);
  }
}

// Where an attribute's bytes are, and the checks that keep every read inside its bytes.
class VertexReader {
 public:
  VertexReader(std::span<const u8> stream, const VertexArrays& arrays, const std::string& origin)
      : stream_(stream), arrays_(arrays), origin_(origin) {}

  void start_vertex(size_t v) { vertex_ = v; }
  size_t cursor() const { return cursor_; }

  // The next `size` bytes of the stream (the vertex's direct data or an index).
  size_t take(int size) {
    if (cursor_ + static_cast<size_t>(size) > stream_.size()) {
      throw InputError(origin_, "vertex " + std::to_string(vertex_),
                       "the vertex stream ends at byte " + std::to_string(stream_.size()) +
                           ", inside this vertex");
    }
    const size_t at = cursor_;
    cursor_ += static_cast<size_t>(size);
    return at;
  }
  u32 take_index(AttributeInput in) {
    const int size = in == AttributeInput::Index8 ? 1 : 2;
    return read_big_endian(stream_, take(size), size);
  }

  // `size` bytes of array `array`'s element `index`, `offset` bytes in: where they are.
  std::span<const u8> element(int array, u32 index, size_t offset, size_t size) const {
    const VertexArray& a = arrays_[static_cast<size_t>(array)];
    if (a.stride > kMaxArrayStride) {
      throw InputError(origin_, attribute_name(array),
                       "array stride " + std::to_string(a.stride) +
                           " does not fit GX_SetArray's 8 bits (0-255)");
    }
    const size_t begin = static_cast<size_t>(index) * a.stride + offset;
    if (begin + size > a.bytes.size()) {
      throw InputError(origin_, attribute_name(array),
                       "index " + std::to_string(index) + " of vertex " +
                           std::to_string(vertex_) + " reads bytes " + std::to_string(begin) +
                           ".." + std::to_string(begin + size - 1) + ", past the array's " +
                           std::to_string(a.bytes.size()) + " bytes");
    }
    return a.bytes.subspan(begin, size);
  }
  std::span<const u8> direct(size_t size) { return stream_.subspan(take(static_cast<int>(size)), size); }

 private:
  std::span<const u8> stream_;
  const VertexArrays& arrays_;
  const std::string& origin_;
  size_t cursor_ = 0, vertex_ = 0;
};

// `count` components of `type` from `bytes`, each multiplied by `scale` when an integer type.
// The x86-64 loader converts each integer to float and multiplies it by 2^-exponent (a power of
// two: exact) [DHW VertexLoaderX64.cpp ReadVertex CVTDQ2PS, MULPS scale_factors]; floats pass
// unchanged.
std::array<float, 3> read_components(std::span<const u8> bytes, ComponentType type, int count,
                                     float scale) {
  std::array<float, 3> out{};
  const int size = component_bytes(type);
  for (int i = 0; i < count && i < 3; ++i) {
    const float v =
        component_value(type, read_big_endian(bytes, static_cast<size_t>(i * size), size));
    out[static_cast<size_t>(i)] = type == ComponentType::F32 ? v : v * scale;
  }
  return out;
}

// 2^-exponent as the loader's table holds it [DHW VertexLoaderX64.cpp scale_factors].
float power_of_half(int exponent) { return std::ldexp(1.0f, -exponent); }

}  // namespace

Color8 decode_vertex_color(ColorType type, std::span<const u8> b) {
  auto widen5 = [](u32 x) { return static_cast<u8>((x << 3) | (x >> 2)); };
  auto widen6 = [](u32 x) { return static_cast<u8>((x << 2) | (x >> 4)); };
  auto widen4 = [](u32 x) { return static_cast<u8>(x * 17); };
  switch (type) {
    case ColorType::Rgb565: {
      // RRRRRGGG GGGBBBBB, big-endian [DHW VertexLoader_Color.cpp SetCol565].
      const u32 v = (u32{b[0]} << 8) | b[1];
      return {widen5(v >> 11), widen6((v >> 5) & 63), widen5(v & 31), 255};
    }
    case ColorType::Rgb8:
    case ColorType::Rgbx8:
      // The bytes in memory order, alpha forced to 255 [DHW VertexLoader_Color.cpp Read24].
      return {b[0], b[1], b[2], 255};
    case ColorType::Rgba4:
      // RRRRGGGG BBBBAAAA [DHW VertexLoader_Color.cpp SetCol4444].
      return {widen4(b[0] >> 4), widen4(b[0] & 15u), widen4(b[1] >> 4), widen4(b[1] & 15u)};
    case ColorType::Rgba6: {
      // RRRRRRGG GGGGBBBB BBAAAAAA [DHW VertexLoader_Color.cpp SetCol6666].
      const u32 v = (u32{b[0]} << 16) | (u32{b[1]} << 8) | b[2];
      return {widen6(v >> 18), widen6((v >> 12) & 63), widen6((v >> 6) & 63), widen6(v & 63)};
    }
    default:
      return {b[0], b[1], b[2], b[3]};
  }
}

VertexLoader::VertexLoader(const VertexInputs& inputs, const VertexAttributeFormat& format,
                           std::string origin)
    : inputs_(inputs), format_(format), origin_(std::move(origin)) {
  check_vertex_format(inputs_, format_, origin_);
  // [DHW VertexLoaderBase.cpp GetVertexSize]: one byte per matrix index, then per attribute its
  // direct bytes or its index.
  size_t size = inputs_.position_matrix_index ? 1 : 0;
  for (bool t : inputs_.texture_matrix_index) size += t ? 1 : 0;
  auto index_bytes = [](AttributeInput in) -> size_t { return in == AttributeInput::Index8 ? 1 : 2; };
  auto add = [&](AttributeInput in, size_t direct_bytes, size_t indices) {
    if (in == AttributeInput::Direct) size += direct_bytes;
    if (in == AttributeInput::Index8 || in == AttributeInput::Index16)
      size += index_bytes(in) * indices;
  };
  const CoordinateFormat& p = format_.position;
  add(inputs_.position, static_cast<size_t>(p.components * component_bytes(p.type)), 1);
  const NormalFormat& n = format_.normal;
  const size_t vectors = n.nbt ? 3 : 1;
  add(inputs_.normal, vectors * 3 * static_cast<size_t>(component_bytes(n.type)),
      n.nbt && n.index3 ? 3 : 1);
  for (int c = 0; c < kVertexColors; ++c) {
    const auto i = static_cast<size_t>(c);
    add(inputs_.color[i], static_cast<size_t>(color_bytes(format_.color[i].type)), 1);
  }
  for (int t = 0; t < kVertexTexCoords; ++t) {
    const auto i = static_cast<size_t>(t);
    const CoordinateFormat& f = format_.texcoord[i];
    add(inputs_.texcoord[i], static_cast<size_t>(f.components * component_bytes(f.type)), 1);
  }
  vertex_size_ = size;
}

std::vector<LoadedVertex> VertexLoader::load(std::span<const u8> stream, size_t count,
                                             const VertexArrays& arrays) const {
  VertexReader reader(stream, arrays, origin_);
  // Positions and texture coordinates are scaled by 2^-frac only where ByteDequant is set: the
  // x86-64 loader tests it for every integer type [DHW VertexLoaderX64.cpp ReadVertex
  // "if (dequantize && scaling_exponent)"]; the portable loader ignores the bit and always
  // scales [DHW VertexLoader.cpp m_posScale]. libogc always sets it, so they agree on a game's
  // data (gx-hardware.md §8).
  auto coordinate_scale = [&](int frac) {
    return format_.byte_dequant ? power_of_half(frac) : 1.0f;
  };
  // Where an attribute's `size` bytes are, `offset` into its element when indexed.
  auto attribute_bytes = [&](AttributeInput in, int array, size_t size,
                             size_t offset) -> std::span<const u8> {
    if (in == AttributeInput::Direct) return reader.direct(size);
    return reader.element(array, reader.take_index(in), offset, size);
  };

  std::vector<LoadedVertex> out;
  out.reserve(count);
  for (size_t v = 0; v < count; ++v) {
    reader.start_vertex(v);
    const size_t vertex_start = reader.cursor();
    LoadedVertex vertex;
    // Matrix indices: one byte each, their low 6 bits [DHW VertexLoader.cpp
    // PosMtx_ReadDirect_UByte, TexMtx_ReadDirect_UByte "& 0x3f"].
    if (inputs_.position_matrix_index) vertex.position_matrix = stream[reader.take(1)] & 0x3f;
    for (int t = 0; t < kVertexTexCoords; ++t) {
      if (inputs_.texture_matrix_index[static_cast<size_t>(t)])
        vertex.texture_matrix[static_cast<size_t>(t)] = stream[reader.take(1)] & 0x3f;
    }

    const CoordinateFormat& p = format_.position;
    const size_t position_bytes = static_cast<size_t>(p.components * component_bytes(p.type));
    std::span<const u8> position;
    if (inputs_.position == AttributeInput::Direct) {
      position = reader.direct(position_bytes);
    } else {
      const u32 index = reader.take_index(inputs_.position);
      const u32 all_ones = inputs_.position == AttributeInput::Index8 ? 0xffu : 0xffffu;
      if (index == all_ones) {
        // The x86-64 loader jumps past the rest of the vertex, reading nothing more of it
        // [DHW VertexLoaderX64.cpp GetVertexAddr "CMP ... Imm8(-1)", m_skip_vertex].
        reader.take(static_cast<int>(vertex_start + vertex_size_ - reader.cursor()));
        continue;
      }
      position = reader.element(kArrayPosition, index, 0, position_bytes);
    }
    const std::array<float, 3> xyz =
        read_components(position, p.type, p.components, coordinate_scale(p.frac));
    vertex.position = {xyz[0], xyz[1], xyz[2]};

    if (inputs_.normal != AttributeInput::None) {
      const NormalFormat& n = format_.normal;
      const size_t vector_bytes = 3 * static_cast<size_t>(component_bytes(n.type));
      const float scale = power_of_half(normal_exponent(n.type));
      const int vectors = n.nbt ? 3 : 1;
      // One index per vector only for an indexed NBT3; the k-th vector is 3k components into
      // the element its index picks, even then [DHW VertexLoader_Normal.cpp
      // Normal_ReadIndex_Offset] [DHW VertexLoaderX64.cpp "even in index3 mode, this offset is
      // applied"].
      const bool index3 = n.nbt && n.index3 && inputs_.normal != AttributeInput::Direct;
      std::span<const u8> all;
      if (!index3)
        all = attribute_bytes(inputs_.normal, kArrayNormal, vector_bytes * vectors, 0);
      for (int k = 0; k < vectors; ++k) {
        const size_t offset = vector_bytes * static_cast<size_t>(k);
        const std::span<const u8> bytes =
            index3 ? attribute_bytes(inputs_.normal, kArrayNormal, vector_bytes, offset)
                   : all.subspan(offset, vector_bytes);
        const std::array<float, 3> c = read_components(bytes, n.type, 3, scale);
        vertex.normal[static_cast<size_t>(k)] = {c[0], c[1], c[2]};
      }
    }

    for (int c = 0; c < kVertexColors; ++c) {
      const auto i = static_cast<size_t>(c);
      if (inputs_.color[i] == AttributeInput::None) continue;
      const ColorType type = format_.color[i].type;
      vertex.color[i] = decode_vertex_color(
          type, attribute_bytes(inputs_.color[i], kArrayColor0 + c,
                                static_cast<size_t>(color_bytes(type)), 0));
    }

    for (int t = 0; t < kVertexTexCoords; ++t) {
      const auto i = static_cast<size_t>(t);
      if (inputs_.texcoord[i] == AttributeInput::None) continue;
      const CoordinateFormat& f = format_.texcoord[i];
      const std::array<float, 3> st = read_components(
          attribute_bytes(inputs_.texcoord[i], kArrayTexCoord0 + t,
                          static_cast<size_t>(f.components * component_bytes(f.type)), 0),
          f.type, f.components, coordinate_scale(f.frac));
      vertex.texcoord[i] = {st[0], st[1]};
    }
    out.push_back(vertex);
  }
  return out;
}

}  // namespace lt::gx
