/* The GX side of a module of a stored variant (`export gx --variant V --format module`, V with
   :vtx= :nrm= :clr= :uv= and :draw=indexed, strips or list): the scene's meshes as a game ships
   them, converted once at export, in the object's own coordinates, quantised as ltrender's
   emulator stores them (the very bytes: gx/vertex_quantiser.h index_attributes), each attribute
   an array of its distinct elements, 32-byte aligned [OGC gc/ogc/cache.h L123-139].
   ltr_stored_init flushes them from the CPU's cache once and builds each display list once;
   every frame, each object loads its matrices for the view and its format, points the CP at its
   arrays and sends its draws or calls its list, in the order ltrender's FIFO log does
   (paths/gx/indexed_recording.cpp draw_indexed_object). A pass that sends t (t=vertex) has a t
   array of its own, one element per vertex of the mesh, which ltr_stored_write_t rewrites and
   flushes every frame before the draw; its indices, and so the display list, never change.
   C99 over libogc's gccore.h, no allocation. */

/* One attribute's array: GX_SetVtxDesc's index type, GX_SetVtxAttrFmt's count, type and
   fraction, and GX_SetArray's base and stride. */
typedef struct {
  u8 attribute; /* GX_VA_POS, GX_VA_NRM (GX_VA_NBT), GX_VA_CLR0, GX_VA_TEXn */
  u8 index;     /* GX_INDEX8 or GX_INDEX16 */
  u8 count, type, frac;
  void* data; /* 32-byte aligned */
  u32 bytes;
  u8 stride;
} ltr_stored_array;

/* One object in one pass: where it stands, its arrays, and its draws: draw_count GX_Begin's of
   `primitive`, draw k sending draw_vertices[k] vertices, each vertex one index per array in
   `indices` (in array order). Under :draw=list the draws are a display list, `list`
   (list_capacity bytes, 32-byte aligned) holds it after ltr_stored_init, list_size its bytes.
   arrays[t_array] is the pass's t (GX_TEX_S), or t_array is -1; t_auto_frac: its fraction is
   chosen again every frame from the frame's t (:uv=TYPE/auto). */
typedef struct {
  const ltr_object_place* place;
  int array_count;
  ltr_stored_array* arrays;
  u8 primitive; /* GX_TRIANGLES or GX_TRIANGLESTRIP */
  int draw_count;
  const u16* draw_vertices;
  const u16* indices;
  void* list; /* 0: the draws are sent every frame */
  u32 list_capacity, list_size;
  int t_array;
  int t_auto_frac;
} ltr_stored_draw;

/* ---- the per-vertex t, stored each frame as ltrender's converter stores it ----
   gx/vertex_quantiser.cpp quantise_component (what the FIFO log's arrays hold): v 2^frac rounded
   to the nearest integer, halves away from zero (C99 round, as std::round), the half step past
   either end of the type clamped to it; F32 the float's bits. Big-endian, as the GP reads memory.
   Where the emulator refuses a value (more than half a step outside the type, e.g. a negative t
   in u16), the module cannot refuse a frame: it clamps to the type's end. */

/* GX_U8, GX_S8, GX_U16, GX_S16's integers (vertex_quantiser.h integer_range). */
static void ltr_integer_range(u8 type, double* lo, double* hi) {
  *lo = type == GX_S8 ? -128.0 : type == GX_S16 ? -32768.0 : 0.0;
  *hi = type == GX_U8 ? 255.0 : type == GX_S8 ? 127.0 : type == GX_U16 ? 65535.0 : 32767.0;
}

/* Whether v 2^frac is within half a step of the type's integers (quantise_component). */
static int ltr_holds(double v, u8 type, int frac) {
  double lo, hi;
  const double scaled = ldexp(v, frac);
  ltr_integer_range(type, &lo, &hi);
  return scaled >= lo - 0.5 && scaled <= hi + 0.5; /* false for NaN and the infinities */
}

/* The widest fraction (31 .. 0) that holds lo and hi (vertex_quantiser.h widest_fraction); 0
   where none does (the emulator refuses such a frame). */
static int ltr_widest_fraction(double lo, double hi, u8 type) {
  int frac;
  for (frac = 31; frac > 0; --frac)
    if (ltr_holds(lo, type, frac) && ltr_holds(hi, type, frac)) return frac;
  return 0;
}

static void ltr_put_be(u8* out, u32 v, int bytes) {
  int i;
  for (i = 0; i < bytes; ++i) out[i] = (u8)(v >> (8 * (bytes - 1 - i)));
}

/* Writes the frame's t (one float per vertex, ltr_fill_t's) into the draw's t array as its
   storage holds it, then flushes the array from the CPU's data cache [OGC gc/ogc/cache.h
   L123-139] (the array is 32-byte aligned: whole cache lines). */
void ltr_stored_write_t(ltr_stored_draw* d, const float* t) {
  ltr_stored_array* a = &d->arrays[d->t_array];
  u8* out = (u8*)a->data;
  const u32 n = a->bytes / a->stride;
  u32 v;
  if (a->type == GX_F32) {
    for (v = 0; v < n; ++v) {
      union {
        float f;
        u32 bits;
      } x;
      x.f = t[v];
      ltr_put_be(out + 4 * v, x.bits, 4);
    }
  } else {
    double lo = 0, hi = 0, type_lo, type_hi;
    ltr_integer_range(a->type, &type_lo, &type_hi);
    /* :uv=TYPE/auto: the widest fraction the frame's t allows, as storage_format picks it from
       the values' bounds (gx/vertex_storage.cpp resolved_fraction). */
    if (d->t_auto_frac) {
      for (v = 0; v < n; ++v) {
        if (v == 0 || t[v] < lo) lo = t[v];
        if (v == 0 || t[v] > hi) hi = t[v];
      }
      a->frac = (u8)ltr_widest_fraction(lo, hi, a->type);
    }
    for (v = 0; v < n; ++v) {
      double q = round(ldexp((double)t[v], a->frac));
      if (!(q >= type_lo)) q = type_lo; /* NaN too */
      if (q > type_hi) q = type_hi;
      ltr_put_be(out + a->stride * v, (u32)(long)q, (int)a->stride);
    }
  }
  DCFlushRange(a->data, a->bytes);
}

/* One index as the attribute's GX_INDEX8 or GX_INDEX16 (libogc's 1x8 and 1x16 writes). */
static void ltr_send_index(const ltr_stored_array* a, u16 i) {
  const int wide = a->index == GX_INDEX16;
  if (a->attribute == GX_VA_POS) {
    if (wide)
      GX_Position1x16(i);
    else
      GX_Position1x8((u8)i);
  } else if (a->attribute == GX_VA_NRM || a->attribute == GX_VA_NBT) {
    /* GX_NRM_NBT3: one index per vector, each the same element (the k-th vector is read from
       its k-th third [DHW VertexLoader_Normal.cpp Normal_ReadIndex_Offset]). */
    int k;
    for (k = 0; k < (a->count == GX_NRM_NBT3 ? 3 : 1); ++k) {
      if (wide)
        GX_Normal1x16(i);
      else
        GX_Normal1x8((u8)i);
    }
  } else if (a->attribute == GX_VA_CLR0) {
    if (wide)
      GX_Color1x16(i);
    else
      GX_Color1x8((u8)i);
  } else {
    if (wide)
      GX_TexCoord1x16(i);
    else
      GX_TexCoord1x8((u8)i);
  }
}

static void ltr_send_draws(const ltr_stored_draw* d) {
  const u16* index = d->indices;
  int k, v, a;
  for (k = 0; k < d->draw_count; ++k) {
    GX_Begin(d->primitive, LTRENDER_VTXFMT, d->draw_vertices[k]);
    for (v = 0; v < d->draw_vertices[k]; ++v)
      for (a = 0; a < d->array_count; ++a) ltr_send_index(&d->arrays[a], *index++);
    GX_End();
  }
}

/* The object's vertex descriptor and format (LTRENDER_VTXFMT): each array indexed, its storage. */
static void ltr_stored_format(const ltr_stored_draw* d) {
  int a;
  GX_ClearVtxDesc();
  for (a = 0; a < d->array_count; ++a) {
    const ltr_stored_array* x = &d->arrays[a];
    GX_SetVtxDesc(x->attribute, x->index);
    GX_SetVtxAttrFmt(LTRENDER_VTXFMT, x->attribute, x->count, x->type, x->frac);
  }
}

/* Once, before the first frame: every array flushed from the CPU's data cache (the GP reads
   main memory), then each display list recorded. GX_BeginDispList sends the state set before it
   to the FIFO, not the list [OGC gx.c GX_BeginDispList], so the list holds the draws alone;
   GX_EndDispList pads it to 32 bytes and gives its size (0 had it overflowed: our bug). */
void ltr_stored_init(ltr_stored_draw draws[], int count) {
  int i, a;
  for (i = 0; i < count; ++i)
    for (a = 0; a < draws[i].array_count; ++a)
      DCFlushRange(draws[i].arrays[a].data, draws[i].arrays[a].bytes);
  for (i = 0; i < count; ++i) {
    ltr_stored_draw* d = &draws[i];
    if (!d->list) continue;
    ltr_stored_format(d);
    GX_BeginDispList(d->list, d->list_capacity);
    ltr_send_draws(d);
    d->list_size = GX_EndDispList();
    DCFlushRange(d->list, d->list_capacity);
  }
}

/* One object in one pass, after the pass function: its matrices under `view`
   (ltr_object_matrices), its format, its arrays, then its draws or its list. */
void ltr_stored_draw_object(const ltr_view* view, const ltr_stored_draw* d) {
  Mtx position, normal;
  float p[3][4], n[3][3];
  int r, c, a;
  ltr_object_matrices(view, d->place, p, n);
  for (r = 0; r < 3; ++r) {
    for (c = 0; c < 4; ++c) position[r][c] = p[r][c];
    for (c = 0; c < 3; ++c) normal[r][c] = n[r][c];
    normal[r][3] = 0;
  }
  GX_LoadPosMtxImm(position, GX_PNMTX0);
  GX_LoadNrmMtxImm(normal, GX_PNMTX0);
  GX_SetCurrentMtx(GX_PNMTX0);
  ltr_stored_format(d);
  for (a = 0; a < d->array_count; ++a)
    GX_SetArray(d->arrays[a].attribute, d->arrays[a].data, d->arrays[a].stride);
  if (d->list)
    GX_CallDispList(d->list, d->list_size);
  else
    ltr_send_draws(d);
}
