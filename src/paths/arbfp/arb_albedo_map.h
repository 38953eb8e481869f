// An albedo map in the ARB programs (load/albedo_map.h): one TEX (2D, texture unit 2) at the
// mesh's UVs times the material's albedo, the colour the final MUL applies. Kept apart from the
// generator's light loop, like the thickness map (arb_thickness_map.h), whose UV varying it reads.
#pragma once

#include <glm/glm.hpp>

#include "arb/arb_ir.h"
#include "scene/scene.h"

namespace lt::arbfp {

// texture[2]: unit 0 is the lobe table's, unit 1 the thickness map's.
inline constexpr int kAlbedoMapUnit = 2;

// The map's UVs travel in result.texcoord[2] (arb_thickness_map.h's emit_map_uv), which a
// material with "thickness": "vertex" fills with its vertex thickness: such a material is refused
// (InputError naming the scene's key), as a port would have to find the program another
// interpolator. `scene_file` names the scene in the error.
void check_albedo_map_texcoord(const Material& material, const std::string& scene_file);

// Fragment program: TEX A, fragment.texcoord[2], texture[2], 2D, then MUL A.xyz by `albedo`.
// Emitted before any ALU instruction, it reads an input and is in the first texture
// indirection (ARB_fragment_program issue 24): it adds one TEX and one ALU, no indirection.
// Returns A (A.w is the texture's alpha, 1 for the GL_RGB* formats map_texture.h uploads).
ir::Reg emit_albedo_map(ir::Program& p, ir::Block& decls, ir::Block& code,
                        const glm::dvec3& albedo);

}  // namespace lt::arbfp
