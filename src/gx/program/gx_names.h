// The GX_* names a program file may use, with libogc's values [OGC gc/ogc/gx.h] and the group
// each belongs to, so the interpreter can say "argument 2 of GX_SetTevColorIn: GX_CA_TEXA is an
// alpha input, expected a colour input (GX_CC_*)" instead of silently using the number; and the
// same table at compile time (GxConst), so the generator cannot name a constant gx.h lacks.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "core/error.h"
#include "gx/program/gx_name_group.h"
#include "gx/program/gx_name_table.h"

namespace lt::gx {

// nullptr for a name gx.h does not define (or that no modelled call takes).
const GxName* find_gx_name(std::string_view name);

// "a colour input (GX_CC_*)": how a message names what a parameter expects.
std::string describe(NameGroup group);

// The compile-time side of the table: a GX_* name of group G, looked up while ltrender is
// compiled. `GxConst<NameGroup::ColorArg>{"GX_CC_RASC"}` compiles; a misspelt name or one of
// another group ("GX_CA_ZERO" where a colour input is expected) is a compile error naming
// gx_name_not_in_libogc_gx_h or gx_name_of_another_group. It keeps the table entry, not just the
// value, so the program prints the spelling chosen (GX_ENABLE and GX_TRUE are both Bool 1).
void gx_name_not_in_libogc_gx_h();  // never defined: only reached in a failed constant lookup
void gx_name_of_another_group();

template <NameGroup G>
class GxConst {
 public:
  consteval GxConst(const char* name) : index_(lookup(name)) {}  // NOLINT: implicit on purpose

  // The name of group G with `value` (the first in table order), for numbered families chosen
  // at run time (GX_TEVSTAGE0 + n, GX_LIGHT0 << n); an absent value is our bug, not the user's.
  static GxConst with_value(long long value) {
    for (std::size_t i = 0; i < std::size(kGxNames); ++i) {
      if (kGxNames[i].group == G && kGxNames[i].value == value) return GxConst(i);
    }
    LT_CHECK(false, "no GX name of this group has the value " + std::to_string(value));
    return GxConst(std::size_t{0});
  }

  constexpr long long value() const { return kGxNames[index_].value; }
  constexpr const char* name() const { return kGxNames[index_].name; }
  constexpr bool operator==(const GxConst&) const = default;

 private:
  explicit constexpr GxConst(std::size_t index) : index_(index) {}

  static consteval std::size_t lookup(const char* name) {
    const std::string_view wanted(name);
    for (std::size_t i = 0; i < std::size(kGxNames); ++i) {
      if (wanted != kGxNames[i].name) continue;
      if (kGxNames[i].group != G) gx_name_of_another_group();
      return i;
    }
    gx_name_not_in_libogc_gx_h();
    return 0;
  }

  std::size_t index_;
};

}  // namespace lt::gx
