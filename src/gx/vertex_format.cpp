#include "gx/vertex_format.h"

#include "core/error.h"

namespace lt::gx {

namespace {

constexpr u32 bits_at(u32 reg, int shift, int bits) { return (reg >> shift) & ((1u << bits) - 1); }
constexpr u32 to_bits(u32 v, int shift, int bits) { return (v & ((1u << bits) - 1)) << shift; }

u32 input_bits(AttributeInput in) { return static_cast<u32>(in); }
AttributeInput input_of(u32 bits) { return static_cast<AttributeInput>(bits); }

// The VAT's three fields of a texture coordinate: count (1 bit), type (3), shift (5).
struct TexCoordField {
  int reg, count_shift, type_shift, frac_reg, frac_shift;
};
// [DHW CPMemory.h UVAT_group0..2]: TEX0 in VAT A, TEX1-3 and TEX4's count and type in VAT B,
// TEX4's shift and TEX5-7 in VAT C.
constexpr std::array<TexCoordField, kVertexTexCoords> kTexCoordFields = {{
    {0, 21, 22, 0, 25},
    {1, 0, 1, 1, 4},
    {1, 9, 10, 1, 13},
    {1, 18, 19, 1, 22},
    {1, 27, 28, 2, 0},
    {2, 5, 6, 2, 9},
    {2, 14, 15, 2, 18},
    {2, 23, 24, 2, 27},
}};

bool known_component(ComponentType t) { return static_cast<u8>(t) <= 4; }

void check_coordinate(const CoordinateFormat& f, int min_components, int array,
                      const std::string& origin) {
  const std::string what = attribute_name(array);
  if (f.components != min_components && f.components != min_components + 1) {
    throw InputError(origin, what,
                     std::to_string(f.components) + " components: it has " +
                         std::to_string(min_components) + " or " +
                         std::to_string(min_components + 1));
  }
  if (!known_component(f.type)) {
    throw InputError(origin, what,
                     "component type " + std::to_string(static_cast<int>(f.type)) +
                         " is not one of GX_U8, GX_S8, GX_U16, GX_S16, GX_F32");
  }
  if (f.frac < 0 || f.frac > kMaxFracBits) {
    throw InputError(origin, what,
                     std::to_string(f.frac) + " fractional bits: the VAT holds 0 to 31");
  }
}

}  // namespace

VertexAttributeFormat::VertexAttributeFormat() {
  texcoord.fill(CoordinateFormat{2, ComponentType::F32, 0});
}

int component_bytes(ComponentType type) {
  switch (type) {
    case ComponentType::U8:
    case ComponentType::S8:
      return 1;
    case ComponentType::U16:
    case ComponentType::S16:
      return 2;
    default:
      return 4;
  }
}

int color_bytes(ColorType type) {
  switch (type) {
    case ColorType::Rgb565:
    case ColorType::Rgba4:
      return 2;
    case ColorType::Rgb8:
    case ColorType::Rgba6:
      return 3;
    default:
      return 4;
  }
}

int normal_exponent(ComponentType type) {
  switch (type) {
    case ComponentType::U8:
      return 7;
    case ComponentType::S8:
      return 6;
    case ComponentType::U16:
      return 15;
    case ComponentType::S16:
      return 14;
    default:
      return 0;
  }
}

std::string attribute_name(int array) {
  if (array == kArrayPosition) return "GX_VA_POS";
  if (array == kArrayNormal) return "GX_VA_NRM";
  if (array < kArrayTexCoord0) return "GX_VA_CLR" + std::to_string(array - kArrayColor0);
  return "GX_VA_TEX" + std::to_string(array - kArrayTexCoord0);
}

std::string component_type_name(ComponentType type) {
  static const char* const names[] = {"GX_U8", "GX_S8", "GX_U16", "GX_S16", "GX_F32"};
  const int t = static_cast<int>(type);
  return t <= 4 ? names[t] : "component type " + std::to_string(t);
}

std::string color_type_name(ColorType type) {
  static const char* const names[] = {"GX_RGB565", "GX_RGB8",  "GX_RGBX8",
                                      "GX_RGBA4",  "GX_RGBA6", "GX_RGBA8"};
  const int t = static_cast<int>(type);
  return t <= 5 ? names[t] : "colour type " + std::to_string(t);
}

void check_vertex_format(const VertexInputs& in, const VertexAttributeFormat& f,
                         const std::string& origin) {
  if (in.position == AttributeInput::None) {
    // Every vertex has a position: Dolphin's loaders read one whatever the descriptor says
    // [DHW VertexLoaderBase.cpp GetVertexComponents "Vertices always have positions"].
    throw InputError(origin, "GX_VA_POS", "the vertex descriptor sends no position");
  }
  check_coordinate(f.position, 2, kArrayPosition, origin);
  if (in.normal != AttributeInput::None && !known_component(f.normal.type)) {
    throw InputError(origin, "GX_VA_NRM",
                     "component type " + std::to_string(static_cast<int>(f.normal.type)) +
                         " is not one of GX_U8, GX_S8, GX_U16, GX_S16, GX_F32");
  }
  for (int c = 0; c < kVertexColors; ++c) {
    const auto i = static_cast<size_t>(c);
    if (in.color[i] != AttributeInput::None && static_cast<u8>(f.color[i].type) > 5) {
      throw InputError(origin, attribute_name(kArrayColor0 + c),
                       color_type_name(f.color[i].type) + " is not one of GX_RGB565 .. GX_RGBA8");
    }
  }
  for (int t = 0; t < kVertexTexCoords; ++t) {
    if (in.texcoord[static_cast<size_t>(t)] != AttributeInput::None)
      check_coordinate(f.texcoord[static_cast<size_t>(t)], 1, kArrayTexCoord0 + t, origin);
  }
}

std::array<u32, 2> pack_vertex_inputs(const VertexInputs& in) {
  u32 low = to_bits(in.position_matrix_index ? 1 : 0, 0, 1);
  for (int t = 0; t < kVertexTexCoords; ++t)
    low |= to_bits(in.texture_matrix_index[static_cast<size_t>(t)] ? 1 : 0, 1 + t, 1);
  low |= to_bits(input_bits(in.position), 9, 2) | to_bits(input_bits(in.normal), 11, 2) |
         to_bits(input_bits(in.color[0]), 13, 2) | to_bits(input_bits(in.color[1]), 15, 2);
  u32 high = 0;
  for (int t = 0; t < kVertexTexCoords; ++t)
    high |= to_bits(input_bits(in.texcoord[static_cast<size_t>(t)]), 2 * t, 2);
  return {low, high};
}

VertexInputs unpack_vertex_inputs(u32 low, u32 high) {
  VertexInputs in;
  in.position_matrix_index = bits_at(low, 0, 1) != 0;
  for (int t = 0; t < kVertexTexCoords; ++t)
    in.texture_matrix_index[static_cast<size_t>(t)] = bits_at(low, 1 + t, 1) != 0;
  in.position = input_of(bits_at(low, 9, 2));
  in.normal = input_of(bits_at(low, 11, 2));
  in.color[0] = input_of(bits_at(low, 13, 2));
  in.color[1] = input_of(bits_at(low, 15, 2));
  for (int t = 0; t < kVertexTexCoords; ++t)
    in.texcoord[static_cast<size_t>(t)] = input_of(bits_at(high, 2 * t, 2));
  return in;
}

std::array<u32, 3> pack_vertex_format(const VertexAttributeFormat& f) {
  std::array<u32, 3> r{0, to_bits(1, 31, 1), 0};
  auto type = [](auto t) { return static_cast<u32>(t); };
  r[0] |= to_bits(f.position.components == 3 ? 1 : 0, 0, 1) | to_bits(type(f.position.type), 1, 3) |
          to_bits(static_cast<u32>(f.position.frac), 4, 5);
  r[0] |= to_bits(f.normal.nbt ? 1 : 0, 9, 1) | to_bits(type(f.normal.type), 10, 3) |
          to_bits(f.normal.index3 ? 1 : 0, 31, 1);
  r[0] |= to_bits(f.color[0].alpha ? 1 : 0, 13, 1) | to_bits(type(f.color[0].type), 14, 3) |
          to_bits(f.color[1].alpha ? 1 : 0, 17, 1) | to_bits(type(f.color[1].type), 18, 3);
  r[0] |= to_bits(f.byte_dequant ? 1 : 0, 30, 1);
  for (int t = 0; t < kVertexTexCoords; ++t) {
    const TexCoordField& field = kTexCoordFields[static_cast<size_t>(t)];
    const CoordinateFormat& c = f.texcoord[static_cast<size_t>(t)];
    auto& reg = r[static_cast<size_t>(field.reg)];
    reg |= to_bits(c.components == 2 ? 1 : 0, field.count_shift, 1) |
           to_bits(type(c.type), field.type_shift, 3);
    r[static_cast<size_t>(field.frac_reg)] |= to_bits(static_cast<u32>(c.frac), field.frac_shift, 5);
  }
  return r;
}

VertexAttributeFormat unpack_vertex_format(u32 a, u32 b, u32 c) {
  const std::array<u32, 3> r{a, b, c};
  VertexAttributeFormat f;
  f.position = {bits_at(a, 0, 1) ? 3 : 2, static_cast<ComponentType>(bits_at(a, 1, 3)),
                static_cast<int>(bits_at(a, 4, 5))};
  f.normal = {static_cast<ComponentType>(bits_at(a, 10, 3)), bits_at(a, 9, 1) != 0,
              bits_at(a, 31, 1) != 0};
  f.color[0] = {bits_at(a, 13, 1) != 0, static_cast<ColorType>(bits_at(a, 14, 3))};
  f.color[1] = {bits_at(a, 17, 1) != 0, static_cast<ColorType>(bits_at(a, 18, 3))};
  f.byte_dequant = bits_at(a, 30, 1) != 0;
  for (int t = 0; t < kVertexTexCoords; ++t) {
    const TexCoordField& field = kTexCoordFields[static_cast<size_t>(t)];
    const u32 reg = r[static_cast<size_t>(field.reg)];
    f.texcoord[static_cast<size_t>(t)] = {
        bits_at(reg, field.count_shift, 1) ? 2 : 1,
        static_cast<ComponentType>(bits_at(reg, field.type_shift, 3)),
        static_cast<int>(bits_at(r[static_cast<size_t>(field.frac_reg)], field.frac_shift, 5))};
  }
  return f;
}

}  // namespace lt::gx
