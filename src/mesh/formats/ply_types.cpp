#include "mesh/formats/ply_types.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace lt::meshio {

std::optional<PlyType> ply_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return std::nullopt;
}

std::size_t ply_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 8;
}

bool ply_is_float(PlyType t) {
  return t == PlyType::Float32 || t == PlyType::Float64;
}

namespace {

template <typename T>
void store_as(double value, unsigned char* out) {
  T v;
  if constexpr (std::is_floating_point_v<T>) {
    v = static_cast<T>(value);
  } else {
    const double lo = static_cast<double>(std::numeric_limits<T>::min());
    const double hi = static_cast<double>(std::numeric_limits<T>::max());
    v = static_cast<T>(std::isfinite(value) ? std::clamp(std::round(value), lo, hi) : 0.0);
  }
  std::memcpy(out, &v, sizeof v);
}

}  // namespace

void ply_store(PlyType type, double value, unsigned char* out) {
  switch (type) {
    case PlyType::Int8:
      return store_as<std::int8_t>(value, out);
    case PlyType::UInt8:
      return store_as<std::uint8_t>(value, out);
    case PlyType::Int16:
      return store_as<std::int16_t>(value, out);
    case PlyType::UInt16:
      return store_as<std::uint16_t>(value, out);
    case PlyType::Int32:
      return store_as<std::int32_t>(value, out);
    case PlyType::UInt32:
      return store_as<std::uint32_t>(value, out);
    case PlyType::Float32:
      return store_as<float>(value, out);
    case PlyType::Float64:
      return store_as<double>(value, out);
  }
}

double ply_value_as(PlyType type, double value) {
  unsigned char bytes[8];
  ply_store(type, value, bytes);
  auto load = [&bytes](auto v) {
    std::memcpy(&v, bytes, sizeof v);
    return static_cast<double>(v);
  };
  switch (type) {
    case PlyType::Int8:
      return load(std::int8_t{});
    case PlyType::UInt8:
      return load(std::uint8_t{});
    case PlyType::Int16:
      return load(std::int16_t{});
    case PlyType::UInt16:
      return load(std::uint16_t{});
    case PlyType::Int32:
      return load(std::int32_t{});
    case PlyType::UInt32:
      return load(std::uint32_t{});
    case PlyType::Float32:
      return load(float{});
    case PlyType::Float64:
      return load(double{});
  }
  return value;
}

}  // namespace lt::meshio
