// The GX_* names a program file may use, with libogc's values [OGC gc/ogc/gx.h] and the group
// each belongs to, so the interpreter can say "argument 2 of GX_SetTevColorIn: GX_CA_TEXA is an
// alpha input, expected a colour input (GX_CC_*)" instead of silently using the number.
#pragma once

#include <string>
#include <string_view>

namespace lt::gx {

enum class NameGroup {
  Number,
  Bool,
  Channel,
  ColorSource,
  Light,
  DiffuseFn,
  AttnFn,
  SpotFn,
  DistFn,
  TexCoord,
  TexMap,
  TevStage,
  ColorArg,
  AlphaArg,
  TevOp,
  TevBias,
  TevScale,
  TevReg,
  KColor,
  KColorSel,
  KAlphaSel,
  TevMode,
  Swap,
  ColorComponent,
  TexGenType,
  TexGenSource,
  TexMtx,
  MtxType,
  Compare,
  AlphaOp,
  BlendMode,
  BlendFactor,
  LogicOp,
  VtxAttr,
  VtxAttrType,
  VtxFmt,
  CompCount,
  CompType,
  TexFormat,
  TexWrap,
  TexFilter,
  PosMtx,
  CullMode,
};

struct GxName {
  const char* name;
  long long value;
  NameGroup group;
};

// nullptr for a name gx.h does not define (or that no modelled call takes).
const GxName* find_gx_name(std::string_view name);

// "a colour input (GX_CC_*)": how a message names what a parameter expects.
std::string describe(NameGroup group);

// The name of `value` in `group` (the first in table order), for printing; empty if none.
std::string gx_name_of(NameGroup group, long long value);

}  // namespace lt::gx
