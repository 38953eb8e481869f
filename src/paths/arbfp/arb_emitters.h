// The blocks the arbfp path's vertex and fragment programs share: the declarations both make
// (guards, material, view, light vectors, light scales) and the code both run (the normal, the
// view vector, a point light's L, t per light, t^k by multiplication, lobe * s + a). Where the
// two program kinds must differ (no CMP and no _SAT in ARB_vertex_program), the emitter asks the
// block which kind it writes.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "arb/arb_ir.h"
#include "scene/scene.h"

namespace lt::arbfp {

// "{x, y, z, w}" of a vector and a w.
std::string vec4(const glm::dvec3& v, double w);

// Lights are packed four to a register: light i is component "xyzw"[i % 4] of group i / 4.
size_t group_count(size_t lights);
std::string component(size_t light);
// The write mask covering the lights of group g: "xyzw", or fewer for the last group.
std::string group_mask(size_t group, size_t lights);
// Light i's component of its group's register, to read and to write.
ir::Reg read_lane(const std::vector<ir::Reg>& groups, size_t light);
ir::Reg write_lane(const std::vector<ir::Reg>& groups, size_t light);

// PARAM guard: the model's hard-case conventions (src/model/translucency.h), by meaning. x, y
// and w are the same in both programs; z is the attenuation floor in the fragment program and
// 1, the upper bound of saturate, in the vertex program (which has no _SAT).
struct Guards {
  ir::Reg inv_normal_max;        // x: clamp of 1/|n| (RSQ(0) = +inf)
  ir::Reg normal_length_sq_min;  // y: below it the normal is "no normal" (N = 0)
  ir::Reg attenuation_min;       // z, fragment: the attenuation denominator's floor
  ir::Reg one;                   // z, vertex: saturate's upper bound
  ir::Reg inv_length_max;        // w: clamp of 1/|v| so normalize(0) = 0 * 1e30 = 0
};
Guards declare_guards(ir::Block& decls);

// PARAM material = (distortion d, power p, lt ambient a, 0).
struct MaterialParams {
  ir::Reg distortion, power, ambient, zero;
};
MaterialParams declare_material(ir::Block& decls, const Translucency& tr);

// PARAM V = -forward for an orthographic camera (every view ray is parallel).
ir::Reg declare_orthographic_view(ir::Block& decls, const Scene& scene);
// The lights a program shades, in lane order (light i is lane i % 4 of group i / 4), each with
// its index in the scene (for names and comments) and the eye its positions are relative to.
// The numbers a (pass's) scene's lights have in the whole scene; empty: 0, 1, ... (light_number).
using LightNumbers = std::vector<size_t>;
inline size_t light_number(const LightNumbers& numbers, size_t i) {
  return numbers.empty() ? i : numbers[i];
}

struct LightList {
  std::vector<Light> lights;
  std::vector<size_t> scene_index;
  glm::dvec3 eye{0};
  size_t size() const { return lights.size(); }
  const Light& operator[](size_t i) const { return lights[i]; }
  std::string name(size_t i) const { return "light" + std::to_string(scene_index[i]); }
};
// The scene's lights in the scene's order, named by `numbers` (a pass's lights keep their
// numbers in the scene, arb_passes.h; empty: 0, 1, ...).
LightList scene_lights(const Scene& scene, const LightNumbers& numbers = {});

// Light i's L (directional: PARAM lightI_L = -direction) or camera-relative position (point).
ir::Reg declare_light_vector(ir::Block& decls, const LightList& lights, size_t light);
// The light scales s of group g, packed like the lights (0 past the last light).
std::array<double, 4> light_scales(const LightList& lights, size_t group);
// PARAM scaleG: light_scales of group g.
ir::Reg declare_scale(ir::Block& decls, const LightList& lights, size_t group);

// The registers the per-light code of both programs reads and writes.
struct Shading {
  ir::Reg r;  // scratch
  ir::Reg N;  // unit normal, or 0 for no normal
  ir::Reg V;  // unit view vector (a temporary, or the orthographic PARAM)
  ir::Reg H;  // distorted light
  ir::Reg L;  // the current point light's direction
  ir::Reg P;  // camera-relative position (an attribute)
  Guards guard;
  MaterialParams material;
  // The zero-normal guard of emit_normal; false where no interpolated normal can vanish
  // (arb_guards.h).
  bool zero_normal_guard = true;
};

// N = n / |n|, or 0 when |n| < kMinNormalLength (without s.zero_normal_guard: n / |n|); r.xyz
// is scratch.
void emit_normal(ir::Block& code, const Shading& s, const ir::Reg& n);
// V = normalize(-P). A vertex program clamps 1/|P| so a vertex at the eye gets V = 0.
void emit_view_vector(ir::Block& code, const Shading& s);
// Light i's comment and its L: the directional light's PARAM, or for a point light s.L =
// (position - P) / dist, and L = N at distance 0 (CMP in a fragment program, a mask in a vertex
// program; the fragment program's CMP only with `distance_zero_guard`). A point light leaves
// 1/dist in r.x, which the fragment program's attenuation reads; scratch: r.x (and r.y in a
// vertex program).
ir::Reg emit_light_direction(ir::Block& code, const Shading& s, const LightList& lights,
                             size_t light, const ir::Reg& light_vector,
                             bool distance_zero_guard = true);
// H = L + N * d, normalised on request, and t = dot(V, -H) into `t` (one lane). A fragment
// program saturates t here; a vertex program saturates whole groups afterwards.
void emit_t(ir::Block& code, const Shading& s, const ir::Reg& L, bool normalize_h,
            const ir::Reg& t);
// t^k from tv[g] into lobe[g] for every group, by left-to-right binary exponentiation; with
// `addend`, t^k + addend[g] (the last MUL becomes a MAD, for free).
void emit_mul_chain(ir::Block& code, unsigned long k, const std::vector<ir::Reg>& tv,
                    const std::vector<ir::Reg>& lobe, size_t lights,
                    const std::vector<ir::Reg>& addend = {});
// dst = lobe * s + a (a MUL when a = 0).
void emit_scale_and_ambient(ir::Block& code, const ir::Reg& dst, const ir::Reg& lobe,
                            const ir::Reg& scale, const MaterialParams& m, bool has_ambient);

}  // namespace lt::arbfp
