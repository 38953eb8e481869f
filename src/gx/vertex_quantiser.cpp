#include "gx/vertex_quantiser.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <unordered_map>

#include "core/error.h"

namespace lt::gx {

namespace {

void append_big_endian(std::vector<u8>& out, u32 v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) out.push_back(static_cast<u8>(v >> (8 * i)));
}

// The stored code of one colour channel: the one of `bits` bits whose widening is nearest to
// `value`, the lower on a tie. `widen` is the loader's rule for that width.
u32 searched_channel_code(u8 value, int bits) {
  u32 best = 0;
  int best_error = 256;
  for (u32 code = 0; code < (1u << bits); ++code) {
    std::array<u8, 4> probe{};
    // The loader's own decoder widens the code (one rule, vertex_loader.h), placed in a field
    // of the width asked for: RGBA4 for 4 bits, RGBA6 for 6, RGB565 (red) for 5.
    Color8 widened;
    if (bits == 4) {
      probe[0] = static_cast<u8>(code << 4);
      widened = decode_vertex_color(ColorType::Rgba4, probe);
    } else if (bits == 6) {
      const u32 v = code << 18;
      probe = {static_cast<u8>(v >> 16), static_cast<u8>(v >> 8), static_cast<u8>(v), 0};
      widened = decode_vertex_color(ColorType::Rgba6, probe);
    } else {
      probe[0] = static_cast<u8>(code << 3);
      widened = decode_vertex_color(ColorType::Rgb565, probe);
    }
    const int error = std::abs(static_cast<int>(widened.r) - static_cast<int>(value));
    if (error < best_error) {
      best_error = error;
      best = code;
    }
  }
  return best;
}

// searched_channel_code of every value, searched once a width: each vertex colour asks it per
// channel, and the search widens up to 64 codes (~5% of a storage-advising run, perf).
u32 nearest_channel_code(u8 value, int bits) {
  using Table = std::array<u32, 256>;
  static const std::array<Table, 3> tables = [] {
    std::array<Table, 3> t{};
    for (int w = 0; w < 3; ++w)
      for (int v = 0; v < 256; ++v)
        t[static_cast<size_t>(w)][static_cast<size_t>(v)] =
            searched_channel_code(static_cast<u8>(v), 4 + w);
    return t;
  }();
  LT_CHECK(bits >= 4 && bits <= 6, "a vertex colour channel is 4, 5 or 6 bits");
  return tables[static_cast<size_t>(bits - 4)][value];
}

// The largest element an array holds: an NBT of F32 normals, 3 x 3 x 4 bytes.
constexpr size_t kLargestElement = 36;

size_t coordinate_bytes(const CoordinateFormat& f) {
  return static_cast<size_t>(f.components * component_bytes(f.type));
}

}  // namespace

IntegerRange integer_range(ComponentType type) {
  switch (type) {
    case ComponentType::U8:
      return {0, 255};
    case ComponentType::S8:
      return {-128, 127};
    case ComponentType::U16:
      return {0, 65535};
    default:
      return {-32768, 32767};
  }
}

std::optional<long> quantise_component(double v, ComponentType type, int exponent) {
  const double scaled = std::ldexp(v, exponent);
  const IntegerRange r = integer_range(type);
  if (!std::isfinite(scaled) || scaled < static_cast<double>(r.lo) - 0.5 ||
      scaled > static_cast<double>(r.hi) + 0.5) {
    return std::nullopt;
  }
  // std::round rounds halves away from zero; the clamp takes the half step past either end.
  return std::clamp(static_cast<long>(std::round(scaled)), r.lo, r.hi);
}

std::optional<int> widest_fraction(double lo, double hi, ComponentType type) {
  for (int frac = kMaxFracBits; frac >= 0; --frac) {
    if (quantise_component(lo, type, frac) && quantise_component(hi, type, frac)) return frac;
  }
  return std::nullopt;
}

void append_components(std::vector<u8>& out, std::span<const float> values, ComponentType type,
                       int exponent) {
  const int size = component_bytes(type);
  for (float v : values) {
    if (type == ComponentType::F32) {
      append_big_endian(out, std::bit_cast<u32>(v), 4);
      continue;
    }
    const std::optional<long> q = quantise_component(v, type, exponent);
    LT_CHECK(q.has_value(), "a value the storage format cannot hold reached the quantiser");
    append_big_endian(out, static_cast<u32>(*q), size);
  }
}

void append_color(std::vector<u8>& out, Color8 c, ColorType type) {
  switch (type) {
    case ColorType::Rgb565: {
      const u32 v = nearest_channel_code(c.r, 5) << 11 | nearest_channel_code(c.g, 6) << 5 |
                    nearest_channel_code(c.b, 5);
      append_big_endian(out, v, 2);
      return;
    }
    case ColorType::Rgba4: {
      const u32 v = nearest_channel_code(c.r, 4) << 12 | nearest_channel_code(c.g, 4) << 8 |
                    nearest_channel_code(c.b, 4) << 4 | nearest_channel_code(c.a, 4);
      append_big_endian(out, v, 2);
      return;
    }
    case ColorType::Rgba6: {
      const u32 v = nearest_channel_code(c.r, 6) << 18 | nearest_channel_code(c.g, 6) << 12 |
                    nearest_channel_code(c.b, 6) << 6 | nearest_channel_code(c.a, 6);
      append_big_endian(out, v, 3);
      return;
    }
    case ColorType::Rgb8:
    case ColorType::Rgbx8:
      out.insert(out.end(), {c.r, c.g, c.b});
      if (type == ColorType::Rgbx8) out.push_back(0);  // the unused byte X
      return;
    default:
      out.insert(out.end(), {c.r, c.g, c.b, c.a});
  }
}

std::pair<glm::vec3, glm::vec3> normal_frame(const glm::vec3& n) {
  // Duff et al. 2017, listing 3: continuous but for n.z = 0's sign, exact to float rounding.
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  return {glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
          glm::vec3(b, sign + n.y * n.y * a, -n.y)};
}

void add_normal_frames(VertexAttributeData& d) {
  d.binormal.clear();
  d.tangent.clear();
  for (const glm::vec3& n : d.normal) {
    const auto [b, t] = normal_frame(n);
    d.binormal.push_back(b);
    d.tangent.push_back(t);
  }
}

void ValueBounds::add(double v) {
  lo = empty ? v : std::min(lo, v);
  hi = empty ? v : std::max(hi, v);
  empty = false;
}

AttributeBounds attribute_bounds(const VertexAttributeData& d) {
  AttributeBounds b;
  for (const glm::vec3& p : d.position) {
    for (int c = 0; c < 3; ++c) b.position.add(p[c]);
  }
  for (const glm::vec3& n : d.normal) {
    for (int c = 0; c < 3; ++c) b.normal.add(n[c]);
  }
  for (int t = 0; t < kVertexTexCoords; ++t) {
    const auto i = static_cast<size_t>(t);
    for (const glm::vec2& uv : d.texcoord[i]) {
      for (int c = 0; c < d.texcoord_components[i]; ++c) b.texcoord[i].add(uv[c]);
    }
  }
  return b;
}

VertexInputs sent_inputs(const VertexAttributeData& d, AttributeInput input) {
  VertexInputs in;
  in.position = input;
  if (!d.normal.empty()) in.normal = input;
  for (size_t c = 0; c < kVertexColors; ++c) {
    if (!d.color[c].empty()) in.color[c] = input;
  }
  for (size_t t = 0; t < kVertexTexCoords; ++t) {
    if (!d.texcoord[t].empty()) in.texcoord[t] = input;
  }
  return in;
}

std::vector<AttributeElements> quantise_attributes(const VertexAttributeData& d,
                                                   const VertexAttributeFormat& f) {
  const size_t n = d.vertex_count();
  std::vector<AttributeElements> out;
  AttributeElements position{kArrayPosition, coordinate_bytes(f.position), {}};
  for (const glm::vec3& p : d.position) {
    const std::array<float, 3> xyz{p.x, p.y, p.z};
    append_components(position.bytes,
                      std::span(xyz).first(static_cast<size_t>(f.position.components)),
                      f.position.type, f.position.frac);
  }
  out.push_back(std::move(position));
  if (!d.normal.empty()) {
    LT_CHECK(d.normal.size() == n, "one normal per vertex");
    LT_CHECK(!f.normal.nbt || (d.binormal.size() == n && d.tangent.size() == n),
             "an NBT needs a binormal and a tangent per vertex");
    // An NBT element is the normal, the binormal and the tangent, nine components in the
    // normal's type [DHW VertexLoader_Normal.cpp: 3 vectors x 3 components].
    const size_t vectors = f.normal.nbt ? 3 : 1;
    AttributeElements normal{kArrayNormal,
                             vectors * 3 * static_cast<size_t>(component_bytes(f.normal.type)),
                             {},
                             f.normal.nbt && f.normal.index3 ? 3 : 1};
    const int e = normal_exponent(f.normal.type);
    for (size_t v = 0; v < n; ++v) {
      for (const std::vector<glm::vec3>* vs : {&d.normal, &d.binormal, &d.tangent}) {
        if (vs != &d.normal && !f.normal.nbt) continue;
        const glm::vec3& x = (*vs)[v];
        const std::array<float, 3> xyz{x.x, x.y, x.z};
        append_components(normal.bytes, xyz, f.normal.type, e);
      }
    }
    out.push_back(std::move(normal));
  }
  for (int c = 0; c < kVertexColors; ++c) {
    const auto i = static_cast<size_t>(c);
    if (d.color[i].empty()) continue;
    LT_CHECK(d.color[i].size() == n, "one colour per vertex");
    AttributeElements color{
        kArrayColor0 + c, static_cast<size_t>(color_bytes(f.color[i].type)), {}};
    for (const Color8& v : d.color[i]) append_color(color.bytes, v, f.color[i].type);
    out.push_back(std::move(color));
  }
  for (int t = 0; t < kVertexTexCoords; ++t) {
    const auto i = static_cast<size_t>(t);
    if (d.texcoord[i].empty()) continue;
    LT_CHECK(d.texcoord[i].size() == n, "one texture coordinate per vertex");
    const CoordinateFormat& cf = f.texcoord[i];
    LT_CHECK(cf.components == d.texcoord_components[i], "the format's count is the data's");
    // A one-component coordinate is a pass's t (scene_vertices.h pass_vertex_data): per vertex.
    AttributeElements tc{kArrayTexCoord0 + t, coordinate_bytes(cf), {}, 1, cf.components == 1};
    for (const glm::vec2& uv : d.texcoord[i]) {
      const std::array<float, 2> st{uv.x, uv.y};
      append_components(tc.bytes, std::span(st).first(static_cast<size_t>(cf.components)), cf.type,
                        cf.frac);
    }
    out.push_back(std::move(tc));
  }
  return out;
}

std::vector<u8> direct_vertex_stream(const std::vector<AttributeElements>& elements,
                                     std::span<const u32> vertices) {
  std::vector<u8> out;
  for (u32 v : vertices) {
    for (const AttributeElements& e : elements) {
      const auto begin = e.bytes.begin() + static_cast<long>(v * e.element_bytes);
      out.insert(out.end(), begin, begin + static_cast<long>(e.element_bytes));
    }
  }
  return out;
}

VertexArrays IndexedArrays::views() const {
  VertexArrays v;
  for (size_t a = 0; a < kVertexArrays; ++a) v[a] = {bytes[a], stride[a]};
  return v;
}

namespace {

using IndexElementKey = std::array<u8, kLargestElement>;

struct IndexElementKeyHash {
  size_t operator()(const IndexElementKey& k) const {
    return std::hash<std::string_view>{}(
        std::string_view(reinterpret_cast<const char*>(k.data()), k.size()));
  }
};

}  // namespace

IndexedArrays index_attributes(const std::vector<AttributeElements>& elements,
                               const std::string& origin) {
  IndexedArrays out;
  for (const AttributeElements& e : elements) {
    const auto a = static_cast<size_t>(e.array);
    out.arrays.push_back(e.array);
    out.stride[a] = static_cast<unsigned>(e.element_bytes);
    // Elements as fixed-size keys, zero-padded (every element of an attribute has one size),
    // hashed: each element is numbered in the order it first appears, whatever the container,
    // and an ordered map's byte comparisons were ~12% of a storage-advising run (perf).
    LT_CHECK(e.element_bytes <= kLargestElement, "an element larger than an NBT of floats");
    std::unordered_map<IndexElementKey, u32, IndexElementKeyHash> seen;
    seen.reserve(e.bytes.size() / e.element_bytes);
    const size_t n = e.bytes.size() / e.element_bytes;
    for (size_t v = 0; v < n; ++v) {
      const auto begin = e.bytes.begin() + static_cast<long>(v * e.element_bytes);
      const auto end = begin + static_cast<long>(e.element_bytes);
      if (e.per_vertex) {
        out.element_of_vertex[a].push_back(static_cast<u32>(v));
        continue;
      }
      IndexElementKey key{};
      std::copy(begin, end, key.begin());
      const auto [it, added] = seen.emplace(key, static_cast<u32>(seen.size()));
      if (added) out.bytes[a].insert(out.bytes[a].end(), begin, end);
      out.element_of_vertex[a].push_back(it->second);
    }
    if (e.per_vertex) out.bytes[a] = e.bytes;
    const size_t count = e.per_vertex ? n : seen.size();
    if (count > 65535) {
      throw InputError(origin, attribute_name(e.array),
                       std::to_string(count) + (e.per_vertex ? " elements" : " distinct elements") +
                           ": GX_INDEX16 reaches 65,535 (an index of 0xFFFF "
                           "drops its vertex)");
    }
    out.input[a] = count <= 255 ? AttributeInput::Index8 : AttributeInput::Index16;
    out.indices[a] = e.indices;
  }
  return out;
}

VertexInputs indexed_inputs(const IndexedArrays& arrays) {
  VertexInputs in;
  for (int a : arrays.arrays) {
    const AttributeInput input = arrays.input[static_cast<size_t>(a)];
    if (a == kArrayPosition)
      in.position = input;
    else if (a == kArrayNormal)
      in.normal = input;
    else if (a < kArrayTexCoord0)
      in.color[static_cast<size_t>(a - kArrayColor0)] = input;
    else
      in.texcoord[static_cast<size_t>(a - kArrayTexCoord0)] = input;
  }
  return in;
}

std::vector<u8> indexed_vertex_stream(const IndexedArrays& arrays, std::span<const u32> vertices) {
  std::vector<u8> out;
  for (u32 v : vertices) {
    for (int a : arrays.arrays) {
      const auto i = static_cast<size_t>(a);
      for (int k = 0; k < arrays.indices[i]; ++k)
        append_big_endian(out, arrays.element_of_vertex[i][v],
                          arrays.input[i] == AttributeInput::Index8 ? 1 : 2);
    }
  }
  return out;
}

}  // namespace lt::gx
