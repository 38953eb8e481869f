// What a GX_* name is (the group of libogc constants it belongs to, its value): the element type
// of the name table (gx_name_table.h).
#pragma once

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
  Anisotropy,
  TlutFormat,
  TlutName,
  PosMtx,
  CullMode,
  PixelFormat,
  ZFormat,
};

struct GxName {
  const char* name;
  long long value;
  NameGroup group;
};

}  // namespace lt::gx
