/* The per-frame maths of a GX module (`ltrender export gx --format module`): what ltrender's gx
   planner (src/paths/gx/pass_planner.cpp) computes at export time, computed by the game each
   frame from its camera and lights. Plain C99 over plain types (no libogc, no allocation), so
   the same text compiles for the console and, in ltrender's tests, on the host, where its
   results drive ltrender's GX emulator (tests/gx_module_test.cpp).

   Every operation is in double and in the order the planner uses (glm's dot is
   (x x' + y y') + z z', normalize is v * (1 / sqrt(v.v)), lookAt's rows are s, u, -f), so the
   floats and bytes it hands to GX are the very ones `export gx --format c` prints for that frame.
   Compile it with -ffp-contract=off (GCC fuses a*b+c into one PowerPC fmadd by default, which
   rounds once where ltrender rounds twice: the results would then differ in the last bit). */
#ifndef LTRENDER_GX_RUNTIME_H
#define LTRENDER_GX_RUNTIME_H

#ifdef __cplusplus
extern "C" {
#endif

/* Hardware lights per pass: the XF sums up to 8 in one channel [OGC gx.h L178-187]. */
#define LTR_MAX_LIGHTS 8

/* The camera as guLookAt takes it, in world space. */
typedef struct {
  float eye[3], target[3], up[3];
} ltr_camera;

/* The view the XF lights in: eye space is the world rotated by `rotation` about the eye. */
typedef struct {
  double eye[3];
  double rotation[3][3]; /* world -> eye, rows s, u, -f as glm::lookAt builds them */
  double forward[3];     /* normalize(target - eye) */
  int orthographic;      /* V = -forward everywhere; else V = normalize(eye - P) */
} ltr_view;

/* One light as the game keeps it, world space. A point light uses `position`, a directional
   light `direction` (where its light travels). `color` is linear and may exceed 1 (intensity
   included); `translucency_scale` is the seed's per-light s. */
typedef struct {
  float position[3];
  float direction[3];
  float color[3];
  float translucency_scale;
} ltr_light;

/* What the export fixed about a light: its type and distance attenuation 1 / (kc + kl d + kq d^2).
 */
typedef struct {
  int point;
  double kc, kl, kq;
} ltr_light_kind;

/* An object's vertices as the game sends them: world-space positions and normals (xyz per
   vertex), the baked thickness colour (rgba per vertex, or 0 when the material has none), the
   UVs (uv per vertex, or 0), and the triangles as a list of vertex indices. The colours and UVs
   must be there where a pass sends them (its vertex format declares GX_VA_CLR0 / a GX_TEX_ST). */
typedef struct {
  const float* positions;
  const float* normals;
  const unsigned char* colors;
  const float* uvs;
  int vertex_count;
  const unsigned short* indices;
  int index_count;
} ltr_mesh;

/* What one light does at the vertices that can be seen: the largest attenuation and the largest
   att x max(N.L, 0). The TEV scales are chosen from it. */
typedef struct {
  double max_attenuation, max_diffuse;
} ltr_light_range;

/* One hardware light object: eye-space position, colour normalised to 255 at its largest
   component, and the distance coefficients with the rest of its magnitude divided in. The XF
   specular light of lobe=xf-spec has no distance term: k is then the fitted lobe's denominator,
   `a` its numerator times the light's magnitude, and `direction` what GX_InitLightDir is passed
   (the negated direction slot u, as libogc stores it negated [OGC gx.c L4686-4693]). */
typedef struct {
  float position[3];
  unsigned char color[4];
  float k[3];
  float a[3];
  float direction[3];
} ltr_light_object;

/* Everything a pass function sets that changes from frame to frame. */
typedef struct {
  ltr_light_object light[LTR_MAX_LIGHTS]; /* by hardware slot GX_LIGHTn */
  unsigned char ambient[2][4];            /* GX_COLOR0A0's and GX_COLOR1A1's ambient register */
  unsigned char reg0[4];                  /* GX_TEVREG0 = 255 a / (a + s) */
  float lut_matrix[3][4];                 /* t from the normal: the texgen matrix (rows 0, 1) */
  int translucency_scale, diffuse_scale;  /* the TEV scales, 1, 2 or 4 */
  int translucency_saturates, diffuse_saturates; /* the light needs more than x4 */
} ltr_pass_state;

/* What the export fixed about a material. `tint` is the thickness tint where the thickness comes
   per vertex or from a map (it then rides in the light colour), 1 otherwise. */
typedef struct {
  double albedo[3], tint[3];
  double ambient, distortion; /* a, d */
  int normalize_h;
  double t_max;      /* the thickness the material register's 255 stands for */
  int lut_size;      /* W texels */
  int t_from_normal; /* t=texgen: t through a texture matrix from the raw normal */
  int view_object;   /* :view=object: V and L taken at the centre of the meshes set up together */
  int xf_spec;       /* lobe=xf-spec: the lobe fitted as the XF specular attenuation */
  double power;      /* p of the lobe t^p (what lobe=xf-spec fits) */
} ltr_material;

/* What the export fixed about one pass (which stages and lights it has). */
typedef struct {
  int diffuse_only; /* one diffuse stage for lights [light, light + light_count) */
  int light, light_count;
  int translucent; /* COLOR0 carries the translucency */
  int lut;         /* stage 0 reads the lobe LUT */
} ltr_pass_shape;

/* What the export fixed about the scene. */
typedef struct {
  const ltr_light_kind* kinds;
  int light_count;
  double ambient_light[3];
} ltr_scene;

/* The view of a camera (glm::lookAt from the origin towards the camera's forward). */
void ltr_view_of(const ltr_camera* camera, int orthographic, ltr_view* view);

/* Widens `range` by the vertices of `mesh` that can be seen (N.V >= -0.2: the back faces hide
   behind the front, the slack keeps the silhouette). Start from {0, 0}.
   Cost per vertex (flops counting each add, multiply, divide, negate; divisions in brackets):
   perspective camera and point light about 45 (7) and 2 square roots; a directional light about
   30 (3) and 1 square root; an orthographic camera saves 14 flops and a square root. */
void ltr_light_range_of(const ltr_view* view, const ltr_light_kind* kind, const ltr_light* light,
                        const ltr_mesh* mesh, ltr_light_range* range);

/* The range of a declared bound instead of a scan (`--light-range D`, :light-range=D): every
   point light stays at least `min_distance` from the vertices it lights, so its attenuation there
   and att x N.L are at most 1 / (kc + kl D + kq D^2); a directional light's are 1. D = 0 holds
   whatever the scene does. Cost: a handful of flops per light, none per vertex. */
void ltr_declared_range(const ltr_light_kind* kind, double min_distance, ltr_light_range* range);

/* The per-vertex t of one light, t = dot(V, -(L + N d)) unsaturated (the LUT's clamp saturates
   it per pixel), into t[0 .. vertex_count): V = the unit vector from the vertex to the eye
   (perspective) or -forward (orthographic), L = the unit vector from the vertex to a point
   light or -direction, N the vertex's world-space normal as sent, all in world space.
   Cost per vertex, counted as for ltr_light_range_of: perspective camera and point light about
   45 flops (7 divisions) and 2 square roots; a directional light about 30 (3) and 1 square root;
   an orthographic camera saves 14 flops and a square root; a material that normalises H adds 11
   flops (3 divisions) and a square root. */
void ltr_fill_t(const ltr_view* view, const ltr_light_kind* kind, const ltr_light* light,
                const ltr_material* material, const ltr_mesh* mesh, float* t);

/* The centre of the meshes' bounding box, world space: (lo + hi) x 0.5 over every vertex (what
   :view=object takes V and L at). Cost per vertex: 6 comparisons. */
void ltr_centre_of(const ltr_mesh meshes[], int mesh_count, double centre[3]);

/* A degree-2 rational (a0 + a1 x + a2 x^2) / (k0 + k1 x + k2 x^2): the XF's specular
   attenuation (GX_AF_SPEC, numerator GX_InitLightAttnA, denominator GX_InitLightAttnK). */
typedef struct {
  double a[3], k[3];
} ltr_rational;

/* lobe=xf-spec's fit (model/rational_fit.cpp, the same operations in the same order): the curve
   f(x) = (a + s lobe(clamp(c0 + sign x, 0, 1))) / (a + s), lobe(t) = t^p, over x in [0, x_max]
   at 513 samples, by up to 30 Sanathanan-Koerner iterations of the linearised least squares
   (k0 = 1), keeping the iterate of least max error whose denominator stays above 1e-3 (so the
   XF never divides by zero); x_max <= 0 gives the constant f(0).
   Cost: 513 pow() and about 65 000 flops per iteration (a 5x5 normal matrix summed over the
   samples, its max error and least denominator), up to 30 iterations: up to about 2 million flops
   a call. The setup calls it once per translucent light and frame; its result depends only on c0 =
   -V.L and s (d, a and p are the material's), so a game whose V.L and s change slowly can keep it
   and fit again only when they move. */
void ltr_fit_lobe(double c0, double sign, double x_max, double a, double s, double p,
                  ltr_rational* out);

/* Where a stored mesh's object stands (a module of a stored variant, :vtx= :nrm= :clr= :uv=):
   the mesh is kept in the object's own coordinates, and the scene's transform places it: its
   3x3 part A (linear[row][column]), its move t (world space) and A^-T (normal), in double as the
   scene gives them. */
typedef struct {
  double linear[3][3];
  double move[3];
  double normal[3][3];
} ltr_object_place;

/* The position and normal matrix GX_PNMTX0 takes for a stored object under `view`: R [A | t - eye]
   and R A^-T (R the view's rotation), in double, then float: the matrices ltrender's emulator
   loads for it (paths/gx/scene_vertices.cpp object_space_mesh, glm's products: each element
   summed left to right, R(r,0) A(0,c) + R(r,1) A(1,c) + R(r,2) A(2,c)). Cost: 63 flops. */
void ltr_object_matrices(const ltr_view* view, const ltr_object_place* place, float position[3][4],
                         float normal[3][3]);

/* One pass's per-frame state from the view, the lights and their ranges (one per light), and
   `centre` (ltr_centre_of of the meshes drawn with it; read only with :view=object). */
void ltr_pass_setup(const ltr_scene* scene, const ltr_material* material,
                    const ltr_pass_shape* shape, const ltr_view* view, const ltr_light* lights,
                    const ltr_light_range* ranges, const double centre[3], ltr_pass_state* out);

#ifdef __cplusplus
}
#endif

#endif
