// Generates the arbfp path's ARB vertex and fragment programs for one material of a scene, as
// instruction lists (arb_ir.h) and as the text GL loads. Pure CPU (no GL context), so
// `ltrender budget` and the tests can count the programs without rendering.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arb/arb_ir.h"
#include "model/power_lut.h"
#include "paths/arbfp/arb_emitters.h"
#include "paths/arbfp/arb_guards.h"
#include "paths/arbfp/arb_variant.h"
#include "scene/scene.h"

namespace lt::arbfp {

struct ArbPrograms {
  std::string vertex, fragment;  // ir::print of the programs below
  ir::Program vertex_program{ir::ProgramKind::Vertex};
  ir::Program fragment_program{ir::ProgramKind::Fragment};
  // The texture the fragment program samples as texture[0] for pow=lut; a lobe-ramp material's
  // program samples its ramp there instead (2D, arb_lobe.h), and has no LUT.
  std::optional<model::PowerLut> lut;
  std::vector<std::string> notes;  // what the variant did for this material (for `info`)
};

// The per-vertex variant passes light group g's lobe in texcoord[kVertexLobeTexcoord + g]; ps_2_0
// has 8 texcoords, so it takes at most 4 * (8 - kVertexLobeTexcoord) lights.
inline constexpr int kVertexLobeTexcoord = 3;
inline constexpr size_t kMaxVertexLobeLights = 4 * (8 - kVertexLobeTexcoord);

// Whether a translucency's lobe varies with t (and the programs compute t): a ramp, or a power
// other than 0 (t^0 = 1 everywhere, 0^0 := 1, is a constant).
inline bool lobe_varies(const Translucency& tr) {
  return tr.ramp != nullptr || tr.power != 0;
}

// `translucency_term = false` generates the same program without the translucency term (diffuse
// only), so the budget can report the term's own cost as the difference. The programs' names,
// comments and notes number the scene's lights by `numbers` (a pass's lights are some of a
// larger scene's, arb_passes.h; empty: 0, 1, ...).
ArbPrograms generate_arb(const Scene& scene, const Material& material, const PowVariant& variant,
                         bool translucency_term = true, const LightNumbers& numbers = {});

// The same with the material's surfaces scanned already (material_surfaces of `scene`'s objects,
// or of a scene with the same objects and other lights): for callers that build many programs.
ArbPrograms generate_arb(const Scene& scene, const Material& material, const PowVariant& variant,
                         const MaterialSurfaces& surfaces, bool translucency_term = true,
                         const LightNumbers& numbers = {});

}  // namespace lt::arbfp
