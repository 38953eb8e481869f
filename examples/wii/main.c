/* A GX module in a Wii program: the file a porter starts from.
 *
 *   ltrender export gx scenes/backlit_sphere.json --format module -o ltrender_module.c
 *
 * writes the module next to this file; it is #included below (one translation unit, as the
 * module's runtime functions are not static). Video and GX are set up as libogc's examples do
 * (devkitPro wii-examples, graphics/gx/triangle); every frame the camera orbits the scene's
 * target and light 0 turns, the module's setup computes that frame's GX state from them, and
 * the scene's first material is drawn on a sphere made here (a game draws its own meshes, in
 * world space, with ltr_mesh pointing at its arrays).
 *
 * Build with devkitPPC's Wii rules and -ffp-contract=off (see ltrender_gx_runtime.h). */
#include <gccore.h>
#include <malloc.h>
#include <math.h>
#include <string.h>

#include "ltrender_module.c"

#define FIFO_SIZE (256 * 1024)
#define RINGS 24
#define SEGMENTS 48
#define VERTICES ((RINGS + 1) * (SEGMENTS + 1))
#define INDICES (RINGS * SEGMENTS * 6)

static float positions[VERTICES * 3], normals[VERTICES * 3], uvs[VERTICES * 2], t_scratch[VERTICES];
static unsigned char colors[VERTICES * 4];
static unsigned short indices[INDICES];

/* A unit sphere at the camera's target: positions, normals, UVs, white thickness colours. */
static void make_sphere(ltr_mesh* mesh, const float centre[3]) {
  int r, s, v = 0, i = 0;
  for (r = 0; r <= RINGS; ++r) {
    const float theta = (float)M_PI * r / RINGS;
    for (s = 0; s <= SEGMENTS; ++s, ++v) {
      const float phi = 2.0f * (float)M_PI * s / SEGMENTS;
      const float n[3] = {sinf(theta) * cosf(phi), cosf(theta), sinf(theta) * sinf(phi)};
      int c;
      for (c = 0; c < 3; ++c) {
        normals[3 * v + c] = n[c];
        positions[3 * v + c] = centre[c] + n[c];
      }
      uvs[2 * v] = (float)s / SEGMENTS;
      uvs[2 * v + 1] = 1.0f - (float)r / RINGS;
      memset(&colors[4 * v], 255, 4);
    }
  }
  for (r = 0; r < RINGS; ++r) {
    for (s = 0; s < SEGMENTS; ++s) {
      const unsigned short a = (unsigned short)(r * (SEGMENTS + 1) + s), b = a + SEGMENTS + 1;
      const unsigned short quad[6] = {a, b, a + 1, a + 1, b, b + 1};
      memcpy(&indices[i], quad, sizeof quad);
      i += 6;
    }
  }
  mesh->positions = positions;
  mesh->normals = normals;
  mesh->colors = colors;
  mesh->uvs = uvs;
  mesh->vertex_count = VERTICES;
  mesh->indices = indices;
  mesh->index_count = INDICES;
}

/* v turned by `angle` radians about the y axis through `centre`. */
static void orbit(const float v[3], const float centre[3], float angle, float out[3]) {
  const float x = v[0] - centre[0], z = v[2] - centre[2];
  out[0] = centre[0] + x * cosf(angle) + z * sinf(angle);
  out[1] = v[1];
  out[2] = centre[2] - x * sinf(angle) + z * cosf(angle);
}

int main(int argc, char** argv) {
  static void* xfb[2];
  static ltr_pass_state state[LTRENDER_MAX_PASSES];
  const GXColor background = {0, 0, 0, 255};
  const float origin[3] = {0.0f, 0.0f, 0.0f};
  GXRModeObj* rmode;
  void* fifo;
  Mtx44 projection;
  ltr_mesh sphere;
  u32 fb = 0, xfb_height, frame = 0;
  f32 yscale;
  (void)argc;
  (void)argv;

  VIDEO_Init();
  rmode = VIDEO_GetPreferredMode(NULL);
  xfb[0] = MEM_K0_TO_K1(SYS_AllocateFramebuffer(rmode));
  xfb[1] = MEM_K0_TO_K1(SYS_AllocateFramebuffer(rmode));
  VIDEO_Configure(rmode);
  VIDEO_SetNextFramebuffer(xfb[fb]);
  VIDEO_SetBlack(FALSE);
  VIDEO_Flush();
  VIDEO_WaitVSync();
  if (rmode->viTVMode & VI_NON_INTERLACE) VIDEO_WaitVSync();

  fifo = memalign(32, FIFO_SIZE);
  memset(fifo, 0, FIFO_SIZE);
  GX_Init(fifo, FIFO_SIZE);
  GX_SetCopyClear(background, 0x00ffffff);
  GX_SetViewport(0, 0, rmode->fbWidth, rmode->efbHeight, 0, 1);
  yscale = GX_GetYScaleFactor(rmode->efbHeight, rmode->xfbHeight);
  xfb_height = GX_SetDispCopyYScale(yscale);
  GX_SetScissor(0, 0, rmode->fbWidth, rmode->efbHeight);
  GX_SetDispCopySrc(0, 0, rmode->fbWidth, rmode->efbHeight);
  GX_SetDispCopyDst(rmode->fbWidth, xfb_height);
  GX_SetCopyFilter(rmode->aa, rmode->sample_pattern, GX_TRUE, rmode->vfilter);
  GX_SetFieldMode(rmode->field_rendering,
                  ((rmode->viHeight == 2 * rmode->xfbHeight) ? GX_ENABLE : GX_DISABLE));
  GX_CopyDisp(xfb[fb], GX_TRUE);
  GX_SetDispCopyGamma(GX_GM_1_0);

  /* The scene's projection; the module lights in the eye space of ltr_load_view. */
  if (LTRENDER_ORTHOGRAPHIC) {
    const f32 h = LTRENDER_ORTHO_HEIGHT / 2, w = h * rmode->fbWidth / rmode->efbHeight;
    guOrtho(projection, h, -h, -w, w, LTRENDER_NEAR, LTRENDER_FAR);
    GX_LoadProjectionMtx(projection, GX_ORTHOGRAPHIC);
  } else {
    guPerspective(projection, LTRENDER_FOV_Y_DEG, (f32)rmode->fbWidth / rmode->efbHeight,
                  LTRENDER_NEAR, LTRENDER_FAR);
    GX_LoadProjectionMtx(projection, GX_PERSPECTIVE);
  }
  make_sphere(&sphere, ltrender_scene_camera.target);
  ltrender_flush_textures();

  for (;;) {
    const float angle = 0.01f * frame++;
    ltr_camera camera = ltrender_scene_camera;
    ltr_light lights[LTRENDER_LIGHTS + 1];
    ltr_view view;
    const ltr_material_module* material = &ltrender_materials[0];
    memcpy(lights, ltrender_scene_lights, sizeof ltrender_scene_lights);
    /* This frame's camera and light 0, in world space as the game keeps them. */
    orbit(ltrender_scene_camera.eye, ltrender_scene_camera.target, angle, camera.eye);
    if (LTRENDER_LIGHTS > 0) {
      orbit(ltrender_scene_lights[0].position, ltrender_scene_camera.target, -0.7f * angle,
            lights[0].position);
      orbit(ltrender_scene_lights[0].direction, origin, -0.7f * angle, lights[0].direction);
    }
    ltrender_view(&camera, &view);

    GX_SetViewport(0, 0, rmode->fbWidth, rmode->efbHeight, 0, 1);
    GX_InvVtxCache();
    ltr_load_view(&view);
    material->setup(&view, lights, &sphere, 1, state);
    material->draw(state, &view, lights, &sphere, t_scratch);
    GX_DrawDone();

    fb ^= 1;
    GX_SetZMode(GX_TRUE, GX_LEQUAL, GX_TRUE);
    GX_SetColorUpdate(GX_TRUE);
    GX_CopyDisp(xfb[fb], GX_TRUE);
    VIDEO_SetNextFramebuffer(xfb[fb]);
    VIDEO_Flush();
    VIDEO_WaitVSync();
  }
  return 0;
}
