// PLY's scalar types, shared by the reader and the writer.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace lt::meshio {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// A type by its header name, old ("uchar") or sized ("uint8"); nullopt for anything else.
std::optional<PlyType> ply_type(std::string_view name);
std::size_t ply_size(PlyType t);
bool ply_is_float(PlyType t);

// `value` stored as `type` in native byte order into `out` (ply_size(type) bytes): integers
// rounded to nearest and clamped to the type's range.
void ply_store(PlyType type, double value, unsigned char* out);

// `value` as `type` holds it (what ply_store keeps): an ascii "0.3333333" of a float property is
// the float nearest to it.
double ply_value_as(PlyType type, double value);

}  // namespace lt::meshio
