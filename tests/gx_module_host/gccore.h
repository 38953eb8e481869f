/* A host stand-in for libogc's gccore.h, for tests/gx_module_test.cpp: the types and calls a GX
   module (`ltrender export gx --format module`) uses, so the module compiles on the host. The
   GX_* values come from gx_constants.h, which the test writes from ltrender's table of libogc's
   names (program/gx_name_table.h); the calls do not touch hardware, they print themselves as
   the program text ltrender's interpreter reads (gx.md §1), to be run on the emulator. */
#ifndef LTRENDER_HOST_GCCORE_H
#define LTRENDER_HOST_GCCORE_H

#include <stdint.h>

typedef uint8_t u8;
typedef uint16_t u16;
typedef uint32_t u32;
typedef int32_t s32;
typedef float f32;
typedef f32 Mtx[3][4];
typedef struct {
  u8 r, g, b, a;
} GXColor;
typedef struct {
  int unused;
} GXLightObj;
typedef struct {
  int unused;
} GXTexObj;
/* libogc's open TPL file [OGC tpl.h]: the fields the module reads (ntextures). */
typedef struct {
  int type;
  int ntextures;
  void* texdesc;
  void* tpl_file;
} TPLFile;
#define ATTRIBUTE_ALIGN(v) __attribute__((aligned(v)))

#include "gx_constants.h"
/* Names the draw uses that no modelled call takes [OGC gx.h]. */
#define GX_TRIANGLES 0x90
#define GX_TRIANGLESTRIP 0x98
#define GX_PNMTX0 0

/* The recorder: each pass function's calls become `void name(void) { ... }` in the text. */
void ltr_host_begin(const char* function);
void ltr_host_end(void);
const char* ltr_host_program(void);
void ltr_host_reset(void);

void GX_ClearVtxDesc(void);
void GX_SetVtxDesc(u8 attr, u8 type);
void GX_SetVtxAttrFmt(u8 vtxfmt, u32 vtxattr, u32 comptype, u32 compsize, u32 frac);
void GX_InitLightPos(GXLightObj* o, f32 x, f32 y, f32 z);
void GX_InitLightColor(GXLightObj* o, GXColor c);
void GX_InitLightDir(GXLightObj* o, f32 x, f32 y, f32 z);
void GX_InitLightSpot(GXLightObj* o, f32 cut_off, u8 fn);
void GX_InitLightAttnK(GXLightObj* o, f32 k0, f32 k1, f32 k2);
void GX_InitLightAttn(GXLightObj* o, f32 a0, f32 a1, f32 a2, f32 k0, f32 k1, f32 k2);
void GX_LoadLightObj(const GXLightObj* o, u8 id);
void GX_SetNumChans(u8 n);
void GX_SetChanCtrl(s32 channel, u8 enable, u8 ambsrc, u8 matsrc, u8 litmask, u8 diff_fn,
                    u8 attn_fn);
void GX_SetChanAmbColor(s32 channel, GXColor c);
void GX_SetChanMatColor(s32 channel, GXColor c);
void GX_LoadTexMtxImm(Mtx m, u32 id, u8 type);
void GX_SetNumTexGens(u32 n);
void GX_SetTexCoordGen(u16 coord, u32 type, u32 src, u32 mtx);
void GX_InitTexObj(GXTexObj* o, void* image, u16 w, u16 h, u8 fmt, u8 wrap_s, u8 wrap_t, u8 mipmap);
void GX_InitTexObjLOD(GXTexObj* o, u8 minfilt, u8 magfilt, f32 minlod, f32 maxlod, f32 lodbias,
                      u8 biasclamp, u8 edgelod, u8 maxaniso);
void GX_LoadTexObj(GXTexObj* o, u8 map);
void GX_SetNumTevStages(u8 n);
void GX_SetTevColor(u8 reg, GXColor c);
void GX_SetTevOrder(u8 stage, u8 coord, u32 map, u8 color);
void GX_SetTevColorIn(u8 stage, u8 a, u8 b, u8 c, u8 d);
void GX_SetTevAlphaIn(u8 stage, u8 a, u8 b, u8 c, u8 d);
void GX_SetTevColorOp(u8 stage, u8 op, u8 bias, u8 scale, u8 clamp, u8 reg);
void GX_SetTevAlphaOp(u8 stage, u8 op, u8 bias, u8 scale, u8 clamp, u8 reg);
void GX_SetTevKAlphaSel(u8 stage, u8 sel);
void GX_SetBlendMode(u8 type, u8 src, u8 dst, u8 op);
void GX_SetZMode(u8 enable, u8 func, u8 update);
void GX_SetAlphaCompare(u8 comp0, u8 ref0, u8 op, u8 comp1, u8 ref1);
void GX_SetCullMode(u8 mode);
/* The draw: matrices and immediate vertices, which a program file leaves to the scene. */
void GX_LoadPosMtxImm(Mtx m, u32 id);
void GX_LoadNrmMtxImm(Mtx m, u32 id);
void GX_SetCurrentMtx(u32 id);
void GX_Begin(u8 primitive, u8 vtxfmt, u16 count);
void GX_Position3f32(f32 x, f32 y, f32 z);
void GX_Normal3f32(f32 x, f32 y, f32 z);
void GX_Color4u8(u8 r, u8 g, u8 b, u8 a);
void GX_TexCoord1f32(f32 s);
void GX_TexCoord2f32(f32 s, f32 t);
void GX_End(void);
void DCFlushRange(void* start, u32 length);
/* A stored module's draw (ltrender_gx_stored.c): recorded, between ltr_host_draws_begin and
   ltr_host_draws, as segments the test compares with ltrender's FIFO log (gx_host.c). */
void ltr_host_draws_begin(void);
const u8* ltr_host_draws(u32* length);
void GX_SetArray(u32 attr, void* ptr, u8 stride);
void GX_BeginDispList(void* list, u32 size);
u32 GX_EndDispList(void);
void GX_CallDispList(void* list, u32 nbytes);
void GX_Position1x8(u8 i);
void GX_Position1x16(u16 i);
void GX_Normal1x8(u8 i);
void GX_Normal1x16(u16 i);
void GX_Color1x8(u8 i);
void GX_Color1x16(u16 i);
void GX_TexCoord1x8(u8 i);
void GX_TexCoord1x16(u16 i);
/* The module's textures come from its TPL: these read it as libogc's tpl.c does and call
   GX_InitTexObj, which records the texture. */
s32 TPL_OpenTPLFromMemory(TPLFile* tdf, void* memory, u32 len);
s32 TPL_GetTexture(TPLFile* tdf, s32 id, GXTexObj* texObj);
void GX_InvalidateTexAll(void);

#endif
