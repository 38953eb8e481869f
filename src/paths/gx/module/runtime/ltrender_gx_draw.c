/* The GX side of a module (`ltrender export gx --format module`): the view matrix and the
   immediate-mode draw of one mesh. C99 over libogc's gccore.h, no allocation. */

/* The vertex format the passes declare and the draws name: the gx variant's :vat=N defines it
   as GX_VTXFMTN before this runtime (the draw command's low three bits pick the VAT the CP reads
   the vertices with [DHW OpcodeDecoding.h detail::RunCommand: vat = cmdbyte & GX_VAT_MASK]). */
#ifndef LTRENDER_VTXFMT
#define LTRENDER_VTXFMT GX_VTXFMT0
#endif

/* A colour byte quadruple of the per-frame state as the GXColor a call passes. */
#define LTR_GXCOLOR(c) ((GXColor){(c)[0], (c)[1], (c)[2], (c)[3]})
/* A TEV scale factor (1, 2, 4) as GX_SetTevColorOp's tevscale [OGC gx.h L578-640]. */
#define LTR_TEV_SCALE(f) ((f) == 4 ? GX_CS_SCALE_4 : (f) == 2 ? GX_CS_SCALE_2 : GX_CS_SCALE_1)

/* Loads the view as the position and normal matrix GX_PNMTX0: the rotation of ltr_view_of and
   the translation -R eye, so the mesh goes in as world space. (ltrender's emulator sends the
   positions relative to the eye and loads the rotation alone; the two differ only in the float
   rounding of the translation.) The normal matrix of a rotation is the rotation itself. The
   eye-space light positions of ltr_pass_setup are in this very space. */
void ltr_load_view(const ltr_view* view) {
  Mtx m;
  int r, c;
  for (r = 0; r < 3; ++r) {
    double t = 0;
    for (c = 0; c < 3; ++c) {
      m[r][c] = (f32)view->rotation[r][c];
      t -= view->rotation[r][c] * view->eye[c];
    }
    m[r][3] = (f32)t;
  }
  GX_LoadPosMtxImm(m, GX_PNMTX0);
  GX_LoadNrmMtxImm(m, GX_PNMTX0);
  GX_SetCurrentMtx(GX_PNMTX0);
}

/* The mesh's triangles in the vertex format a pass declared (LTRENDER_VTXFMT, every attribute
   GX_DIRECT): position and normal always, then the thickness colour, t and the UV where the
   pass sends them. GX_Begin counts vertices in a u16, so a long list goes in several batches. */
void ltr_draw_mesh(const ltr_mesh* mesh, int colour, const float* t, int uv) {
  const int batch = 65535 - 65535 % 3;
  int first = 0;
  while (first < mesh->index_count) {
    const int n = mesh->index_count - first < batch ? mesh->index_count - first : batch;
    int i;
    GX_Begin(GX_TRIANGLES, LTRENDER_VTXFMT, (u16)n);
    for (i = first; i < first + n; ++i) {
      const int v = mesh->indices[i];
      GX_Position3f32(mesh->positions[3 * v], mesh->positions[3 * v + 1],
                      mesh->positions[3 * v + 2]);
      GX_Normal3f32(mesh->normals[3 * v], mesh->normals[3 * v + 1], mesh->normals[3 * v + 2]);
      if (colour)
        GX_Color4u8(mesh->colors[4 * v], mesh->colors[4 * v + 1], mesh->colors[4 * v + 2], 255);
      if (t) GX_TexCoord1f32(t[v]);
      if (uv) GX_TexCoord2f32(mesh->uvs[2 * v], mesh->uvs[2 * v + 1]);
    }
    GX_End();
    first += n;
  }
}
