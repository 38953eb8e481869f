// What the command processor (CP) is told about a vertex before it reads one: which attributes
// the stream carries and how (the vertex descriptor, VCD: GX_SetVtxDesc), how each attribute is
// encoded (one of eight vertex attribute formats, VAT: GX_SetVtxAttrFmt), and where indexed
// attributes find their data (GX_SetArray). The vertex loader (vertex_loader.h) reads a vertex
// stream through these; pack_* give the CP registers they are (the FIFO log encodes its F32
// stream with fifo/cp_registers.h, GxVertexLoader.PackedRegisters* holds the two equal, and a
// stored mesh's VAT with pack_vertex_format: paths/gx/frame_recording.cpp).
//
// Field layouts are Dolphin's [DHW CPMemory.h TVtxDesc, UVAT_group0..2], which libogc writes
// [OGC gx.c __SETVCDATTR L2295-2367, __SETVCDFMT L2533-2620, GX_SetArray L2283-2293]. Enum values
// are libogc's constants [OGC gx.h L82-117].
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "gx/gx_types.h"

namespace lt::gx {

// How an attribute arrives: GX_NONE, GX_DIRECT (its bytes in the stream), GX_INDEX8 /
// GX_INDEX16 (a big-endian index into its array) [OGC gx.h L82-85].
enum class AttributeInput : u8 { None = 0, Direct = 1, Index8 = 2, Index16 = 3 };

// Component types of positions, normals and texture coordinates: GX_U8, GX_S8, GX_U16, GX_S16,
// GX_F32 [OGC gx.h L93-97]. The VAT's 3-bit field can hold 5-7 too; Dolphin reads those as
// floats and names them invalid [DHW CPMemory.h ComponentFormat::InvalidFloat5..7]: refused.
enum class ComponentType : u8 { U8 = 0, S8 = 1, U16 = 2, S16 = 3, F32 = 4 };

// Vertex colour encodings: GX_RGB565, GX_RGB8, GX_RGBX8, GX_RGBA4, GX_RGBA6, GX_RGBA8
// [OGC gx.h L98-103]. 6 and 7 fit the field but Dolphin refuses them ("Invalid color format"
// [DHW VertexLoader_Color.cpp GetFunction]): refused.
enum class ColorType : u8 { Rgb565 = 0, Rgb8 = 1, Rgbx8 = 2, Rgba4 = 3, Rgba6 = 4, Rgba8 = 5 };

inline constexpr int kVertexColors = 2;     // GX_VA_CLR0, GX_VA_CLR1
inline constexpr int kVertexTexCoords = 8;  // GX_VA_TEX0..7
inline constexpr int kMaxFracBits = 31;     // the VAT's 5-bit shift fields

// The vertex descriptor (VCD): which attributes each vertex carries, in the order the stream
// holds them: the position-normal matrix index and the eight texture matrix indices (one byte
// each, GX_VA_PTNMTXIDX, GX_VA_TEXnMTXIDX), then position, normal, colour 0, colour 1, texture
// coordinates 0..7 [DHW VertexLoader.cpp CompileVertexTranslator].
struct VertexInputs {
  bool position_matrix_index = false;
  std::array<bool, kVertexTexCoords> texture_matrix_index{};
  AttributeInput position = AttributeInput::None;
  AttributeInput normal = AttributeInput::None;
  std::array<AttributeInput, kVertexColors> color{};
  std::array<AttributeInput, kVertexTexCoords> texcoord{};
  bool operator==(const VertexInputs&) const = default;
};

// A position (2 or 3 components: GX_POS_XY, GX_POS_XYZ) or texture coordinate (1 or 2:
// GX_TEX_S, GX_TEX_ST) with its fractional bits (0-31; ignored for GX_F32).
struct CoordinateFormat {
  int components = 3;
  ComponentType type = ComponentType::F32;
  int frac = 0;
  bool operator==(const CoordinateFormat&) const = default;
};

// Normals have no fraction field: the exponent is fixed by the type (normal_exponent). `nbt`
// sends normal, binormal and tangent (libogc's GX_VA_NBT with GX_NRM_NBT or GX_NRM_NBT3, VAT A
// bit 9); `index3` (GX_NRM_NBT3, bit 31) gives an indexed NBT one index per vector.
struct NormalFormat {
  ComponentType type = ComponentType::F32;
  bool nbt = false;
  bool index3 = false;
  bool operator==(const NormalFormat&) const = default;
};

// GX_CLR_RGB / GX_CLR_RGBA and the encoding. The count changes nothing the loader reads: the
// encoding alone fixes the bytes and whether alpha is sent (Dolphin reads ColorElements nowhere
// in its loaders [DHW VertexLoader_Color.cpp, VertexLoaderX64.cpp ReadColor]).
struct ColorFormat {
  bool alpha = true;
  ColorType type = ColorType::Rgba8;
  bool operator==(const ColorFormat&) const = default;
};

// One of the eight vertex attribute formats (GX_VTXFMT0..7). The defaults are the ltrender F32
// stream's (gx.md §1); `byte_dequant` is VAT A bit 30, which libogc sets in every format at
// GX_Init and never clears [OGC gx.c __GX_InitRevBits L244, __SETVCDFMT L2543].
struct VertexAttributeFormat {
  CoordinateFormat position{3, ComponentType::F32, 0};
  NormalFormat normal;
  std::array<ColorFormat, kVertexColors> color{};
  std::array<CoordinateFormat, kVertexTexCoords> texcoord;
  bool byte_dequant = true;
  VertexAttributeFormat();
  bool operator==(const VertexAttributeFormat&) const = default;
};

// The CP's arrays (GX_SetArray; CP 0xA0 + n base, 0xB0 + n stride) in their order: position,
// normal (GX_VA_NBT shares it), colour 0, colour 1, texture coordinates 0..7 [OGC gx.c
// GX_SetArray L2283-2293] [DHW CPMemory.h CPArray].
inline constexpr int kArrayPosition = 0, kArrayNormal = 1, kArrayColor0 = 2, kArrayTexCoord0 = 4;
inline constexpr int kVertexArrays = 12;
// GX_SetArray takes the stride as a u8 [OGC gx.h L1929]; the CP keeps 8 bits of it.
inline constexpr unsigned kMaxArrayStride = 255;

// Bytes of one component of `type` (1, 2 or 4).
int component_bytes(ComponentType type);
// Bytes of one colour of `type` sent directly: 2, 3, 4, 2, 3, 4 [DHW VertexLoader_Color.h
// GetSize] [DHW VertexLoaderX64.cpp ReadColor load_bytes].
int color_bytes(ColorType type);
// The fixed exponent of a normal's type: the value is v / 2^exponent. s8: 6, s16: 14 (one sign
// bit and one integer bit), u8: 7, u16: 15, f32: 0 [DHW VertexLoader_Normal.cpp FracAdjust,
// whose own comment asks "TODO: is this right?"; VertexLoaderX64.cpp SCALE_MAP {7, 6, 15, 14}].
int normal_exponent(ComponentType type);

// Names for messages: "GX_VA_POS", "GX_VA_NRM", "GX_VA_CLR0", "GX_VA_TEX3", by array number.
std::string attribute_name(int array);
std::string component_type_name(ComponentType type);  // "GX_S16"
std::string color_type_name(ColorType type);          // "GX_RGB565"

// Checks that every attribute the descriptor sends has a format the hardware and Dolphin define:
// positions 2 or 3 components, texture coordinates 1 or 2, types U8..F32, colours
// RGB565..RGBA8, fractions 0-31. Throws InputError(origin, attribute name, what) otherwise.
void check_vertex_format(const VertexInputs& inputs, const VertexAttributeFormat& format,
                         const std::string& origin);

// The CP registers these pack into: VCD low (0x50) and high (0x60), VAT A/B/C (0x70/0x80/0x90
// + format number) [DHW CPMemory.h]. Unpacking takes what the fields hold (a type of 5-7 is
// kept; check_vertex_format refuses it); packing a VAT B sets bit 31 (VCacheEnhance, "must
// always be on" [DHW CPMemory.h UVAT_group1]) as libogc does [OGC gx.c L245].
std::array<u32, 2> pack_vertex_inputs(const VertexInputs& inputs);
VertexInputs unpack_vertex_inputs(u32 vcd_low, u32 vcd_high);
std::array<u32, 3> pack_vertex_format(const VertexAttributeFormat& format);
VertexAttributeFormat unpack_vertex_format(u32 vat_a, u32 vat_b, u32 vat_c);

}  // namespace lt::gx
