#include "paths/arbfp/arb_variant.h"

#include <cstdio>

#include "core/error.h"

namespace lt::arbfp {

namespace {

// The methods by name: one row each, read by name() and parse_variant() alike. The LUT's
// "lut:N:FORMAT" is a grammar of its own (any N and format the generator builds).
struct MethodName {
  const char* name;
  PowMethod method;
  bool per_vertex;
};
constexpr MethodName kMethods[] = {
    {"exact", PowMethod::Exact, false},
    {"sg", PowMethod::Sg, false},
    {"sg-simplified", PowMethod::SgSimplified, false},
    {"sg-fitted", PowMethod::SgFitted, false},
    {"mul", PowMethod::Mul, false},
    {"mul:vertex", PowMethod::Mul, true},
};

std::string valid_names() {
  std::string s;
  for (const MethodName& m : kMethods) s += std::string("pow=") + m.name + ", ";
  return s + "pow=lut:N:u8|f16|f32 with 2 <= N <= 4096";
}

const char kAllGuards[] = ":guards=all";

std::string method_name(const PowVariant& v) {
  if (v.method == PowMethod::Lut)
    return "pow=lut:" + std::to_string(v.lut_size) + ":" + model::to_string(v.lut_format);
  for (const MethodName& m : kMethods) {
    if (m.method == v.method && m.per_vertex == v.per_vertex) return std::string("pow=") + m.name;
  }
  return "?";
}

PowVariant parse_method(const std::string& name);

}  // namespace

std::string PowVariant::name() const {
  return method_name(*this) + (all_guards ? kAllGuards : "");
}

PowVariant parse_variant(const std::string& name) {
  const size_t n = sizeof kAllGuards - 1;
  if (name.size() > n && name.compare(name.size() - n, n, kAllGuards) == 0) {
    PowVariant v = parse_method(name.substr(0, name.size() - n));
    v.all_guards = true;
    return v;
  }
  return parse_method(name);
}

namespace {

PowVariant parse_method(const std::string& name) {
  PowVariant v;
  const std::string prefix = "pow=";
  if (name.rfind(prefix, 0) != 0) {
    throw InputError("--variant", name, "arbfp variants start with pow=");
  }
  const std::string m = name.substr(prefix.size());
  for (const MethodName& row : kMethods) {
    if (m != row.name) continue;
    v.method = row.method;
    v.per_vertex = row.per_vertex;
    return v;
  }
  // lut:N:FORMAT
  int size = 0;
  char format[8] = {};
  if (std::sscanf(m.c_str(), "lut:%d:%7s", &size, format) == 2 && size >= 2 && size <= 4096) {
    v.method = PowMethod::Lut;
    v.lut_size = size;
    const std::string f = format;
    if (f == "u8")
      v.lut_format = model::LutFormat::U8;
    else if (f == "f16")
      v.lut_format = model::LutFormat::F16;
    else if (f == "f32")
      v.lut_format = model::LutFormat::F32;
    else
      throw InputError("--variant", name, "LUT format must be u8, f16 or f32");
    if (v.name() == name) return v;
  }
  throw InputError(
      "--variant", name,
      "unknown arbfp variant (" + valid_names() + ", each with an optional " + kAllGuards + ")");
}

}  // namespace

}  // namespace lt::arbfp
