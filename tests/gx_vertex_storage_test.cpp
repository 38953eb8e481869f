// The converter's side of the vertex loader (src/gx/vertex_quantiser.h, vertex_storage.h): a
// mesh's floats stored in a vertex format and read back by the loader (vertex_loader.h) land
// within half a step of where they were, the auto mode picks the widest fraction the bounds
// allow (worked out by hand below), and what a format cannot hold is refused naming its key.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "core/error.h"
#include "gx/vertex_loader.h"
#include "gx/vertex_storage.h"

namespace lt::gx {
namespace {

// A seeded mesh: positions in [-r, r], unit normals, colours, a UV in [0, 1] and a t in [-2, 2].
VertexAttributeData seeded_mesh(size_t n, float r, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-r, r), unit(0.0f, 1.0f), t(-2.0f, 2.0f);
  std::uniform_int_distribution<int> byte(0, 255);
  VertexAttributeData d;
  for (size_t v = 0; v < n; ++v) {
    d.position.emplace_back(pos(rng), pos(rng), pos(rng));
    glm::vec3 nrm(pos(rng), pos(rng), pos(rng));
    const float len = std::sqrt(nrm.x * nrm.x + nrm.y * nrm.y + nrm.z * nrm.z);
    d.normal.push_back(len > 0 ? nrm / len : glm::vec3(0, 0, 1));
    d.color[0].push_back(Color8{static_cast<u8>(byte(rng)), static_cast<u8>(byte(rng)),
                                static_cast<u8>(byte(rng)), static_cast<u8>(byte(rng))});
    d.texcoord[0].emplace_back(t(rng), 0.0f);
    d.texcoord[1].emplace_back(unit(rng), unit(rng));
  }
  d.texcoord_components[0] = 1;
  return d;
}

std::vector<u32> identity_order(size_t n) {
  std::vector<u32> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = static_cast<u32>(i);
  return v;
}

// What the loader reads back from the mesh stored as `key`, sent directly.
std::vector<LoadedVertex> round_trip(const VertexAttributeData& d, const std::string& key,
                                     VertexAttributeFormat* format_out = nullptr) {
  const VertexAttributeFormat f = storage_format(parse_vertex_storage(key, "test"), d, "test");
  if (format_out) *format_out = f;
  const auto elements = quantise_attributes(d, f);
  const auto order = identity_order(d.vertex_count());
  const auto stream = direct_vertex_stream(elements, order);
  return VertexLoader(sent_inputs(d, AttributeInput::Direct), f, "test")
      .load(stream, d.vertex_count(), {});
}

TEST(GxVertexStorage, QuantisedValuesComeBackWithinHalfAStep) {
  const VertexAttributeData d = seeded_mesh(500, 5.0f, 46);
  VertexAttributeFormat f;
  const auto out = round_trip(d, "vtx=s16/auto,nrm=s8,clr=rgba8,uv=s16/auto", &f);
  ASSERT_EQ(out.size(), d.vertex_count());
  const double pos_step = std::ldexp(1.0, -f.position.frac);
  const double t_step = std::ldexp(1.0, -f.texcoord[0].frac);
  const double uv_step = std::ldexp(1.0, -f.texcoord[1].frac);
  for (size_t v = 0; v < out.size(); ++v) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(std::abs(double(out[v].position[c]) - d.position[v][c]), pos_step / 2) << v;
      EXPECT_LE(std::abs(double(out[v].normal[0][c]) - d.normal[v][c]), 1.0 / 128) << v;
    }
    EXPECT_LE(std::abs(double(out[v].texcoord[0].x) - d.texcoord[0][v].x), t_step / 2);
    EXPECT_EQ(out[v].texcoord[0].y, 0.0f);
    for (int c = 0; c < 2; ++c)
      EXPECT_LE(std::abs(double(out[v].texcoord[1][c]) - d.texcoord[1][v][c]), uv_step / 2);
    EXPECT_EQ(out[v].color[0], d.color[0][v]);  // RGBA8 is exact
  }
}

TEST(GxVertexStorage, ColoursComeBackAsTheNearestWidenedCode) {
  // Every 8-bit value through each narrow encoding: the loader's value is the nearest of the
  // widened codes, written here from their closed forms (5 bits floor(33x/4), 6 bits
  // floor(65x/16), 4 bits 17x).
  auto nearest = [](int value, int codes, const std::function<int(int)>& widen) {
    int best = widen(0);
    for (int x = 0; x < codes; ++x) {
      if (std::abs(widen(x) - value) < std::abs(best - value)) best = widen(x);
    }
    return best;
  };
  auto w5 = [](int x) { return 33 * x / 4; };
  auto w6 = [](int x) { return 65 * x / 16; };
  auto w4 = [](int x) { return 17 * x; };
  for (int value = 0; value < 256; ++value) {
    const u8 v = static_cast<u8>(value), inv = static_cast<u8>(255 - value);
    const Color8 c{v, inv, v, inv};
    std::vector<u8> b;
    append_color(b, c, ColorType::Rgb565);
    EXPECT_EQ(decode_vertex_color(ColorType::Rgb565, b),
              (Color8{static_cast<u8>(nearest(v, 32, w5)), static_cast<u8>(nearest(inv, 64, w6)),
                      static_cast<u8>(nearest(v, 32, w5)), 255}))
        << value;
    b.clear();
    append_color(b, c, ColorType::Rgba4);
    const u8 n4 = static_cast<u8>(nearest(v, 16, w4)), m4 = static_cast<u8>(nearest(inv, 16, w4));
    EXPECT_EQ(decode_vertex_color(ColorType::Rgba4, b), (Color8{n4, m4, n4, m4})) << value;
    b.clear();
    append_color(b, c, ColorType::Rgba6);
    const u8 n6 = static_cast<u8>(nearest(v, 64, w6)), m6 = static_cast<u8>(nearest(inv, 64, w6));
    EXPECT_EQ(decode_vertex_color(ColorType::Rgba6, b), (Color8{n6, m6, n6, m6})) << value;
    b.clear();
    append_color(b, c, ColorType::Rgbx8);
    EXPECT_EQ(decode_vertex_color(ColorType::Rgbx8, b), (Color8{v, inv, v, 255}));
  }
}

TEST(GxVertexStorage, RoundingIsToNearestHalvesAwayFromZeroAndClampsHalfAStepPast) {
  EXPECT_EQ(quantise_component(0.5, ComponentType::S8, 0), 1);
  EXPECT_EQ(quantise_component(-0.5, ComponentType::S8, 0), -1);
  EXPECT_EQ(quantise_component(2.5 / 256, ComponentType::S16, 8), 3);
  EXPECT_EQ(quantise_component(1.5, ComponentType::S16, 8), 0x180);
  EXPECT_EQ(quantise_component(127.5, ComponentType::S8, 0), 127);  // clamped
  EXPECT_EQ(quantise_component(-128.5, ComponentType::S8, 0), -128);
  EXPECT_EQ(quantise_component(127.51, ComponentType::S8, 0), std::nullopt);
  EXPECT_EQ(quantise_component(-0.51, ComponentType::U16, 0), std::nullopt);
  EXPECT_EQ(quantise_component(NAN, ComponentType::U16, 0), std::nullopt);
}

TEST(GxVertexStorage, AutoPicksTheWidestFractionTheBoundsAllow) {
  // [-5, 5] as s16: 5 * 2^12 = 20480 fits, 5 * 2^13 = 40960 does not.
  EXPECT_EQ(widest_fraction(-5, 5, ComponentType::S16), 12);
  // [0, 1] as u16: 2^16 = 65536 is past 65535.5; 2^15 fits. Just under 1 takes 16.
  EXPECT_EQ(widest_fraction(0, 1, ComponentType::U16), 15);
  EXPECT_EQ(widest_fraction(0, 0.99999, ComponentType::U16), 16);
  // A unit interval as s8: 64 at 6 bits, 128 (past 127.5) at 7.
  EXPECT_EQ(widest_fraction(-1, 1, ComponentType::S8), 6);
  // A negative value never fits an unsigned type (beyond half a step).
  EXPECT_EQ(widest_fraction(-1, 1, ComponentType::U8), std::nullopt);
  // Tiny bounds take all 31 bits.
  EXPECT_EQ(widest_fraction(-1e-6, 1e-6, ComponentType::S16), 31);
  // Through the key, from a mesh whose positions reach 100: 100 * 2^8 = 25600, 2^9 is past.
  VertexAttributeData d = seeded_mesh(10, 1.0f, 1);
  d.position[3] = {100.0f, -0.5f, 0.0f};
  const VertexAttributeFormat f =
      storage_format(parse_vertex_storage("vtx=s16", "test"), d, "test");
  EXPECT_EQ(f.position.type, ComponentType::S16);
  EXPECT_EQ(f.position.frac, 8);
  // TEX0's t is negative somewhere, so u16 cannot hold it at any fraction: refused.
  EXPECT_THROW(storage_format(parse_vertex_storage("uv=u16", "test"), d, "test"), InputError);
}

void expect_storage_error(const std::function<void()>& f, const std::string& key,
                          const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--variant gx:vtx");
    EXPECT_EQ(e.where(), key);
    EXPECT_NE(e.what_only().find(part), std::string::npos) << e.what_only();
  }
}

TEST(GxVertexStorage, OverflowIsRefusedNamingTheKeyAndTheFractionThatHolds) {
  VertexAttributeData d = seeded_mesh(4, 1.0f, 2);
  d.position[1] = {40.25f, 0.0f, 0.0f};
  const std::string origin = "--variant gx:vtx";
  // s16/10 holds -32 .. 31.999; 40.25 needs 9 bits at most (40.25 * 512 = 20608).
  expect_storage_error(
      [&] { storage_format(parse_vertex_storage("vtx=s16/10", origin), d, origin); }, "vtx",
      "s16/10 holds -32 .. 31.999; the mesh's positions reach 40.25 (s16/9 holds them)");
  d.position[1] = {40000.0f, 0.0f, 0.0f};
  expect_storage_error([&] { storage_format(parse_vertex_storage("vtx=s16", origin), d, origin); },
                       "vtx", "at 0 fractional bits; the mesh's positions reach 40000");
  VertexAttributeData bent = seeded_mesh(4, 1.0f, 3);
  bent.normal[0] = {2.5f, 0.0f, 0.0f};  // past s8's -2 .. 1.984
  expect_storage_error(
      [&] { storage_format(parse_vertex_storage("nrm=s8", origin), bent, origin); }, "nrm",
      "the mesh's normals reach 2.5");
}

TEST(GxVertexStorage, TheKeyParsesBackAndBadKeysNameTheKey) {
  const VertexStorage s = parse_vertex_storage("vtx=s16/8,nrm=s8,clr=rgb565,uv=u16/15", "k");
  EXPECT_EQ(s.position, (CoordinateStorage{ComponentType::S16, 8, false}));
  EXPECT_EQ(s.normal, ComponentType::S8);
  EXPECT_EQ(s.color, ColorType::Rgb565);
  EXPECT_EQ(s.texcoord, (CoordinateStorage{ComponentType::U16, 15, false}));
  EXPECT_EQ(vertex_storage_key(s), "vtx=s16/8,nrm=s8,clr=rgb565,uv=u16/15");
  EXPECT_EQ(parse_vertex_storage(vertex_storage_key(s), "k"), s);
  // Keys left out keep the F32 stream; a type alone is auto.
  const VertexStorage partial = parse_vertex_storage("clr=rgba4,vtx=s8", "k");
  EXPECT_EQ(vertex_storage_key(partial), "vtx=s8/auto,nrm=f32,clr=rgba4,uv=f32");
  EXPECT_TRUE(parse_vertex_storage("vtx=f32", "k").is_default());
  const std::string origin = "--variant gx:vtx";
  expect_storage_error([&] { parse_vertex_storage("pos=s16", origin); }, "pos",
                       "not a vertex storage key (vtx, nrm, clr, uv)");
  expect_storage_error([&] { parse_vertex_storage("vtx=s16,nrm=u8", origin); }, "nrm",
                       "'u8' is not a normal type (f32, s16, s8)");
  expect_storage_error([&] { parse_vertex_storage("clr=rgb555", origin); }, "clr",
                       "'rgb555' is not a colour type");
  expect_storage_error([&] { parse_vertex_storage("uv=s16/32", origin); }, "uv",
                       "'32' is not a number of fractional bits");
  expect_storage_error([&] { parse_vertex_storage("vtx=f32/4", origin); }, "vtx",
                       "f32 takes no fractional bits");
  expect_storage_error([&] { parse_vertex_storage("vtx=s8,vtx=s16", origin); }, "vtx",
                       "given twice");
  expect_storage_error([&] { parse_vertex_storage("vtx", origin); }, "vtx", "needs a value");
  expect_storage_error([&] { parse_vertex_storage("uv=h16", origin); }, "uv",
                       "'h16' is not a component type");
}

TEST(GxVertexStorage, IndexedArraysHoldEachDistinctElementOnceAndReadBackTheSame) {
  VertexAttributeData d = seeded_mesh(300, 2.0f, 4);
  // 300 vertices, but only 3 colours and every position twice: positions index with 150
  // elements (GX_INDEX8), colours with 3.
  for (size_t v = 0; v < 300; ++v) {
    d.color[0][v] = Color8{static_cast<u8>(100 * (v % 3)), 0, 0, 255};
    if (v >= 150) d.position[v] = d.position[v - 150];
  }
  const VertexAttributeFormat f =
      storage_format(parse_vertex_storage("vtx=s16,nrm=s16,clr=rgb565,uv=s16", "t"), d, "t");
  const auto elements = quantise_attributes(d, f);
  const IndexedArrays arrays = index_attributes(elements, "t");
  EXPECT_EQ(arrays.bytes[kArrayPosition].size(), 150u * 6);
  EXPECT_EQ(arrays.input[kArrayPosition], AttributeInput::Index8);
  EXPECT_EQ(arrays.bytes[kArrayColor0].size(), 3u * 2);
  EXPECT_EQ(arrays.input[kArrayNormal], AttributeInput::Index16);  // 300 distinct normals
  const auto order = identity_order(300);
  const auto direct = VertexLoader(sent_inputs(d, AttributeInput::Direct), f, "t")
                          .load(direct_vertex_stream(elements, order), 300, {});
  const VertexLoader indexed_loader(indexed_inputs(arrays), f, "t");
  const auto indexed =
      indexed_loader.load(indexed_vertex_stream(arrays, order), 300, arrays.views());
  ASSERT_EQ(indexed.size(), direct.size());
  for (size_t v = 0; v < direct.size(); ++v) {
    EXPECT_EQ(indexed[v].position, direct[v].position);
    EXPECT_EQ(indexed[v].normal[0], direct[v].normal[0]);
    EXPECT_EQ(indexed[v].color[0], direct[v].color[0]);
    EXPECT_EQ(indexed[v].texcoord[1], direct[v].texcoord[1]);
  }
  // Indices: 1 (position) + 2 (normal) + 1 (colour) + 2 + 2 (t and UV, 300 distinct each).
  EXPECT_EQ(indexed_loader.vertex_size(), 8u);
}

// A pass's t (a one-component coordinate) is an array of one element per vertex, equal or not:
// the CPU rewrites it every frame, so each vertex's index into it (and a display list of those
// indices) must not depend on the frame's values. The UVs beside it keep their distinct elements.
TEST(GxVertexStorage, ATArrayKeepsOneElementPerVertexUnderTheSameIndices) {
  VertexAttributeData d = seeded_mesh(300, 2.0f, 9);
  for (size_t v = 0; v < 300; ++v) {
    d.texcoord[0][v].x = v % 2 ? 0.5f : -0.25f;  // two values
    d.texcoord[1][v] = glm::vec2(0.25f, 0.75f);  // one UV
  }
  const VertexAttributeFormat f =
      storage_format(parse_vertex_storage("vtx=s16,nrm=s16,clr=rgb565,uv=s16/8", "t"), d, "t");
  const IndexedArrays arrays = index_attributes(quantise_attributes(d, f), "t");
  const auto t = static_cast<size_t>(kArrayTexCoord0);
  EXPECT_EQ(arrays.bytes[t].size(), 300u * 2);  // 300 s16 elements, not 2
  EXPECT_EQ(arrays.input[t], AttributeInput::Index16);
  for (u32 v = 0; v < 300; ++v) EXPECT_EQ(arrays.element_of_vertex[t][v], v);
  // Element v is vertex v's t: 0.5 x 2^8 = 128 = 0x0080, -0.25 x 2^8 = -64 = 0xFFC0.
  EXPECT_EQ(arrays.bytes[t][2], 0x00);
  EXPECT_EQ(arrays.bytes[t][3], 0x80);
  EXPECT_EQ(arrays.bytes[t][0], 0xFF);
  EXPECT_EQ(arrays.bytes[t][1], 0xC0);
  EXPECT_EQ(arrays.bytes[t + 1].size(), 2u * 2);  // the one UV, s16 s and t
  EXPECT_EQ(arrays.input[t + 1], AttributeInput::Index8);
}

TEST(GxVertexStorage, MoreThan65535DistinctElementsAreRefused) {
  AttributeElements positions{kArrayPosition, 2, {}};
  for (u32 v = 0; v < 65536; ++v) {
    positions.bytes.push_back(static_cast<u8>(v >> 8));
    positions.bytes.push_back(static_cast<u8>(v));
  }
  EXPECT_THROW(index_attributes({positions}, "t"), InputError);
  positions.bytes.resize(2 * 65535);
  EXPECT_EQ(index_attributes({positions}, "t").input[kArrayPosition], AttributeInput::Index16);
  positions.bytes.resize(2 * 255);
  EXPECT_EQ(index_attributes({positions}, "t").input[kArrayPosition], AttributeInput::Index8);
}

}  // namespace
}  // namespace lt::gx
