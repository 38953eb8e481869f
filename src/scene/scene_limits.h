// The bounds every scene obeys, whatever file it came from (a scene JSON, a glTF file): one
// list, read by scene.cpp and by the glTF importer (load/gltf/), so both refuse the same values.
#pragma once

#include <cstddef>
#include <string>

#include "scene/triangle_mesh.h"

namespace lt {

inline constexpr double kMaxImageSide = 16384;

// Magnitude limits. They keep every product of the equation finite in float, the precision of
// the GL paths (albedo * color * intensity * (lobe * scale + ambient) * attenuation * thickness
// * tint stays below 1e30 < FLT_MAX = 3.4e38), so no Inf or NaN can reach an image, and they are
// far beyond anything a scene means: HDR colours up to 1e4, coordinates up to 1e9 (the 1e6 hard
// case is inside), powers up to 1e6 (t^p underflows to 0 long before).
inline constexpr double kMaxColour =
    1e4;  // albedo, colour, intensity, scale, ambient, thickness, tint
inline constexpr double kMaxCoordinate = 1e9;  // positions, eye, target, translate
inline constexpr double kMaxPower = 1e6;
inline constexpr double kMaxDistortion = 1e3;
inline constexpr double kMaxAttenuation = 1e6;  // kc, kl, kq
inline constexpr double kMaxScaleFactor = 1e6;  // transform.scale, and 1 / it

// Count limits (docs/input-files.md): what a scene may ask for, far above what the targets
// draw, and low enough that no accepted scene stalls a command. The GL paths unroll the light
// loop, and llvmpipe's compile time grows with it (64 lights: ~6 s for glsl; 1,000: minutes);
// fixed-function GL and the Wii's XF light 8 at a time.
inline constexpr std::size_t kMaxLights = 64;
inline constexpr std::size_t kMaxMaterials = 256;
inline constexpr std::size_t kMaxObjects = 1024;
// Every vertex is uploaded (float) and shaded per path; 2^24 vertices is ~10 binary PLYs at the
// mesh size cap, and a GL index buffer of 2^24 entries per attribute stays addressable.
inline constexpr std::size_t kMaxSceneVertices = std::size_t{1} << 24;

// "N lights, more than the limit of 64": the one wording of a count over its limit.
std::string over_limit_message(std::size_t count, const char* noun, std::size_t limit);

// Vertex colours that are a material's thickness take the scalar's bounds (kMaxColour): a float
// colour of 3e38, or a negative one, would carry Inf or a negative lobe into every path. Checked
// where the colour becomes a number of the equation; a mesh's colours mean nothing before.
// Throws InputError(file, where, "vertex V of MESH has colour component ...").
void check_vertex_thickness(const TriangleMesh& mesh, const std::string& file,
                            const std::string& where, const std::string& mesh_name);

// A material with a thickness map needs the mesh's UVs: InputError(file, where, naming the
// material, the map, `mesh_name` and `why_no_uvs` when the reader dropped them) when the mesh
// has none. Nothing for other materials.
struct Material;
void check_uvs_for_material(const TriangleMesh& mesh, const Material& material,
                            const std::string& file, const std::string& where,
                            const std::string& mesh_name, const std::string& why_no_uvs = "");

}  // namespace lt
