// The converter's side of the vertex loader: what a port's tool stores for a mesh's floats and
// 8-bit colours in the console's vertex formats, so that the loader (vertex_loader.h) gives back
// the nearest value each format holds. No console source states how a converter rounds; this is
// ltrender's choice, documented in docs/porting-to-the-wii.md ("Vertex storage"):
// - an integer component with exponent e (a position's or texture coordinate's fractional bits,
//   a normal's fixed exponent) stores v * 2^e rounded to the nearest integer, halves away from
//   zero; a value at most half a step past the type's range clamps to its end, one further is
//   refused (the caller names its key), so every stored value is within half a step of its float;
// - a colour channel stores the code whose widened value (decode_vertex_color) is nearest to the
//   8-bit value, the lower code on a tie; an encoding without alpha drops it (the loader gives
//   255).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "gx/vertex_loader.h"

namespace lt::gx {

// The integers `type` holds: 0..255, -128..127, 0..65535, -32768..32767.
struct IntegerRange {
  long lo = 0, hi = 0;
};
IntegerRange integer_range(ComponentType type);

// The integer stored for `v` as integer `type` with exponent `exponent`; nullopt when v * 2^e is
// more than half a step outside the type's range (or not finite).
std::optional<long> quantise_component(double v, ComponentType type, int exponent);

// The largest fraction (0..31) at which both `lo` and `hi` are held by integer `type`; nullopt
// when not even 0 fractional bits hold them. For lo = -5, hi = 5 as s16: 12 (5 * 4096 = 20480;
// 5 * 8192 is past 32767).
std::optional<int> widest_fraction(double lo, double hi, ComponentType type);

// Appends `values` as `type` with exponent `exponent`, big-endian (F32: the float's bits).
// Every value must fit (quantise_component); a value that does not is our bug (LT_CHECK).
void append_components(std::vector<u8>& out, std::span<const float> values, ComponentType type,
                       int exponent);
// Appends colour `c` as `type` (color_bytes(type) bytes).
void append_color(std::vector<u8>& out, Color8 c, ColorType type);

// A mesh's vertex attributes before storage: one entry per vertex in each attribute it sends
// (an empty attribute is not sent). Texture coordinate n has texcoord_components[n] components
// (GX_TEX_S: only .x is stored).
struct VertexAttributeData {
  std::vector<glm::vec3> position;
  std::vector<glm::vec3> normal;
  // Each vertex's binormal and tangent, stored after its normal where the format sends an NBT
  // (NormalFormat::nbt) and ignored otherwise (normal_frame gives them).
  std::vector<glm::vec3> binormal, tangent;
  std::array<std::vector<Color8>, kVertexColors> color;
  std::array<std::vector<glm::vec2>, kVertexTexCoords> texcoord;
  std::array<int, kVertexTexCoords> texcoord_components{2, 2, 2, 2, 2, 2, 2, 2};
  size_t vertex_count() const { return position.size(); }
};

// The smallest and largest component value of each coordinate attribute (over all its
// components), what a fraction must hold.
struct ValueBounds {
  double lo = 0, hi = 0;
  bool empty = true;
  void add(double v);
};
struct AttributeBounds {
  ValueBounds position, normal;
  std::array<ValueBounds, kVertexTexCoords> texcoord;
};
AttributeBounds attribute_bounds(const VertexAttributeData& data);

// The attributes `data` sends, each sent as `input` (position always; GX_NONE where empty).
VertexInputs sent_inputs(const VertexAttributeData& data, AttributeInput input);

// An orthonormal binormal and tangent for unit normal `n`, a fixed function of n alone (Duff
// et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1) 2017): what ltrender sends as
// an NBT's second and third vectors. Nothing the translucency term draws reads them (the XF
// lights the normal alone; they feed GX_TG_BUMP texgens), so a mesh's UV tangents are not
// computed; a port with bump maps sends its own.
std::pair<glm::vec3, glm::vec3> normal_frame(const glm::vec3& n);
// Fills `data`'s binormals and tangents from its normals (normal_frame).
void add_normal_frames(VertexAttributeData& data);

// Each sent attribute's stored element per vertex, in vertex order: array number (kArray*),
// element size and the elements' bytes (vertex v's at v * element_bytes). `indices` is how many
// indices an indexed vertex sends for it: 3 for an NBT3 normal (one per vector, each the same
// element: vector k is read 3k components into the element it names [DHW
// VertexLoader_Normal.cpp Normal_ReadIndex_Offset]), else 1. `per_vertex`: the array keeps one
// element per vertex, equal or not (a GX_TEX_S coordinate: the per-vertex t the CPU rewrites every
// frame, so a vertex's index into it, and a display list of those indices, stays the same from
// frame to frame while the values change).
struct AttributeElements {
  int array = 0;
  size_t element_bytes = 0;
  std::vector<u8> bytes;
  int indices = 1;
  bool per_vertex = false;
};
// `format` must hold every value (storage_format checks it); the attributes in stream order.
std::vector<AttributeElements> quantise_attributes(const VertexAttributeData& data,
                                                   const VertexAttributeFormat& format);

// The direct stream of `vertices` (indices into the data, in draw order): each vertex's
// elements one after the other.
std::vector<u8> direct_vertex_stream(const std::vector<AttributeElements>& elements,
                                     std::span<const u32> vertices);

// The mesh as indexed arrays: per attribute its distinct elements (first use first; a
// `per_vertex` attribute every vertex's, in vertex order), tightly strided, and each vertex's
// element number. An attribute of at most 255 elements is indexed
// with GX_INDEX8, of at most 65,535 with GX_INDEX16 (an index of all ones drops a vertex,
// vertex_loader.h); more is refused with InputError(origin, attribute, ...).
struct IndexedArrays {
  std::array<std::vector<u8>, kVertexArrays> bytes;
  std::array<unsigned, kVertexArrays> stride{};
  std::array<AttributeInput, kVertexArrays> input{};
  std::array<std::vector<u32>, kVertexArrays> element_of_vertex;
  std::array<int, kVertexArrays> indices{};  // a vertex's indices into each (AttributeElements)
  std::vector<int> arrays;                   // the sent attributes' array numbers, in stream order
  VertexArrays views() const;
};
IndexedArrays index_attributes(const std::vector<AttributeElements>& elements,
                               const std::string& origin);
// The descriptor an indexed draw of these arrays sends.
VertexInputs indexed_inputs(const IndexedArrays& arrays);
// The index stream of `vertices`: each vertex's indices, one per attribute (three for an NBT3
// normal), big-endian.
std::vector<u8> indexed_vertex_stream(const IndexedArrays& arrays, std::span<const u32> vertices);

}  // namespace lt::gx
