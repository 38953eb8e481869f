#include "gx/vertex_storage.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace lt::gx {

namespace {

// The storage key's names for component and colour types (libogc's without "GX_", lower case).
constexpr std::string_view kComponentNames[] = {"u8", "s8", "u16", "s16", "f32"};
constexpr std::string_view kColorNames[] = {"rgb565", "rgb8", "rgbx8", "rgba4", "rgba6", "rgba8"};

std::string join_names(std::span<const std::string_view> names) {
  std::string s;
  for (std::string_view n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

std::optional<ComponentType> component_named(std::string_view name) {
  for (size_t i = 0; i < std::size(kComponentNames); ++i) {
    if (kComponentNames[i] == name) return static_cast<ComponentType>(i);
  }
  return std::nullopt;
}

CoordinateStorage parse_coordinate(std::string_view key, std::string_view value,
                                   const std::string& origin) {
  const size_t slash = value.find('/');
  const std::string_view type_name = value.substr(0, slash);
  const std::optional<ComponentType> type = component_named(type_name);
  if (!type) {
    throw InputError(origin, std::string(key),
                     "'" + std::string(type_name) + "' is not a component type (" +
                         join_names(kComponentNames) + ")");
  }
  CoordinateStorage s{*type, 0, *type != ComponentType::F32};
  if (slash == std::string_view::npos) return s;
  const std::string_view frac = value.substr(slash + 1);
  if (*type == ComponentType::F32) {
    throw InputError(origin, std::string(key),
                     "f32 takes no fractional bits ('" + std::string(value) + "')");
  }
  if (frac == "auto") return s;
  int bits = -1;
  const auto [end, error] = std::from_chars(frac.data(), frac.data() + frac.size(), bits);
  if (error != std::errc() || end != frac.data() + frac.size() || bits < 0 || bits > kMaxFracBits) {
    throw InputError(
        origin, std::string(key),
        "'" + std::string(frac) + "' is not a number of fractional bits (0-31, or auto)");
  }
  s.frac = bits;
  s.auto_frac = false;
  return s;
}

std::string coordinate_key(const CoordinateStorage& c) {
  const std::string type(kComponentNames[static_cast<size_t>(c.type)]);
  if (c.type == ComponentType::F32) return type;
  return type + "/" + (c.auto_frac ? std::string("auto") : std::to_string(c.frac));
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The fraction coordinate attribute `key` is stored with, for values in `bounds`.
int resolved_fraction(const CoordinateStorage& c, const ValueBounds& bounds, std::string_view key,
                      const std::string& what, const std::string& origin) {
  if (c.type == ComponentType::F32 || bounds.empty) return c.auto_frac ? 0 : c.frac;
  const std::optional<int> widest = widest_fraction(bounds.lo, bounds.hi, c.type);
  const std::string type(kComponentNames[static_cast<size_t>(c.type)]);
  const IntegerRange range = integer_range(c.type);
  const double far = std::abs(bounds.lo) > std::abs(bounds.hi) ? bounds.lo : bounds.hi;
  if (!widest) {
    throw InputError(origin, std::string(key),
                     type + " holds " + std::to_string(range.lo) + " .. " +
                         std::to_string(range.hi) + " at 0 fractional bits; the mesh's " + what +
                         " reach " + number(far));
  }
  if (c.auto_frac) return *widest;
  if (c.frac > *widest) {
    throw InputError(origin, std::string(key),
                     type + "/" + std::to_string(c.frac) + " holds " +
                         number(std::ldexp(static_cast<double>(range.lo), -c.frac)) + " .. " +
                         number(std::ldexp(static_cast<double>(range.hi), -c.frac)) +
                         "; the mesh's " + what + " reach " + number(far) + " (" + type + "/" +
                         std::to_string(*widest) + " holds them)");
  }
  return c.frac;
}

}  // namespace

void set_vertex_storage(VertexStorage& s, std::string_view name, std::string_view value,
                        const std::string& origin) {
  if (name == "vtx") {
    s.position = parse_coordinate(name, value, origin);
  } else if (name == "uv") {
    s.texcoord = parse_coordinate(name, value, origin);
  } else if (name == "nrm") {
    const size_t slash = value.find('/');
    const std::string_view type_name = value.substr(0, slash);
    const std::optional<ComponentType> t = component_named(type_name);
    if (!t || (*t != ComponentType::F32 && *t != ComponentType::S16 && *t != ComponentType::S8)) {
      throw InputError(origin, "nrm",
                       "'" + std::string(type_name) + "' is not a normal type (f32, s16, s8)");
    }
    s.normal = *t;
    s.normal_vectors = NormalVectors::Normal;
    if (slash != std::string_view::npos) {
      const std::string_view vectors = value.substr(slash + 1);
      if (vectors != "nbt" && vectors != "nbt3")
        throw InputError(origin, "nrm",
                         "'" + std::string(value) +
                             "': a normal type takes /nbt or /nbt3 (normal, binormal, tangent)");
      s.normal_vectors = vectors == "nbt" ? NormalVectors::Nbt : NormalVectors::Nbt3;
    }
  } else if (name == "clr") {
    size_t c = std::size(kColorNames);
    for (size_t i = 0; i < std::size(kColorNames); ++i) {
      if (kColorNames[i] == value) c = i;
    }
    if (c == std::size(kColorNames)) {
      throw InputError(
          origin, "clr",
          "'" + std::string(value) + "' is not a colour type (" + join_names(kColorNames) + ")");
    }
    s.color = static_cast<ColorType>(c);
  } else {
    throw InputError(origin, std::string(name),
                     "not a vertex storage key (" + join_names(kVertexStorageKeys) + ")");
  }
}

VertexStorage parse_vertex_storage(std::string_view key, const std::string& origin) {
  VertexStorage s;
  std::array<bool, std::size(kVertexStorageKeys)> seen{};
  size_t at = 0;
  while (at <= key.size()) {
    const size_t comma = std::min(key.find(',', at), key.size());
    const std::string_view item = key.substr(at, comma - at);
    at = comma + 1;
    const size_t eq = item.find('=');
    const std::string_view name = item.substr(0, eq);
    size_t which = std::size(kVertexStorageKeys);
    for (size_t k = 0; k < std::size(kVertexStorageKeys); ++k) {
      if (kVertexStorageKeys[k] == name) which = k;
    }
    if (which == std::size(kVertexStorageKeys)) {
      throw InputError(origin, std::string(name),
                       "not a vertex storage key (" + join_names(kVertexStorageKeys) + ")");
    }
    if (eq == std::string_view::npos || eq + 1 == item.size()) {
      throw InputError(origin, std::string(name), "needs a value (" + std::string(name) + "=...)");
    }
    if (seen[which]) throw InputError(origin, std::string(name), "given twice");
    seen[which] = true;
    set_vertex_storage(s, name, item.substr(eq + 1), origin);
    if (comma == key.size()) break;
  }
  return s;
}

std::string vertex_storage_value(const VertexStorage& s, std::string_view name) {
  if (name == "vtx") return coordinate_key(s.position);
  if (name == "uv") return coordinate_key(s.texcoord);
  if (name == "nrm") {
    const std::string type(kComponentNames[static_cast<size_t>(s.normal)]);
    if (s.normal_vectors == NormalVectors::Normal) return type;
    return type + (s.normal_vectors == NormalVectors::Nbt ? "/nbt" : "/nbt3");
  }
  LT_CHECK(name == "clr", "not a vertex storage key");
  return std::string(kColorNames[static_cast<size_t>(s.color)]);
}

std::string vertex_storage_key(const VertexStorage& s) {
  std::string key;
  for (std::string_view name : kVertexStorageKeys) {
    if (!key.empty()) key += ',';
    key.append(name).append("=").append(vertex_storage_value(s, name));
  }
  return key;
}

VertexAttributeFormat storage_format(const VertexStorage& s, const VertexAttributeData& data,
                                     const std::string& origin) {
  const AttributeBounds bounds = attribute_bounds(data);
  VertexAttributeFormat f;
  f.position = {3, s.position.type,
                resolved_fraction(s.position, bounds.position, "vtx", "positions", origin)};
  f.normal.type = s.normal;
  f.normal.nbt = s.normal_vectors != NormalVectors::Normal;
  f.normal.index3 = s.normal_vectors == NormalVectors::Nbt3;
  if (s.normal != ComponentType::F32 && !bounds.normal.empty) {
    const int e = normal_exponent(s.normal);
    if (!quantise_component(bounds.normal.lo, s.normal, e) ||
        !quantise_component(bounds.normal.hi, s.normal, e)) {
      const IntegerRange r = integer_range(s.normal);
      throw InputError(
          origin, "nrm",
          std::string(kComponentNames[static_cast<size_t>(s.normal)]) + " holds " +
              number(std::ldexp(static_cast<double>(r.lo), -e)) + " .. " +
              number(std::ldexp(static_cast<double>(r.hi), -e)) + "; the mesh's normals reach " +
              number(std::abs(bounds.normal.lo) > std::abs(bounds.normal.hi) ? bounds.normal.lo
                                                                             : bounds.normal.hi));
    }
  }
  for (ColorFormat& c : f.color) c = {true, s.color};
  for (int t = 0; t < kVertexTexCoords; ++t) {
    const auto i = static_cast<size_t>(t);
    f.texcoord[i] = {data.texcoord_components[i], s.texcoord.type,
                     resolved_fraction(s.texcoord, bounds.texcoord[i], "uv",
                                       "texture coordinates (t and UVs)", origin)};
  }
  return f;
}

}  // namespace lt::gx
