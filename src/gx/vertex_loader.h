// The command processor's vertex loader: turns the bytes of a vertex stream (each attribute sent
// directly or as an index into its array) into the floats and 8-bit colours the transform unit
// works on, exactly as Dolphin 5.0-17995's loaders do on x86-64 (VertexLoaderX64, the one
// Debian's build runs; the portable VertexLoader agrees wherever ByteDequant is set, as libogc
// always sets it) [DHW VertexLoaderX64.cpp ReadVertex, ReadColor, GenerateVertexLoader]
// [DHW VertexLoader.cpp, VertexLoader_Position.cpp, VertexLoader_Normal.cpp,
// VertexLoader_Color.cpp, VertexLoader_TextCoord.cpp], then handed to the software renderer's
// vertex as SWVertexLoader fills it [DSW SWVertexLoader.cpp ParseVertex].
//
// Every number in the stream and in the arrays is big-endian, the Broadway's byte order.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

#include "gx/vertex_format.h"

namespace lt::gx {

// One array as GX_SetArray gives it: the bytes from its base to the end of the memory that holds
// it (an element past them is an error here, garbage on a console), and the stride between
// elements (at most kMaxArrayStride; it may be smaller than an element, as the CP allows).
struct VertexArray {
  std::span<const u8> bytes;
  unsigned stride = 0;
};
using VertexArrays = std::array<VertexArray, kVertexArrays>;

// One vertex as the transform unit receives it. What the descriptor does not send stays zero
// here; the software renderer then takes a missing z or t as 0 [DSW SWVertexLoader.cpp
// ReadVertexAttribute, "dst[i_dst] = i == 3"].
struct LoadedVertex {
  u8 position_matrix = 0;                      // GX_VA_PTNMTXIDX, its low 6 bits
  std::array<u8, kVertexTexCoords> texture_matrix{};  // GX_VA_TEXnMTXIDX, low 6 bits
  glm::vec3 position{0.0f};
  // The normal, then an NBT's second and third vectors in stream order (libogc's binormal and
  // tangent; Dolphin's normals[1] and [2]).
  std::array<glm::vec3, 3> normal{};
  std::array<Color8, kVertexColors> color{};
  std::array<glm::vec2, kVertexTexCoords> texcoord{};
};

class VertexLoader {
 public:
  // Checks the format (check_vertex_format); `origin` names the input in every error (a file, a
  // variant key).
  VertexLoader(const VertexInputs& inputs, const VertexAttributeFormat& format,
               std::string origin);

  // Bytes one vertex takes in the stream: one per matrix index, then each attribute's direct
  // bytes or its index (1 or 2; an NBT3 normal three indices) [DHW VertexLoaderBase.cpp
  // GetVertexSize]. The vertex stream's share of the FIFO per vertex.
  size_t vertex_size() const { return vertex_size_; }

  // Reads `count` vertices from the start of `stream`. A position index of all ones (0xFF for
  // GX_INDEX8, 0xFFFF for GX_INDEX16) drops its vertex, as Dolphin's loaders do [DHW
  // VertexLoader_Position.cpp Pos_ReadIndex "m_vertexSkip", VertexLoaderX64.cpp GetVertexAddr]:
  // the result then holds fewer than `count`. A stream shorter than count vertices, an index
  // past its array or an array stride over 255 throws InputError(origin, ...).
  std::vector<LoadedVertex> load(std::span<const u8> stream, size_t count,
                                 const VertexArrays& arrays) const;

  const VertexInputs& inputs() const { return inputs_; }
  const VertexAttributeFormat& format() const { return format_; }

 private:
  VertexInputs inputs_;
  VertexAttributeFormat format_;
  std::string origin_;
  size_t vertex_size_ = 0;
};

// The colour a vertex colour's bytes decode to: 5- and 6-bit fields widen by repeating their top
// bits (x << 3 | x >> 2, x << 2 | x >> 4), 4-bit ones by x * 17, and an encoding without alpha
// gives 255 [DHW VertexLoader_Color.cpp SetCol565, SetCol4444, SetCol6666, Read24].
// `bytes` holds color_bytes(type) bytes.
Color8 decode_vertex_color(ColorType type, std::span<const u8> bytes);

}  // namespace lt::gx
