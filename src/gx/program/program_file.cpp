#include "gx/program/program_file.h"

namespace lt::gx {

Arg Arg::integer(const std::string& gx_name, long long v) {
  Arg a;
  a.kind = Kind::Integer;
  a.text = gx_name;
  a.value = v;
  a.number = static_cast<double>(v);
  return a;
}
Arg Arg::literal(long long v) {
  Arg a = integer(std::to_string(v), v);
  return a;
}
Arg Arg::f32(float v) {
  Arg a;
  a.kind = Kind::Number;
  a.number = v;
  return a;
}
Arg Arg::rgba(std::array<long long, 4> c, bool s10) {
  Arg a;
  a.kind = s10 ? Kind::ColorS10 : Kind::Color;
  a.color = c;
  return a;
}
Arg Arg::address_of(const std::string& n) {
  Arg a;
  a.kind = Kind::AddressOf;
  a.name = n;
  a.text = "&" + n;
  return a;
}
Arg Arg::identifier(const std::string& n) {
  Arg a;
  a.kind = Kind::Identifier;
  a.name = n;
  a.text = n;
  return a;
}

Arg Arg::string(const std::string& s) {
  Arg a;
  a.kind = Kind::String;
  a.text = s;
  return a;
}

Statement Statement::of(Call c, std::string comment) {
  Statement s;
  s.kind = Kind::Call;
  s.call = std::move(c);
  s.comment = std::move(comment);
  return s;
}

Statement Statement::of(Declaration d, std::string comment) {
  Statement s;
  s.kind = Kind::Declaration;
  s.declaration = std::move(d);
  s.comment = std::move(comment);
  return s;
}

}  // namespace lt::gx
