#include "paths/arbfp/arb_variant.h"

#include <cstdio>

#include "core/error.h"

namespace lt::arbfp {

std::string PowVariant::name() const {
  switch (method) {
    case PowMethod::Exact:
      return "pow=exact";
    case PowMethod::Lut:
      return "pow=lut:" + std::to_string(lut_size) + ":" + model::to_string(lut_format);
    case PowMethod::Sg:
      return "pow=sg";
    case PowMethod::SgSimplified:
      return "pow=sg-simplified";
    case PowMethod::SgFitted:
      return "pow=sg-fitted";
    case PowMethod::Mul:
      return per_vertex ? "pow=mul:vertex" : "pow=mul";
  }
  return "?";
}

PowVariant parse_variant(const std::string& name) {
  PowVariant v;
  const std::string prefix = "pow=";
  if (name.rfind(prefix, 0) != 0) {
    throw InputError("--variant", name, "arbfp variants start with pow=");
  }
  const std::string m = name.substr(prefix.size());
  if (m == "exact") return v;
  if (m == "sg") return {PowMethod::Sg};
  if (m == "sg-simplified") return {PowMethod::SgSimplified};
  if (m == "sg-fitted") return {PowMethod::SgFitted};
  if (m == "mul") return {PowMethod::Mul};
  if (m == "mul:vertex") {
    v.method = PowMethod::Mul;
    v.per_vertex = true;
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
  throw InputError("--variant", name,
                   "unknown arbfp variant (pow=exact, pow=lut:N:u8|f16|f32 with 2 <= N <= 4096, "
                   "pow=sg, pow=sg-simplified, pow=sg-fitted, pow=mul, pow=mul:vertex)");
}

}  // namespace lt::arbfp
