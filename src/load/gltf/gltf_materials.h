// glTF materials (glTF 2.0 §3.9, KHR_materials_volume, KHR_materials_diffuse_transmission) as
// the term's Material; docs/scenes-and-gltf.md's glTF table gives each row and its reason.
#pragma once

#include "load/gltf/gltf_notes.h"
#include "load/gltf/gltf_textures.h"
#include "scene/scene.h"

namespace lt::gltf {

// The documented defaults of what glTF does not carry (extras.ltrender overrides them).
inline constexpr double kDefaultPower = 8;
inline constexpr double kDefaultDistortion = 0.2;

// Maps /materials/{index} but its baseColorTexture, described in `texture` (gltf_textures.h) to
// become the albedo map when it is loaded. Throws InputError naming the pointer for a texture that
// does not exist (gltf_textures.h), a value out of the scene's bounds, and an unknown key in
// extras.ltrender (a typo must not silently render something else).
GltfMaterial map_material(const Document& doc, int index, Notes& notes);

// glTF 2.0 §3.9.6: a primitive without a material gets the default material, white and opaque:
// plain diffuse with albedo 1 here.
Material default_material();

// T = attenuationColor ^ (thickness / attenuationDistance), per channel: the fraction of light
// that KHR_materials_volume's Beer-Lambert law lets through `thickness` of the medium (thin
// parts bright). An infinite distance (the extension's default) lets everything through.
glm::dvec3 volume_transmittance(const glm::dvec3& attenuation_color, double thickness,
                                double attenuation_distance);

}  // namespace lt::gltf
