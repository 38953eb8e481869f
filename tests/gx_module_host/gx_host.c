/* The recorder behind the host gccore.h (see there): every call appends its libogc text. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gccore.h"

static char* program;
static size_t length, capacity;
static char top[16 << 20];

static int recording_draws;
static void draw_segment(u8 kind, const u8* bytes, u32 n);

static void append(const char* format, ...) {
  char line[4096];
  va_list args;
  int n;
  if (recording_draws) return; /* a stored draw's pass functions: their text is the frame's */
  va_start(args, format);
  n = vsnprintf(line, sizeof line, format, args);
  va_end(args);
  if (length + (size_t)n + 1 > capacity) {
    capacity = (length + (size_t)n + 1) * 2;
    program = realloc(program, capacity);
  }
  memcpy(program + length, line, (size_t)n + 1);
  length += (size_t)n;
}

/* Objects and arrays by address: named o<N> and a<N> as first seen. */
static const void* objects[64];
static int object_count;
static const void* arrays[16];
static int array_count;

static int object_name(const void* p, const char* type) {
  int i;
  if (recording_draws) return 0; /* names only the text's objects */
  for (i = 0; i < object_count; ++i)
    if (objects[i] == p) return i;
  objects[object_count] = p;
  append("  %s o%d;\n", type, object_count);
  return object_count++;
}

/* %.9g reads back as the same float; the interpreter needs a '.' or an exponent before 'f'. */
static const char* flt(char* buf, f32 v) {
  snprintf(buf, 40, "%.9g", (double)v);
  if (!strpbrk(buf, ".en")) strcat(buf, ".0");
  strcat(buf, "f");
  return buf;
}

void ltr_host_reset(void) {
  length = 0;
  if (program) program[0] = 0;
  array_count = 0;
  top[0] = 0;
}
void ltr_host_begin(const char* function) {
  object_count = 0;
  append("void %s(void) {\n", function);
}
void ltr_host_end(void) {
  append("}\n");
}
const char* ltr_host_program(void) {
  static char* whole;
  free(whole);
  whole = malloc(strlen(top) + length + 1);
  strcpy(whole, top);
  memcpy(whole + strlen(top), program ? program : "", length + 1);
  return whole;
}

static void light3(const char* f, GXLightObj* o, f32 x, f32 y, f32 z) {
  char a[40], b[40], c[40];
  const int n = object_name(o, "GXLightObj");
  append("  %s(&o%d, %s, %s, %s);\n", f, n, flt(a, x), flt(b, y), flt(c, z));
}

void GX_ClearVtxDesc(void) {
  append("  GX_ClearVtxDesc();\n");
}
void GX_SetVtxDesc(u8 attr, u8 type) {
  const u8 bytes[2] = {attr, type};
  if (recording_draws) draw_segment('V', bytes, 2);
  append("  GX_SetVtxDesc(%d, %d);\n", attr, type);
}
void GX_SetVtxAttrFmt(u8 f, u32 attr, u32 type, u32 size, u32 frac) {
  const u8 bytes[4] = {(u8)attr, (u8)type, (u8)size, (u8)frac};
  if (recording_draws) draw_segment('F', bytes, 4);
  append("  GX_SetVtxAttrFmt(%d, %u, %u, %u, %u);\n", f, attr, type, size, frac);
}
void GX_InitLightPos(GXLightObj* o, f32 x, f32 y, f32 z) {
  light3("GX_InitLightPos", o, x, y, z);
}
void GX_InitLightDir(GXLightObj* o, f32 x, f32 y, f32 z) {
  light3("GX_InitLightDir", o, x, y, z);
}
void GX_InitLightAttnK(GXLightObj* o, f32 x, f32 y, f32 z) {
  light3("GX_InitLightAttnK", o, x, y, z);
}
void GX_InitLightAttn(GXLightObj* o, f32 a0, f32 a1, f32 a2, f32 k0, f32 k1, f32 k2) {
  char v[6][40];
  const int n = object_name(o, "GXLightObj");
  append("  GX_InitLightAttn(&o%d, %s, %s, %s, %s, %s, %s);\n", n, flt(v[0], a0), flt(v[1], a1),
         flt(v[2], a2), flt(v[3], k0), flt(v[4], k1), flt(v[5], k2));
}
void GX_InitLightColor(GXLightObj* o, GXColor c) {
  const int n = object_name(o, "GXLightObj");
  append("  GX_InitLightColor(&o%d, (GXColor){%d, %d, %d, %d});\n", n, c.r, c.g, c.b, c.a);
}
void GX_InitLightSpot(GXLightObj* o, f32 cut_off, u8 fn) {
  char a[40];
  const int n = object_name(o, "GXLightObj");
  append("  GX_InitLightSpot(&o%d, %s, %d);\n", n, flt(a, cut_off), fn);
}
void GX_LoadLightObj(const GXLightObj* o, u8 id) {
  append("  GX_LoadLightObj(&o%d, %d);\n", object_name(o, "GXLightObj"), id);
}
void GX_SetNumChans(u8 n) {
  append("  GX_SetNumChans(%d);\n", n);
}
void GX_SetChanCtrl(s32 ch, u8 en, u8 amb, u8 mat, u8 lit, u8 diff, u8 attn) {
  append("  GX_SetChanCtrl(%d, %d, %d, %d, %d, %d, %d);\n", ch, en, amb, mat, lit, diff, attn);
}
void GX_SetChanAmbColor(s32 ch, GXColor c) {
  append("  GX_SetChanAmbColor(%d, (GXColor){%d, %d, %d, %d});\n", ch, c.r, c.g, c.b, c.a);
}
void GX_SetChanMatColor(s32 ch, GXColor c) {
  append("  GX_SetChanMatColor(%d, (GXColor){%d, %d, %d, %d});\n", ch, c.r, c.g, c.b, c.a);
}
void GX_LoadTexMtxImm(Mtx m, u32 id, u8 type) {
  char v[12][40];
  static int count;
  int i;
  for (i = 0; i < 12; ++i) flt(v[i], m[i / 4][i % 4]);
  append("  Mtx m%d = {{%s, %s, %s, %s}, {%s, %s, %s, %s}, {%s, %s, %s, %s}};\n", count, v[0], v[1],
         v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]);
  append("  GX_LoadTexMtxImm(m%d, %u, %d);\n", count++, id, type);
}
void GX_SetNumTexGens(u32 n) {
  append("  GX_SetNumTexGens(%u);\n", n);
}
void GX_SetTexCoordGen(u16 coord, u32 type, u32 src, u32 mtx) {
  append("  GX_SetTexCoordGen(%d, %u, %u, %u);\n", coord, type, src, mtx);
}

/* Bytes of a texture in GX tile order: I8 8x4 tiles of 32 bytes, RGB565 4x4 of 32, RGBA8 4x4
   of 64 [OGC gx.c GX_GetTexBufferSize]. */
static size_t texture_bytes(int w, int h, int fmt) {
  const int tw = fmt == GX_TF_I8 ? 8 : 4, th = 4;
  const size_t tile = fmt == GX_TF_RGBA8 ? 64 : 32;
  return (size_t)((w + tw - 1) / tw) * (size_t)((h + th - 1) / th) * tile;
}

void GX_InitTexObj(GXTexObj* o, void* image, u16 w, u16 h, u8 fmt, u8 ws, u8 wt, u8 mip) {
  int a;
  const int n = object_name(o, "GXTexObj");
  for (a = 0; a < array_count; ++a)
    if (arrays[a] == image) break;
  if (a == array_count) {
    /* A mip chain (power-of-two sides) holds every level after the one before, down to 1x1
       (gx/mip_chain.h mip_chain_bytes); the interpreter counts the levels from the bytes. */
    size_t bytes = texture_bytes(w, h, fmt);
    int lw = w, lh = h;
    while (mip && (lw > 1 || lh > 1)) {
      lw = lw > 1 ? lw / 2 : 1;
      lh = lh > 1 ? lh / 2 : 1;
      bytes += texture_bytes(lw, lh, fmt);
    }
    const u8* p = image;
    size_t i, at = strlen(top);
    arrays[array_count++] = image;
    at += (size_t)snprintf(top + at, sizeof top - at, "u8 a%d[%zu] ATTRIBUTE_ALIGN(32) = {", a,
                           bytes);
    for (i = 0; i < bytes && at + 8 < sizeof top; ++i)
      at += (size_t)snprintf(top + at, sizeof top - at, "%s%d", i ? "," : "", p[i]);
    snprintf(top + at, sizeof top - at, "};\n");
  }
  append("  GX_InitTexObj(&o%d, a%d, %d, %d, %d, %d, %d, %d);\n", n, a, w, h, fmt, ws, wt, mip);
}
void GX_InitTexObjLOD(GXTexObj* o, u8 minfilt, u8 magfilt, f32 minlod, f32 maxlod, f32 lodbias,
                      u8 biasclamp, u8 edgelod, u8 maxaniso) {
  char a[40], b[40], c[40];
  append("  GX_InitTexObjLOD(&o%d, %d, %d, %s, %s, %s, %d, %d, %d);\n", object_name(o, "GXTexObj"),
         minfilt, magfilt, flt(a, minlod), flt(b, maxlod), flt(c, lodbias), biasclamp, edgelod,
         maxaniso);
}
void GX_LoadTexObj(GXTexObj* o, u8 map) {
  append("  GX_LoadTexObj(&o%d, %d);\n", object_name(o, "GXTexObj"), map);
}
void GX_SetNumTevStages(u8 n) {
  append("  GX_SetNumTevStages(%d);\n", n);
}
void GX_SetTevColor(u8 reg, GXColor c) {
  append("  GX_SetTevColor(%d, (GXColor){%d, %d, %d, %d});\n", reg, c.r, c.g, c.b, c.a);
}
void GX_SetTevOrder(u8 s, u8 coord, u32 map, u8 color) {
  append("  GX_SetTevOrder(%d, %d, %u, %d);\n", s, coord, map, color);
}
void GX_SetTevColorIn(u8 s, u8 a, u8 b, u8 c, u8 d) {
  append("  GX_SetTevColorIn(%d, %d, %d, %d, %d);\n", s, a, b, c, d);
}
void GX_SetTevAlphaIn(u8 s, u8 a, u8 b, u8 c, u8 d) {
  append("  GX_SetTevAlphaIn(%d, %d, %d, %d, %d);\n", s, a, b, c, d);
}
void GX_SetTevColorOp(u8 s, u8 op, u8 bias, u8 scale, u8 clamp, u8 reg) {
  append("  GX_SetTevColorOp(%d, %d, %d, %d, %d, %d);\n", s, op, bias, scale, clamp, reg);
}
void GX_SetTevAlphaOp(u8 s, u8 op, u8 bias, u8 scale, u8 clamp, u8 reg) {
  append("  GX_SetTevAlphaOp(%d, %d, %d, %d, %d, %d);\n", s, op, bias, scale, clamp, reg);
}
void GX_SetTevKAlphaSel(u8 s, u8 sel) {
  append("  GX_SetTevKAlphaSel(%d, %d);\n", s, sel);
}
void GX_SetBlendMode(u8 type, u8 src, u8 dst, u8 op) {
  append("  GX_SetBlendMode(%d, %d, %d, %d);\n", type, src, dst, op);
}
void GX_SetZMode(u8 e, u8 f, u8 u) {
  append("  GX_SetZMode(%d, %d, %d);\n", e, f, u);
}
void GX_SetAlphaCompare(u8 c0, u8 r0, u8 op, u8 c1, u8 r1) {
  append("  GX_SetAlphaCompare(%d, %d, %d, %d, %d);\n", c0, r0, op, c1, r1);
}
void GX_SetCullMode(u8 mode) {
  append("  GX_SetCullMode(%d);\n", mode);
}

/* The F32 draw is not recorded: the emulator takes geometry and matrices from the scene. A
   stored module's draw is (ltr_host_draws_begin .. ltr_host_draws), as segments: a kind byte,
   a 4-byte host-order length, the bytes:
     'P' GX_LoadPosMtxImm's 12 floats, 'N' GX_LoadNrmMtxImm's 9 (big-endian, as the FIFO has them)
     'A' GX_SetArray's attribute and stride bytes, then the array's bytes (DCFlushRange's length)
     'F' GX_SetVtxAttrFmt's attribute, count, type, fraction; 'V' GX_SetVtxDesc's attribute, type
     'D' a GX_Begin .. GX_End sent to the FIFO: the command byte, the count (big-endian), indices
     'L' a GX_CallDispList: the list's bytes as GX_EndDispList left them (padded to 32). */
static u8* draws;
static u32 draws_length, draws_capacity;
static u8 scratch[1 << 22];
static u32 scratch_length;
static u8* list;
static u32 list_capacity, list_length;
static int in_list;
static struct {
  void* start;
  u32 length;
} flushed[4096];
static int flushed_count;

static void draw_segment(u8 kind, const u8* bytes, u32 n) {
  if (draws_length + n + 5 > draws_capacity) {
    draws_capacity = (draws_length + n + 5) * 2;
    draws = realloc(draws, draws_capacity);
  }
  draws[draws_length] = kind;
  memcpy(draws + draws_length + 1, &n, 4);
  memcpy(draws + draws_length + 5, bytes, n);
  draws_length += n + 5;
}
void ltr_host_draws_begin(void) {
  draws_length = 0;
  recording_draws = 1;
}
const u8* ltr_host_draws(u32* length) {
  recording_draws = 0;
  *length = draws_length;
  return draws;
}
/* A byte written to the FIFO: into the display list being recorded, else the open draw. */
static void put8(u8 b) {
  if (in_list) {
    if (list_length < list_capacity) list[list_length] = b;
    ++list_length;
  } else if (scratch_length < sizeof scratch) {
    scratch[scratch_length++] = b;
  }
}
static void put16(u16 v) {
  put8((u8)(v >> 8));
  put8((u8)v);
}
static void matrix(u8 kind, Mtx m, int columns) {
  u8 bytes[48];
  int r, c, i = 0;
  for (r = 0; r < 3; ++r) {
    for (c = 0; c < columns; ++c) {
      u32 w;
      memcpy(&w, &m[r][c], 4);
      bytes[i++] = (u8)(w >> 24), bytes[i++] = (u8)(w >> 16), bytes[i++] = (u8)(w >> 8);
      bytes[i++] = (u8)w;
    }
  }
  if (recording_draws) draw_segment(kind, bytes, (u32)i);
}
void GX_LoadPosMtxImm(Mtx m, u32 id) {
  (void)id;
  matrix('P', m, 4);
}
void GX_LoadNrmMtxImm(Mtx m, u32 id) {
  (void)id;
  matrix('N', m, 3);
}
void GX_SetCurrentMtx(u32 id) {
  (void)id;
}
void GX_Begin(u8 p, u8 f, u16 n) {
  if (!in_list) scratch_length = 0;
  put8((u8)(p | f));
  put16(n);
}
void GX_Position1x8(u8 i) {
  put8(i);
}
void GX_Position1x16(u16 i) {
  put16(i);
}
void GX_Normal1x8(u8 i) {
  put8(i);
}
void GX_Normal1x16(u16 i) {
  put16(i);
}
void GX_Color1x8(u8 i) {
  put8(i);
}
void GX_Color1x16(u16 i) {
  put16(i);
}
void GX_TexCoord1x8(u8 i) {
  put8(i);
}
void GX_TexCoord1x16(u16 i) {
  put16(i);
}
void GX_SetArray(u32 attr, void* ptr, u8 stride) {
  int i;
  u32 n = 0;
  u8* bytes;
  if (!recording_draws) return;
  for (i = 0; i < flushed_count; ++i)
    if (flushed[i].start == ptr) n = flushed[i].length;
  bytes = malloc(n + 2);
  bytes[0] = (u8)attr;
  bytes[1] = stride;
  memcpy(bytes + 2, ptr, n);
  draw_segment('A', bytes, n + 2);
  free(bytes);
}
void GX_BeginDispList(void* l, u32 size) {
  list = l;
  list_capacity = size;
  list_length = 0;
  in_list = 1;
}
/* Pads with GX_NOP to 32 bytes; 0 when the list overflowed its buffer (libogc's FIFO ends 4
   bytes before it [OGC gx.c GX_BeginDispList]). */
u32 GX_EndDispList(void) {
  while (list_length % 32) put8(0);
  in_list = 0;
  return list_length + 4 > list_capacity ? 0 : list_length;
}
void GX_CallDispList(void* l, u32 n) {
  if (recording_draws) draw_segment('L', l, n);
}
void GX_Position3f32(f32 x, f32 y, f32 z) {
  (void)x, (void)y, (void)z;
}
void GX_Normal3f32(f32 x, f32 y, f32 z) {
  (void)x, (void)y, (void)z;
}
void GX_Color4u8(u8 r, u8 g, u8 b, u8 a) {
  (void)r, (void)g, (void)b, (void)a;
}
void GX_TexCoord1f32(f32 s) {
  (void)s;
}
void GX_TexCoord2f32(f32 s, f32 t) {
  (void)s, (void)t;
}
void GX_End(void) {
  if (!in_list && recording_draws) draw_segment('D', scratch, scratch_length);
}
void DCFlushRange(void* p, u32 n) {
  int i;
  for (i = 0; i < flushed_count; ++i)
    if (flushed[i].start == p) break;
  if (i == (int)(sizeof flushed / sizeof flushed[0])) return;
  flushed[i].start = p;
  flushed[i].length = n;
  if (i == flushed_count) ++flushed_count;
}
void GX_InvalidateTexAll(void) {}

/* TPL files as libogc reads them [OGC tpl.c L147-250], on a little-endian host: the file is
   big-endian, so every field is read byte by byte. The header's filters count only for a mip
   chain (max LOD > 0): then GX_InitTexObjLOD with them, libogc's biasclamp (bias > 0) passed as
   both the bias clamp and the edge LOD, the edge LOD byte as the anisotropy [OGC tpl.c
   L241-248]; the module's pass then sets its own LOD fields. */
static u32 be32(const u8* p) {
  return (u32)p[0] << 24 | (u32)p[1] << 16 | (u32)p[2] << 8 | p[3];
}
static f32 bef32(const u8* p) {
  const u32 bits = be32(p);
  f32 v;
  memcpy(&v, &bits, sizeof v);
  return v;
}
s32 TPL_OpenTPLFromMemory(TPLFile* tdf, void* memory, u32 len) {
  if (!memory || !len) return -1;
  tdf->type = 1;
  tdf->ntextures = (int)be32((const u8*)memory + 4);
  tdf->texdesc = memory;
  tdf->tpl_file = 0;
  return 1;
}
s32 TPL_GetTexture(TPLFile* tdf, s32 id, GXTexObj* texObj) {
  const u8* p = tdf->texdesc;
  const u8* image;
  if (id < 0 || id >= tdf->ntextures) return -1;
  image = p + be32(p + 12 + 8 * (u32)id);
  GX_InitTexObj(texObj, (void*)(p + be32(image + 4 + 4)), (u16)(image[2] << 8 | image[3]),
                (u16)(image[0] << 8 | image[1]), (u8)be32(image + 4), (u8)be32(image + 12),
                (u8)be32(image + 16), image[34] > 0);
  if (image[34] > 0) {
    const f32 bias = bef32(image + 28);
    GX_InitTexObjLOD(texObj, (u8)be32(image + 20), (u8)be32(image + 24), image[33], image[34], bias,
                     bias > 0, bias > 0, image[32]);
  }
  return 0;
}
