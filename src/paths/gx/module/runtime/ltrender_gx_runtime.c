/* The per-frame maths of a GX module (ltrender_gx_runtime.h): the gx planner's choices
   (src/paths/gx/pass_planner.cpp) and the model's t (src/model/translucency.cpp), operation for
   operation in double. */
#include "ltrender_gx_runtime.h"

#include <math.h>

/* A directional light is a point light this far away against its direction, in eye space:
   libogc's own "large number" for lights at infinity [OGC gx.c L23-25, GX_InitSpecularDir],
   small enough that |v|^2 (1e36) stays finite in the XF's float. Being in eye space, it moves
   with the camera: this is why the setup runs every frame. */
static const double ltr_far_away = 1.0e18;
/* How far past the silhouette (N.V < 0) a vertex still counts as possibly seen. */
static const double ltr_back_facing = 0.2;
/* Point-light attenuation denominators are floored here (model/translucency.h). */
static const double ltr_min_denominator = 1e-6;

static double ltr_dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double ltr_max3(const double v[3]) {
  double m = v[0];
  if (m < v[1]) m = v[1];
  if (m < v[2]) m = v[2];
  return m;
}

/* v * (1 / sqrt(v.v)), as glm::normalize. */
static void ltr_normalize(const double v[3], double out[3]) {
  const double inv = 1.0 / sqrt(ltr_dot(v, v));
  int i;
  for (i = 0; i < 3; ++i) out[i] = v[i] * inv;
}

static void ltr_cross(const double x[3], const double y[3], double out[3]) {
  out[0] = x[1] * y[2] - y[1] * x[2];
  out[1] = x[2] * y[0] - y[2] * x[0];
  out[2] = x[0] * y[1] - y[0] * x[1];
}

static void ltr_widen(const float f[3], double out[3]) {
  int i;
  for (i = 0; i < 3; ++i) out[i] = f[i];
}

/* 0..1 to 0..255, rounded; NaN and below 0 give 0 (image/image.h to_unorm8). */
static unsigned char ltr_unorm8(double v) {
  if (!(v > 0.0)) return 0;
  if (v >= 1.0) return 255;
  return (unsigned char)(v * 255.0 + 0.5);
}

static void ltr_rgb8(const double c[3], unsigned char out[4]) {
  int i;
  for (i = 0; i < 3; ++i) out[i] = ltr_unorm8(c[i]);
  out[3] = 255;
}

/* The smallest of x1, x2, x4 that holds `magnitude`; 4 where even that is too small. */
static int ltr_scale_for(double magnitude) {
  int s;
  for (s = 1; s <= 4; s *= 2) {
    if (magnitude <= s * (1 + 1e-9)) return s;
  }
  return 4;
}

void ltr_view_of(const ltr_camera* camera, int orthographic, ltr_view* view) {
  double eye[3], target[3], up[3], d[3], f[3], s[3], u[3], cs[3];
  int i;
  ltr_widen(camera->eye, eye);
  ltr_widen(camera->target, target);
  ltr_widen(camera->up, up);
  for (i = 0; i < 3; ++i) d[i] = target[i] - eye[i];
  ltr_normalize(d, view->forward);
  /* glm::lookAt(0, forward, up): f is forward normalised once more. */
  ltr_normalize(view->forward, f);
  ltr_cross(f, up, cs);
  ltr_normalize(cs, s);
  ltr_cross(s, f, u);
  for (i = 0; i < 3; ++i) {
    view->eye[i] = eye[i];
    view->rotation[0][i] = s[i];
    view->rotation[1][i] = u[i];
    view->rotation[2][i] = -f[i];
  }
  view->orthographic = orthographic;
}

static void ltr_rotate(const ltr_view* view, const double v[3], double out[3]) {
  int r;
  for (r = 0; r < 3; ++r)
    out[r] =
        view->rotation[r][0] * v[0] + view->rotation[r][1] * v[1] + view->rotation[r][2] * v[2];
}

/* V at world point P: normalize(eye - P), or -forward (model::view_vector). */
static void ltr_view_vector(const ltr_view* view, const double P[3], double V[3]) {
  double rel[3], len = 0;
  int i;
  if (!view->orthographic) {
    for (i = 0; i < 3; ++i) rel[i] = P[i] - view->eye[i];
    len = sqrt(ltr_dot(rel, rel));
  }
  if (!(len > 0)) { /* orthographic, or a point at the eye (never rasterised: near > 0) */
    for (i = 0; i < 3; ++i) V[i] = -view->forward[i];
    return;
  }
  for (i = 0; i < 3; ++i) V[i] = -rel[i] / len;
}

/* L and the attenuation at world point P (model::sample_light). */
static double ltr_sample_light(const ltr_light_kind* kind, const ltr_light* light,
                               const double P[3], const double N[3], double L[3]) {
  double to_light[3], dist, den;
  int i;
  if (!kind->point) {
    for (i = 0; i < 3; ++i) L[i] = -(double)light->direction[i];
    return 1.0;
  }
  for (i = 0; i < 3; ++i) to_light[i] = (double)light->position[i] - P[i];
  dist = sqrt(ltr_dot(to_light, to_light));
  for (i = 0; i < 3; ++i) L[i] = dist > 0 ? to_light[i] / dist : N[i];
  den = kind->kc + kind->kl * dist + kind->kq * dist * dist;
  return 1.0 / (den < ltr_min_denominator ? ltr_min_denominator : den);
}

void ltr_light_range_of(const ltr_view* view, const ltr_light_kind* kind, const ltr_light* light,
                        const ltr_mesh* mesh, ltr_light_range* range) {
  int v;
  for (v = 0; v < mesh->vertex_count; ++v) {
    double P[3], N[3], V[3], L[3], att, nl, diffuse;
    ltr_widen(mesh->positions + 3 * v, P);
    ltr_widen(mesh->normals + 3 * v, N);
    ltr_view_vector(view, P, V);
    if (ltr_dot(N, V) < -ltr_back_facing) continue;
    att = ltr_sample_light(kind, light, P, N, L);
    if (range->max_attenuation < att) range->max_attenuation = att;
    nl = ltr_dot(N, L);
    diffuse = att * (nl < 0.0 ? 0.0 : nl);
    if (range->max_diffuse < diffuse) range->max_diffuse = diffuse;
  }
}

void ltr_declared_range(const ltr_light_kind* kind, double min_distance, ltr_light_range* range) {
  const double d = min_distance, den = kind->kc + kind->kl * d + kind->kq * d * d;
  range->max_attenuation =
      kind->point ? 1.0 / (den < ltr_min_denominator ? ltr_min_denominator : den) : 1.0;
  range->max_diffuse = range->max_attenuation;
}

void ltr_fill_t(const ltr_view* view, const ltr_light_kind* kind, const ltr_light* light,
                const ltr_material* material, const ltr_mesh* mesh, float* t) {
  const double d = material->distortion;
  int v, i;
  for (v = 0; v < mesh->vertex_count; ++v) {
    double P[3], N[3], V[3], L[3], H[3], minus_h[3];
    ltr_widen(mesh->positions + 3 * v, P);
    ltr_widen(mesh->normals + 3 * v, N);
    ltr_view_vector(view, P, V);
    ltr_sample_light(kind, light, P, N, L);
    for (i = 0; i < 3; ++i) H[i] = L[i] + N[i] * d;
    if (material->normalize_h) {
      const double len = sqrt(ltr_dot(H, H));
      for (i = 0; i < 3; ++i) H[i] = len > 0 ? H[i] / len : 0.0;
    }
    for (i = 0; i < 3; ++i) minus_h[i] = -H[i];
    t[v] = (float)ltr_dot(V, minus_h);
  }
}

/* The eye-space position the XF lights from: a point light's own, a directional light's far
   away against its direction. */
static void ltr_light_eye(const ltr_view* view, const ltr_light_kind* kind, const ltr_light* light,
                          float out[3]) {
  double w[3], e[3];
  int i;
  for (i = 0; i < 3; ++i)
    w[i] = kind->point ? (double)light->position[i] - view->eye[i]
                       : -(double)light->direction[i] * ltr_far_away;
  ltr_rotate(view, w, e);
  for (i = 0; i < 3; ++i) out[i] = (float)e[i];
}

/* A distance-attenuated light object: the colour normalised to 255 at its largest component,
   k divided by `gain`, so the XF computes gain x att x colour. */
static void ltr_distance_light(const ltr_view* view, const ltr_light_kind* kind,
                               const ltr_light* light, const double color[3], double gain,
                               ltr_light_object* out) {
  const double m = ltr_max3(color);
  const double kc = kind->point ? kind->kc : 1.0, kl = kind->point ? kind->kl : 0.0,
               kq = kind->point ? kind->kq : 0.0;
  double unit[3];
  int i;
  ltr_light_eye(view, kind, light, out->position);
  for (i = 0; i < 3; ++i) unit[i] = m > 0 ? color[i] / m : 0.0;
  ltr_rgb8(unit, out->color);
  if (!(m > 0 && gain > 0)) gain = 1.0;
  out->k[0] = (float)(kc / gain);
  out->k[1] = (float)(kl / gain);
  out->k[2] = (float)(kq / gain);
}

static void ltr_ambient(const ltr_scene* scene, int first, int scale, unsigned char out[4]) {
  double c[3];
  int i;
  for (i = 0; i < 3; ++i) c[i] = first ? scene->ambient_light[i] / (double)scale : 0.0;
  ltr_rgb8(c, out);
}

/* Lights [light, light + count) summed in one channel, one stage (pass_planner diffuse_pass). */
static void ltr_diffuse_pass(const ltr_scene* scene, const ltr_pass_shape* shape,
                             const ltr_view* view, const ltr_light* lights,
                             const ltr_light_range* ranges, ltr_pass_state* out) {
  const int first = shape->light == 0;
  double magnitude = first ? ltr_max3(scene->ambient_light) : 0.0;
  int l, sd;
  for (l = shape->light; l < shape->light + shape->light_count; ++l) {
    double color[3];
    ltr_widen(lights[l].color, color);
    magnitude += ranges[l].max_diffuse * ltr_max3(color);
  }
  sd = ltr_scale_for(magnitude);
  for (l = shape->light; l < shape->light + shape->light_count; ++l) {
    double color[3];
    ltr_widen(lights[l].color, color);
    ltr_distance_light(view, &scene->kinds[l], &lights[l], color, ltr_max3(color) / sd,
                       &out->light[l - shape->light]);
  }
  ltr_ambient(scene, first, sd, out->ambient[0]);
  out->diffuse_scale = sd;
  out->diffuse_saturates = magnitude > 4;
}

void ltr_centre_of(const ltr_mesh meshes[], int mesh_count, double centre[3]) {
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  int m, v, i;
  for (m = 0; m < mesh_count; ++m) {
    for (v = 0; v < meshes[m].vertex_count; ++v) {
      for (i = 0; i < 3; ++i) {
        const double p = meshes[m].positions[3 * v + i];
        if (p < lo[i]) lo[i] = p;
        if (hi[i] < p) hi[i] = p;
      }
    }
  }
  for (i = 0; i < 3; ++i) centre[i] = lo[0] > hi[0] ? 0.0 : (lo[i] + hi[i]) * 0.5;
}

/* ---- lobe=xf-spec: the lobe as a rational of x = N.u (model/rational_fit.cpp) ---- */

#define LTR_FIT_SAMPLES 513

static double ltr_rational_at(const ltr_rational* r, double x) {
  return (r->a[0] + r->a[1] * x + r->a[2] * x * x) / (r->k[0] + r->k[1] * x + r->k[2] * x * x);
}

/* The fit's sample i: x_max i / (samples - 1). */
static double ltr_fit_x(double x_max, int i) {
  return x_max * i / (LTR_FIT_SAMPLES - 1);
}

static double ltr_fit_max_error(const ltr_rational* r, double x_max, const double fs[]) {
  double e = 0;
  int i;
  for (i = 0; i < LTR_FIT_SAMPLES; ++i) {
    const double v = fabs(ltr_rational_at(r, ltr_fit_x(x_max, i)) - fs[i]);
    if (e < v) e = v;
  }
  return e;
}

static double ltr_fit_min_denominator(const ltr_rational* r, double x_max) {
  double m = 1e300;
  int i;
  for (i = 0; i < LTR_FIT_SAMPLES; ++i) {
    const double x = ltr_fit_x(x_max, i), q = r->k[0] + r->k[1] * x + r->k[2] * x * x;
    if (q < m) m = q;
  }
  return m;
}

/* m x = b for a 5x5 m (Gaussian elimination, partial pivoting; m is overwritten); 0 if
   singular. */
static int ltr_solve5(double m[5][5], double b[5]) {
  int c, r, k;
  for (c = 0; c < 5; ++c) {
    int p = c;
    for (r = c + 1; r < 5; ++r) {
      if (fabs(m[r][c]) > fabs(m[p][c])) p = r;
    }
    if (fabs(m[p][c]) < 1e-300) return 0;
    for (k = 0; k < 5; ++k) {
      const double t = m[p][k];
      m[p][k] = m[c][k];
      m[c][k] = t;
    }
    {
      const double t = b[p];
      b[p] = b[c];
      b[c] = t;
    }
    for (r = c + 1; r < 5; ++r) {
      const double f = m[r][c] / m[c][c];
      for (k = c; k < 5; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (c = 5; c-- > 0;) {
    for (k = c + 1; k < 5; ++k) b[c] -= m[c][k] * b[k];
    b[c] /= m[c][c];
  }
  return 1;
}

void ltr_fit_lobe(double c0, double sign, double x_max, double a, double s, double p,
                  ltr_rational* out) {
  double fs[LTR_FIT_SAMPLES], best_error;
  ltr_rational current = {{0, 0, 0}, {1, 0, 0}}, best = {{0, 0, 0}, {1, 0, 0}};
  int i, iter, r, c;
  for (i = 0; i < LTR_FIT_SAMPLES; ++i) {
    double t = c0 + sign * (x_max > 0 ? ltr_fit_x(x_max, i) : 0.0), lobe;
    t = t < 0.0 ? 0.0 : (1.0 < t ? 1.0 : t);
    lobe = p == 0 ? 1.0 : (t <= 0 ? 0.0 : pow(t, p)); /* 0^0 := 1: a flat lobe */
    fs[i] = (a + s * lobe) / (a + s);
    if (!(x_max > 0)) break;
  }
  best.a[0] = fs[0];
  if (!(x_max > 0)) {
    *out = best;
    return;
  }
  /* Unknowns (a0, a1, a2, k1, k2): residual P(x) - f(x) (1 + k1 x + k2 x^2), each sample weighted
     by 1 / Q_prev(x)^2 so the iteration converges to the true rational least squares. */
  best_error = ltr_fit_max_error(&best, x_max, fs);
  for (iter = 0; iter < 30; ++iter) {
    double m[5][5] = {{0}}, rhs[5] = {0}, e;
    ltr_rational next;
    for (i = 0; i < LTR_FIT_SAMPLES; ++i) {
      const double x = ltr_fit_x(x_max, i),
                   q = current.k[0] + current.k[1] * x + current.k[2] * x * x;
      const double w = 1.0 / (q * q);
      const double row[5] = {1, x, x * x, -fs[i] * x, -fs[i] * x * x};
      for (r = 0; r < 5; ++r) {
        for (c = 0; c < 5; ++c) m[r][c] += w * row[r] * row[c];
        rhs[r] += w * row[r] * fs[i];
      }
    }
    /* A tiny ridge keeps the system solvable for flat curves (k1 = k2 = 0 is then the answer). */
    for (r = 0; r < 5; ++r) m[r][r] += 1e-12 * (1 + m[r][r]);
    if (!ltr_solve5(m, rhs)) break;
    for (i = 0; i < 3; ++i) next.a[i] = rhs[i];
    next.k[0] = 1;
    next.k[1] = rhs[3];
    next.k[2] = rhs[4];
    if (ltr_fit_min_denominator(&next, x_max) < 1e-3) break;
    e = ltr_fit_max_error(&next, x_max, fs);
    if (e < best_error) {
      best = next;
      best_error = e;
    }
    current = next;
  }
  *out = best;
}

/* V and L held constant over the object (object_view.h): at the meshes' centre with
   :view=object, else the exact variants' -forward and -direction. Returns the light's distance
   attenuation there (1 but for :view=object and a point light). */
static double ltr_constant_view(const ltr_material* material, const ltr_view* view,
                                const ltr_light_kind* kind, const ltr_light* light,
                                const double centre[3], double V[3], double L[3]) {
  int i;
  if (material->view_object) {
    ltr_view_vector(view, centre, V);
    /* A point light at the centre lights it head-on from the eye's side (L = V). */
    return ltr_sample_light(kind, light, centre, V, L);
  }
  for (i = 0; i < 3; ++i) {
    V[i] = -view->forward[i];
    L[i] = -(double)light->direction[i];
  }
  return 1.0;
}

/* lobe=xf-spec's light (pass_planner_textures.cpp specular_light): x = max(0, N.u) with
   u = -+k in eye space, k = -d V (the sign that makes x >= 0 on front faces), so t = c0 + sign x
   with c0 = -V.L; the position far along V so the XF's N.l >= 0 test passes on front faces; the
   numerator scaled by the light's magnitude 1 / inv_gain (its attenuation at the centre
   included: the specular attenuation has no distance term). */
static void ltr_specular_light(const ltr_view* view, const ltr_material* material,
                               const ltr_light* light, const double V[3], const double L[3],
                               const double color[3], double inv_gain, ltr_light_object* out) {
  const double d = material->distortion, c0 = -ltr_dot(V, L), sign = d >= 0 ? -1.0 : 1.0;
  const double m = ltr_max3(color), g = m > 0 ? 1.0 / inv_gain : 0.0;
  double k_world[3], k_eye[3], v_eye[3], unit[3];
  ltr_rational r;
  int i;
  for (i = 0; i < 3; ++i) k_world[i] = -d * V[i];
  ltr_rotate(view, k_world, k_eye);
  ltr_rotate(view, V, v_eye);
  ltr_fit_lobe(c0, sign, fabs(d), material->ambient, light->translucency_scale, material->power,
               &r);
  for (i = 0; i < 3; ++i) {
    /* GX_InitLightDir stores its argument negated: pass -u so the slot holds u. */
    const double u = d >= 0 ? -k_eye[i] : k_eye[i];
    out->position[i] = (float)(v_eye[i] * ltr_far_away);
    unit[i] = m > 0 ? color[i] / m : 0.0;
    out->direction[i] = (float)-u;
    out->a[i] = (float)(r.a[i] * g);
    out->k[i] = (float)r.k[i];
  }
  ltr_rgb8(unit, out->color);
}

/* One light's pass (pass_planner choose and light_pass): slot 0 the translucency light, slot 1
   the diffuse light, the scales from the light's range. */
static void ltr_light_pass(const ltr_scene* scene, const ltr_material* material,
                           const ltr_pass_shape* shape, const ltr_view* view,
                           const ltr_light* lights, const ltr_light_range* ranges,
                           const double centre[3], ltr_pass_state* out) {
  const int l = shape->light;
  const ltr_light* light = &lights[l];
  const ltr_light_kind* kind = &scene->kinds[l];
  const double s = light->translucency_scale, a = material->ambient;
  double color[3], trans_color[3], s0, diffuse_mag, trans_mag, V[3], L[3], att;
  int i, sd, st, st_needed;
  ltr_widen(light->color, color);
  for (i = 0; i < 3; ++i) trans_color[i] = color[i] * material->albedo[i] * material->tint[i];
  s0 = ltr_max3(trans_color) * (a + s) * material->t_max;
  diffuse_mag =
      (l == 0 ? ltr_max3(scene->ambient_light) : 0.0) + ranges[l].max_diffuse * ltr_max3(color);
  sd = ltr_scale_for(diffuse_mag);
  /* t=texgen's and lobe=xf-spec's V and L; xf-spec's magnitude is the attenuation at the centre. */
  att = ltr_constant_view(material, view, kind, light, centre, V, L);
  trans_mag = (material->xf_spec ? att : ranges[l].max_attenuation) * s0;
  st_needed = ltr_scale_for(trans_mag);
  st = sd > st_needed ? sd : st_needed;
  if (shape->translucent && material->xf_spec)
    ltr_specular_light(view, material, light, V, L, trans_color, st / (s0 * att), &out->light[0]);
  else if (shape->translucent)
    ltr_distance_light(view, kind, light, trans_color, s0 / st, &out->light[0]);
  ltr_distance_light(view, kind, light, color, ltr_max3(color) / sd, &out->light[1]);
  ltr_ambient(scene, 0, 1, out->ambient[0]);
  ltr_ambient(scene, l == 0, sd, out->ambient[1]);
  if (shape->lut) {
    const unsigned char a8 = ltr_unorm8(a / (a + s));
    out->reg0[0] = out->reg0[1] = out->reg0[2] = a8;
    out->reg0[3] = 255;
  }
  if (shape->lut && material->t_from_normal) {
    /* t = c0 + k.N with V and L constant over the mesh: c0 = -V.L, k = -d V, folded with the
       LUT's texel-centre remap s = t (W-1)/W + 0.5/W into row 0 of the texture matrix
       (pass_planner_textures.cpp). Exact (an orthographic camera, a directional light):
       V = -forward, L = -direction. :view=object (object_view.h): V = the unit vector from the
       meshes' centre to the eye, L = from the centre to a point light or -direction; this is the
       per-frame texture matrix that spares the CPU its per-vertex t. */
    const double n = material->lut_size, scale = (n - 1) / n, offset = 0.5 / n;
    int r, c;
    for (r = 0; r < 3; ++r)
      for (c = 0; c < 4; ++c) out->lut_matrix[r][c] = 0.0f;
    for (c = 0; c < 3; ++c) out->lut_matrix[0][c] = (float)(-material->distortion * V[c] * scale);
    out->lut_matrix[0][3] = (float)(-ltr_dot(V, L) * scale + offset);
  }
  out->translucency_scale = st / sd;
  out->diffuse_scale = sd;
  out->translucency_saturates = trans_mag > 4;
  out->diffuse_saturates = diffuse_mag > 4;
}

void ltr_pass_setup(const ltr_scene* scene, const ltr_material* material,
                    const ltr_pass_shape* shape, const ltr_view* view, const ltr_light* lights,
                    const ltr_light_range* ranges, const double centre[3], ltr_pass_state* out) {
  if (shape->diffuse_only) {
    ltr_diffuse_pass(scene, shape, view, lights, ranges, out);
  } else {
    ltr_light_pass(scene, material, shape, view, lights, ranges, centre, out);
  }
}

void ltr_object_matrices(const ltr_view* view, const ltr_object_place* place, float position[3][4],
                         float normal[3][3]) {
  const double(*R)[3] = view->rotation;
  double rel[3];
  int r, c;
  for (c = 0; c < 3; ++c) rel[c] = place->move[c] - view->eye[c];
  for (r = 0; r < 3; ++r) {
    for (c = 0; c < 3; ++c) {
      position[r][c] = (float)(R[r][0] * place->linear[0][c] + R[r][1] * place->linear[1][c] +
                               R[r][2] * place->linear[2][c]);
      normal[r][c] = (float)(R[r][0] * place->normal[0][c] + R[r][1] * place->normal[1][c] +
                             R[r][2] * place->normal[2][c]);
    }
    position[r][3] = (float)(R[r][0] * rel[0] + R[r][1] * rel[1] + R[r][2] * rel[2]);
  }
}
