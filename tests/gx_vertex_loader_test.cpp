// The command processor's vertex loader (src/gx/vertex_loader.h) against closed forms of the rules
// it cites: an integer component with f fractional bits is exactly v * 2^-f (ldexp), a normal's
// exponent is fixed by its type, colours widen by bit replication (5 bits: floor(33x / 4), 6 bits:
// floor(65x / 16), 4 bits: 17x), every number is big-endian, an index reads base + index *
// stride. The expected values are written from those rules, not from the loader's output.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <functional>

#include "core/error.h"
#include "gx/vertex_loader.h"
#include "gx/fifo/cp_registers.h"

namespace lt::gx {
namespace {

using Bytes = std::vector<u8>;

void put16(Bytes& b, u32 v) {
  b.push_back(static_cast<u8>(v >> 8));
  b.push_back(static_cast<u8>(v));
}

VertexInputs position_only(AttributeInput in) {
  VertexInputs v;
  v.position = in;
  return v;
}

VertexAttributeFormat position_format(int components, ComponentType type, int frac) {
  VertexAttributeFormat f;
  f.position = {components, type, frac};
  return f;
}

std::vector<LoadedVertex> load(const VertexInputs& in, const VertexAttributeFormat& f,
                               const Bytes& stream, size_t count, const VertexArrays& arrays = {}) {
  return VertexLoader(in, f, "test").load(stream, count, arrays);
}

// The signed value of `raw` read as `type` (the test's own reading of two's complement).
double integer_value(ComponentType type, u32 raw) {
  switch (type) {
    case ComponentType::S8:
      return raw >= 0x80 ? static_cast<double>(raw) - 256.0 : raw;
    case ComponentType::S16:
      return raw >= 0x8000 ? static_cast<double>(raw) - 65536.0 : raw;
    default:
      return raw;
  }
}

TEST(GxVertexLoader, S16PositionWithEightFractionalBitsIsTheValueOver256) {
  // 0x0180 = 384 = 1.5 * 256; 0xFE80 = -384; 0x7FFF = 32767 / 256.
  Bytes s;
  for (u32 v : {0x0180u, 0xFE80u, 0x7FFFu}) put16(s, v);
  const auto out =
      load(position_only(AttributeInput::Direct), position_format(3, ComponentType::S16, 8), s, 1);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].position.x, 1.5f);
  EXPECT_EQ(out[0].position.y, -1.5f);
  EXPECT_EQ(out[0].position.z, 32767.0f / 256.0f);
}

TEST(GxVertexLoader, EveryIntegerTypeAndFractionIsExactlyTheIntegerTimesTwoToMinusFrac) {
  struct Case {
    ComponentType type;
    std::vector<u32> raws;
  };
  const std::vector<Case> cases = {
      {ComponentType::U8, {0x00, 0x01, 0x7f, 0x80, 0xff}},
      {ComponentType::S8, {0x00, 0x01, 0x7f, 0x80, 0xff}},
      {ComponentType::U16, {0x0000, 0x0001, 0x7fff, 0x8000, 0xffff}},
      {ComponentType::S16, {0x0000, 0x0001, 0x7fff, 0x8000, 0xffff}},
  };
  for (const Case& c : cases) {
    for (int frac : {0, 1, 6, 7, 8, 14, 15, 16, 24, 31}) {
      // Each raw value as GX_TEX_S of its own vertex, after a two-byte u8 XY position.
      VertexInputs in = position_only(AttributeInput::Direct);
      VertexAttributeFormat f = position_format(2, ComponentType::U8, 0);
      Bytes stream;
      for (u32 raw : c.raws) {
        stream.push_back(0);
        stream.push_back(0);
        if (component_bytes(c.type) == 1) stream.push_back(static_cast<u8>(raw));
        else put16(stream, raw);
      }
      in.texcoord[0] = AttributeInput::Direct;
      f.texcoord[0] = {1, c.type, frac};
      const auto out = load(in, f, stream, c.raws.size());
      ASSERT_EQ(out.size(), c.raws.size());
      for (size_t i = 0; i < c.raws.size(); ++i) {
        const double expected = std::ldexp(integer_value(c.type, c.raws[i]), -frac);
        EXPECT_EQ(static_cast<double>(out[i].texcoord[0].x), expected)
            << component_type_name(c.type) << " frac " << frac << " raw " << c.raws[i];
        EXPECT_EQ(out[i].texcoord[0].y, 0.0f);  // GX_TEX_S: t stays 0
      }
    }
  }
}

TEST(GxVertexLoader, FloatsAreBigEndianAndIgnoreTheFraction) {
  Bytes s;
  for (u32 word : {0x3FC00000u, 0xC0490FDBu}) {  // 1.5f, -3.14159274f
    put16(s, word >> 16);
    put16(s, word & 0xffff);
  }
  const auto out =
      load(position_only(AttributeInput::Direct), position_format(2, ComponentType::F32, 8), s, 1);
  EXPECT_EQ(out[0].position.x, 1.5f);
  EXPECT_EQ(out[0].position.y, -3.14159274f);
  EXPECT_EQ(out[0].position.z, 0.0f);  // GX_POS_XY: z is 0
}

TEST(GxVertexLoader, NormalsUseTheTypesFixedExponent) {
  // s8: 6 (0x40 = 64 -> 1), u8: 7 (0x80 -> 1), s16: 14 (0x4000 -> 1), u16: 15 (0x8000 -> 1).
  struct Case {
    ComponentType type;
    Bytes bytes;
    glm::vec3 expected;
  };
  const std::vector<Case> cases = {
      {ComponentType::S8, {0x40, 0xC0, 0x01}, {1.0f, -1.0f, 1.0f / 64}},
      {ComponentType::U8, {0x80, 0xFF, 0x01}, {1.0f, 255.0f / 128, 1.0f / 128}},
      {ComponentType::S16, {0x40, 0x00, 0xC0, 0x00, 0x7F, 0xFF}, {1.0f, -1.0f, 32767.0f / 16384}},
      {ComponentType::U16, {0x80, 0x00, 0x00, 0x01, 0xFF, 0xFF}, {1.0f, 1.0f / 32768, 65535.0f / 32768}},
  };
  for (const Case& c : cases) {
    VertexInputs in = position_only(AttributeInput::Direct);
    in.normal = AttributeInput::Direct;
    VertexAttributeFormat f = position_format(2, ComponentType::U8, 0);
    f.normal.type = c.type;
    Bytes s{0, 0};
    s.insert(s.end(), c.bytes.begin(), c.bytes.end());
    const auto out = load(in, f, s, 1);
    EXPECT_EQ(out[0].normal[0], c.expected) << component_type_name(c.type);
  }
  EXPECT_EQ(normal_exponent(ComponentType::S8), 6);
  EXPECT_EQ(normal_exponent(ComponentType::S16), 14);
}

TEST(GxVertexLoader, ColoursWidenByBitReplication) {
  for (u32 x = 0; x < 32; ++x) {
    // RGB565 with r = b = x and g = 2x + 1: each field widened on its own.
    const u32 g = 2 * x + 1;
    const u32 v = (x << 11) | (g << 5) | x;
    const Bytes b{static_cast<u8>(v >> 8), static_cast<u8>(v)};
    const Color8 c = decode_vertex_color(ColorType::Rgb565, b);
    EXPECT_EQ(c, (Color8{static_cast<u8>(33 * x / 4), static_cast<u8>(65 * g / 16),
                         static_cast<u8>(33 * x / 4), 255}))
        << x;
  }
  for (u32 x = 0; x < 16; ++x) {
    const u32 y = 15 - x;
    const Bytes b{static_cast<u8>(x << 4 | y), static_cast<u8>(y << 4 | x)};
    EXPECT_EQ(decode_vertex_color(ColorType::Rgba4, b),
              (Color8{static_cast<u8>(17 * x), static_cast<u8>(17 * y), static_cast<u8>(17 * y),
                      static_cast<u8>(17 * x)}));
  }
  for (u32 x = 0; x < 64; ++x) {
    const u32 y = 63 - x;
    const u32 v = (x << 18) | (y << 12) | (x << 6) | y;  // RRRRRRGG GGGGBBBB BBAAAAAA
    const Bytes b{static_cast<u8>(v >> 16), static_cast<u8>(v >> 8), static_cast<u8>(v)};
    const u8 wx = static_cast<u8>(65 * x / 16), wy = static_cast<u8>(65 * y / 16);
    EXPECT_EQ(decode_vertex_color(ColorType::Rgba6, b), (Color8{wx, wy, wx, wy}));
  }
  const Bytes four{10, 20, 30, 40};
  EXPECT_EQ(decode_vertex_color(ColorType::Rgb8, four), (Color8{10, 20, 30, 255}));
  EXPECT_EQ(decode_vertex_color(ColorType::Rgbx8, four), (Color8{10, 20, 30, 255}));
  EXPECT_EQ(decode_vertex_color(ColorType::Rgba8, four), (Color8{10, 20, 30, 40}));
  // Bit replication is not rounding: 5-bit 3 gives 24 where round(3 * 255 / 31) is 25.
  EXPECT_EQ(decode_vertex_color(ColorType::Rgb565, Bytes{0x18, 0x00}).r, 24);
}

TEST(GxVertexLoader, IndicesReadBasePlusIndexTimesStride) {
  // Positions s16 XYZ (6 bytes) in elements of stride 8; colours RGBA8 at stride 4; the index
  // of the position is 16-bit, the colour's 8-bit.
  Bytes positions;
  for (int e = 0; e < 4; ++e) {
    for (int c = 0; c < 3; ++c) put16(positions, static_cast<u32>(e * 16 + c));
    put16(positions, 0xDEAD);  // padding the stride skips
  }
  const Bytes colors{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  VertexArrays arrays;
  arrays[kArrayPosition] = {positions, 8};
  arrays[kArrayColor0] = {colors, 4};
  VertexInputs in = position_only(AttributeInput::Index16);
  in.color[0] = AttributeInput::Index8;
  VertexAttributeFormat f = position_format(3, ComponentType::S16, 4);
  const Bytes stream{0x00, 0x03, 0x02, 0x00, 0x01, 0x00};  // (pos 3, clr 2), (pos 1, clr 0)
  const auto out = load(in, f, stream, 2, arrays);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].position, glm::vec3(48.0f / 16, 49.0f / 16, 50.0f / 16));
  EXPECT_EQ(out[0].color[0], (Color8{9, 10, 11, 12}));
  EXPECT_EQ(out[1].position, glm::vec3(1.0f, 17.0f / 16, 18.0f / 16));
  EXPECT_EQ(out[1].color[0], (Color8{1, 2, 3, 4}));
}

TEST(GxVertexLoader, Nbt3GivesEachVectorItsOwnIndexAndKeepsItsOffset) {
  // s8 normals; element e holds nine bytes 9e .. 9e+8 (stride 9). With three indices (2, 0, 1),
  // the normal reads element 2's bytes 0-2, the second vector element 0's bytes 3-5, the third
  // element 1's bytes 6-8 [DHW VertexLoaderX64.cpp: the offset applies in index3 mode too].
  Bytes normals;
  for (int i = 0; i < 27; ++i) normals.push_back(static_cast<u8>(i));
  VertexArrays arrays;
  arrays[kArrayNormal] = {normals, 9};
  VertexInputs in = position_only(AttributeInput::Direct);
  in.normal = AttributeInput::Index8;
  VertexAttributeFormat f = position_format(2, ComponentType::U8, 0);
  f.normal = {ComponentType::S8, true, true};
  const Bytes stream{0, 0, 2, 0, 1};
  const auto out = load(in, f, stream, 1, arrays);
  auto v = [](int a) { return glm::vec3(a / 64.0f, (a + 1) / 64.0f, (a + 2) / 64.0f); };
  EXPECT_EQ(out[0].normal[0], v(18));
  EXPECT_EQ(out[0].normal[1], v(3));
  EXPECT_EQ(out[0].normal[2], v(15));
  // Without index3 one index reads all nine bytes of its element.
  f.normal.index3 = false;
  const auto one = load(in, f, Bytes{0, 0, 1}, 1, arrays);
  EXPECT_EQ(one[0].normal[0], v(9));
  EXPECT_EQ(one[0].normal[1], v(12));
  EXPECT_EQ(one[0].normal[2], v(15));
}

TEST(GxVertexLoader, VertexSizeCountsDirectBytesAndIndices) {
  VertexInputs in;
  in.position_matrix_index = true;                    // 1
  in.texture_matrix_index[3] = true;                  // 1
  in.position = AttributeInput::Direct;               // s16 XYZ: 6
  in.normal = AttributeInput::Index8;                 // 1
  in.color[0] = AttributeInput::Direct;               // RGB565: 2
  in.color[1] = AttributeInput::Direct;               // RGBA6: 3
  in.texcoord[0] = AttributeInput::Index16;           // 2
  in.texcoord[5] = AttributeInput::Direct;            // u8 S: 1
  VertexAttributeFormat f = position_format(3, ComponentType::S16, 8);
  f.normal.type = ComponentType::S8;
  f.color[0].type = ColorType::Rgb565;
  f.color[1].type = ColorType::Rgba6;
  f.texcoord[5] = {1, ComponentType::U8, 0};
  EXPECT_EQ(VertexLoader(in, f, "t").vertex_size(), 1u + 1 + 6 + 1 + 2 + 3 + 2 + 1);
  // An indexed NBT3 sends three indices; a direct NBT nine components.
  f.normal = {ComponentType::S16, true, true};
  in.normal = AttributeInput::Index16;
  EXPECT_EQ(VertexLoader(in, f, "t").vertex_size(), 1u + 1 + 6 + 6 + 2 + 3 + 2 + 1);
  in.normal = AttributeInput::Direct;
  EXPECT_EQ(VertexLoader(in, f, "t").vertex_size(), 1u + 1 + 6 + 18 + 2 + 3 + 2 + 1);
  // The F32 stream ltrender draws today: 12 + 12 + 4 + 4 = 32 bytes, the FIFO's own count.
  VertexInputs today = position_only(AttributeInput::Direct);
  today.normal = today.color[0] = today.texcoord[0] = AttributeInput::Direct;
  VertexAttributeFormat today_format;
  today_format.texcoord[0].components = 1;
  VertexDescriptor descriptor;
  descriptor.type[kVaPos] = descriptor.type[kVaNrm] = descriptor.type[kVaClr0] =
      descriptor.type[kVaTex0] = 1;
  EXPECT_EQ(VertexLoader(today, today_format, "t").vertex_size(),
            fifo::vertex_size(descriptor, TexCoordFormats{}));
}

TEST(GxVertexLoader, MatrixIndicesKeepTheirLowSixBitsAndComeFirst) {
  VertexInputs in = position_only(AttributeInput::Direct);
  in.position_matrix_index = true;
  in.texture_matrix_index[1] = true;
  const Bytes stream{0xC3, 0x7E, 5, 6};
  const auto out = load(in, position_format(2, ComponentType::U8, 0), stream, 1);
  EXPECT_EQ(out[0].position_matrix, 3);
  EXPECT_EQ(out[0].texture_matrix[1], 0x3E);
  EXPECT_EQ(out[0].position, glm::vec3(5, 6, 0));
}

TEST(GxVertexLoader, APositionIndexOfAllOnesDropsTheVertex) {
  const Bytes positions{1, 2, 3, 4};
  VertexArrays arrays;
  arrays[kArrayPosition] = {positions, 2};
  VertexInputs in = position_only(AttributeInput::Index8);
  in.color[0] = AttributeInput::Direct;
  VertexAttributeFormat f = position_format(2, ComponentType::U8, 0);
  f.color[0].type = ColorType::Rgb8;
  // Vertex 1's index is 0xFF: dropped with its colour bytes, nothing of it read.
  const Bytes stream{0, 9, 9, 9, 0xFF, 7, 7, 7, 1, 8, 8, 8};
  const auto out = load(in, f, stream, 3, arrays);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].position, glm::vec3(1, 2, 0));
  EXPECT_EQ(out[1].position, glm::vec3(3, 4, 0));
  EXPECT_EQ(out[1].color[0], (Color8{8, 8, 8, 255}));
}

TEST(GxVertexLoader, WithoutByteDequantIntegersAreNotScaled) {
  // Dolphin's x86-64 loader scales positions and texture coordinates only with VAT A bit 30 set
  // (libogc always sets it); normals always keep their exponent.
  VertexInputs in = position_only(AttributeInput::Direct);
  in.normal = AttributeInput::Direct;
  VertexAttributeFormat f = position_format(2, ComponentType::S16, 8);
  f.normal.type = ComponentType::S8;
  f.byte_dequant = false;
  const Bytes stream{0x01, 0x80, 0x00, 0x02, 0x40, 0x40, 0x40};
  const auto out = load(in, f, stream, 1);
  EXPECT_EQ(out[0].position, glm::vec3(384, 2, 0));
  EXPECT_EQ(out[0].normal[0], glm::vec3(1, 1, 1));
}

TEST(GxVertexLoader, PackedRegistersMatchLibogcsBitsAndTheFifoLogsEncoder) {
  // GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_POS, GX_POS_XYZ, GX_S16, 8) on GX_Init's VAT A
  // (0x40000000) [OGC gx.c __SETVCDFMT]: count 1 at bit 0, GX_S16 (3) at 1-3, 8 at 4-8.
  VertexAttributeFormat f;
  f.position = {3, ComponentType::S16, 8};
  const u32 a = pack_vertex_format(f)[0];
  EXPECT_EQ(a & 0x1ffu, 0x87u);
  EXPECT_EQ(a & 0x40000000u, 0x40000000u);
  // The stream ltrender sends today, as the FIFO log encodes it (a second implementation).
  VertexAttributeFormat today;
  today.texcoord[0].components = 1;
  EXPECT_EQ(pack_vertex_format(today), fifo::vertex_attribute_formats(TexCoordFormats{}));
  VertexInputs in = position_only(AttributeInput::Index16);
  in.normal = AttributeInput::Index8;
  in.color = {AttributeInput::Direct, AttributeInput::None};
  in.texcoord[7] = AttributeInput::Index16;
  in.texture_matrix_index[7] = true;
  EXPECT_EQ(unpack_vertex_inputs(pack_vertex_inputs(in)[0], pack_vertex_inputs(in)[1]), in);
  // Every field survives a round trip.
  VertexAttributeFormat g;
  g.position = {2, ComponentType::U8, 31};
  g.normal = {ComponentType::S16, true, true};
  g.color = {ColorFormat{false, ColorType::Rgb565}, ColorFormat{true, ColorType::Rgba6}};
  for (int t = 0; t < kVertexTexCoords; ++t)
    g.texcoord[static_cast<size_t>(t)] = {1 + t % 2, static_cast<ComponentType>(t % 5), 3 * t + 1};
  g.byte_dequant = false;
  const auto r = pack_vertex_format(g);
  EXPECT_EQ(unpack_vertex_format(r[0], r[1], r[2]), g);
}

void expect_loader_error(const std::function<void()>& f, const std::string& where,
                        const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << where;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "frame.dff");
    EXPECT_EQ(e.where(), where);
    EXPECT_NE(e.what_only().find(part), std::string::npos) << e.what_only();
  }
}

TEST(GxVertexLoader, BadInputNamesTheAttribute) {
  const Bytes positions{1, 2, 3, 4};
  VertexArrays arrays;
  arrays[kArrayPosition] = {positions, 2};
  const VertexInputs indexed = position_only(AttributeInput::Index8);
  const VertexAttributeFormat xy = position_format(2, ComponentType::U8, 0);
  // Index 2 of a two-element array.
  expect_loader_error(
      [&] { VertexLoader(indexed, xy, "frame.dff").load(Bytes{2}, 1, arrays); }, "GX_VA_POS",
      "index 2 of vertex 0 reads bytes 4..5, past the array's 4 bytes");
  // A stride GX_SetArray cannot hold.
  VertexArrays wide = arrays;
  wide[kArrayPosition].stride = 256;
  expect_loader_error([&] { VertexLoader(indexed, xy, "frame.dff").load(Bytes{0}, 1, wide); },
                     "GX_VA_POS", "does not fit");
  // Formats an attribute cannot have.
  VertexInputs colored = position_only(AttributeInput::Direct);
  colored.color[1] = AttributeInput::Direct;
  VertexAttributeFormat bad_color = xy;
  bad_color.color[1].type = static_cast<ColorType>(6);
  expect_loader_error([&] { VertexLoader(colored, bad_color, "frame.dff"); }, "GX_VA_CLR1",
                     "not one of GX_RGB565");
  expect_loader_error(
      [&] { VertexLoader(colored, position_format(2, static_cast<ComponentType>(5), 0), "frame.dff"); },
      "GX_VA_POS", "not one of GX_U8");
  VertexInputs textured = colored;
  textured.texcoord[2] = AttributeInput::Direct;
  VertexAttributeFormat three = xy;
  three.texcoord[2].components = 3;
  expect_loader_error([&] { VertexLoader(textured, three, "frame.dff"); }, "GX_VA_TEX2",
                     "3 components");
  VertexAttributeFormat deep = xy;
  deep.position.frac = 32;
  expect_loader_error([&] { VertexLoader(colored, deep, "frame.dff"); }, "GX_VA_POS",
                     "32 fractional bits");
  // A stream that ends inside a vertex.
  expect_loader_error(
      [&] { VertexLoader(colored, xy, "frame.dff").load(Bytes{1, 2, 3, 4, 5, 6, 7}, 2, {}); },
      "vertex 1", "ends at byte 7");
}

}  // namespace
}  // namespace lt::gx
