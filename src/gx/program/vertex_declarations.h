// The vertex format calls of a program file (GX_ClearVtxDesc, GX_SetVtxDesc, GX_SetVtxAttrFmt):
// what each attribute is sent as and how the scene's mesh is stored, recorded in the state's
// DeclaredStorage (gx_state.h) as a storage key's values, read by vertex_storage.h's one parser
// so a declaration and the variant's `:vtx= :nrm= :clr= :uv=` axes mean the same. Internal to
// program/ (calls_pixel.cpp's table).
#pragma once

#include "gx/program/machine.h"

namespace lt::gx::interp {

// GX_ClearVtxDesc(): no attribute sent [OGC gx.c GX_ClearVtxDesc].
void clear_vertex_inputs(Machine& m);
// GX_SetVtxDesc(attr, type): GX_NONE, GX_DIRECT, GX_INDEX8, GX_INDEX16; every attribute sent
// directly or every one indexed (the :draw= axis sends a vertex one way); GX_VA_NBT is the
// normal's field; GX_VA_CLR1 sends the scene's one vertex colour as GX_VA_CLR0 does.
void set_vertex_input(Machine& m);
// GX_SetVtxAttrFmt(fmt, attr, count, type, frac): positions GX_POS_XYZ, normals GX_NRM_XYZ,
// colours any of the six encodings, texture coordinates GX_TEX_S (the CPU's t) or GX_TEX_ST (the
// mesh's UV); positions and texture coordinates U8/S8/U16/S16 with frac 0-31 or F32; normals
// F32/S16/S8 (exponent fixed by the type). Each of GX_VTXFMT0..7 keeps its own declarations;
// the storage is the drawing format's: the one whose call declares GX_VA_POS (GX_VTXFMT0 where
// none does), a pass declaring the position in two formats refused (gx_state.h DeclaredStorage).
void set_vertex_attribute_format(Machine& m);
// GX_SetArray(attr, array, stride): the stride of the attribute's array (GX_VA_NBT: the
// normal's).
void set_vertex_array(Machine& m);

}  // namespace lt::gx::interp
