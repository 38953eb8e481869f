// How a port stores a mesh's vertices: the component type (and fractional bits) of positions,
// normals, colours and texture coordinates, written as a storage key
//
//   vtx=s16/8,nrm=s8,clr=rgb565,uv=u16/15
//
// One parser, one list of keys (kVertexStorageKeys); a key left out keeps the F32 stream ltrender
// sends by default (vtx=f32,nrm=f32,clr=rgba8,uv=f32). Values:
//   vtx, uv   f32 | u8/N | s8/N | u16/N | s16/N (N = 0..31 fractional bits)
//             | u8/auto ... s16/auto, or the type alone: the widest fraction that holds the
//               mesh's bounds (widest_fraction, vertex_quantiser.h)
//   nrm       f32 | s16 | s8 (exponents 14 and 6, fixed by the type; libogc takes no other
//             normal type [OGC gx.c __SETVCDFMT L2545-2555]), alone or followed by /nbt or
//             /nbt3: the normal sent as an NBT (normal, binormal, tangent: libogc's GX_VA_NBT
//             with GX_NRM_NBT or GX_NRM_NBT3 [OGC gx.c __SETVCDFMT L2549-2554]); nbt3 sends an
//             indexed NBT one index per vector (the same for direct input)
//   clr       rgba8 | rgbx8 | rgb8 | rgba6 | rgba4 | rgb565
// `uv` covers every texture coordinate the stream sends (the pass's t and the mesh's UVs); with
// auto, each gets the widest fraction its own bounds allow.
#pragma once

#include <string>
#include <string_view>

#include "gx/vertex_quantiser.h"

namespace lt::gx {

struct CoordinateStorage {
  ComponentType type = ComponentType::F32;
  int frac = 0;
  bool auto_frac = false;  // pick the widest fraction the mesh's bounds allow
  bool operator==(const CoordinateStorage&) const = default;
};

// How many vectors the normal sends: the normal alone (GX_NRM_XYZ), or an NBT (GX_NRM_NBT), or
// an NBT indexed one index per vector (GX_NRM_NBT3).
enum class NormalVectors : u8 { Normal, Nbt, Nbt3 };

struct VertexStorage {
  CoordinateStorage position;                            // vtx
  ComponentType normal = ComponentType::F32;             // nrm
  NormalVectors normal_vectors = NormalVectors::Normal;  // nrm's /nbt or /nbt3
  ColorType color = ColorType::Rgba8;                    // clr (both colours)
  CoordinateStorage texcoord;                            // uv
  bool operator==(const VertexStorage&) const = default;
  bool is_default() const { return *this == VertexStorage{}; }
};

inline constexpr std::string_view kVertexStorageKeys[] = {"vtx", "nrm", "clr", "uv"};

// Parses a storage key; an unknown key, a repeated one or a value the attribute cannot have
// throws InputError(origin, the key, what) (e.g. `nrm`: "u8 is not a normal type (f32, s16,
// s8)").
VertexStorage parse_vertex_storage(std::string_view key, const std::string& origin);
// One attribute of a storage key: sets `name`'s (one of kVertexStorageKeys) attribute of `s` from
// `value` ("s16/8", "rgb565"), or throws InputError as parse_vertex_storage does. The gx variant
// takes each attribute as an axis of its own (`:vtx=s16/8:nrm=s8`) through this, so the values
// have one parser.
void set_vertex_storage(VertexStorage& s, std::string_view name, std::string_view value,
                        const std::string& origin);
// The value of attribute `name` in `s`, as set_vertex_storage reads it ("s16/auto", "rgb565").
std::string vertex_storage_value(const VertexStorage& s, std::string_view name);
// The key that parses back to `storage`, every attribute named: "vtx=s16/8,nrm=s8,clr=rgb565,
// uv=f32" (auto as "s16/auto").
std::string vertex_storage_key(const VertexStorage& storage);

// The vertex attribute format that stores `data` as `storage` says: fixed fractions checked
// against the data's bounds, auto ones chosen from them. A value a format cannot hold throws
// InputError(origin, the key, what), naming the value and the widest fraction that would hold
// it (e.g. `vtx`: "s16/10 holds -32 .. 31.999; the mesh's positions reach 40.25 (s16/9 holds
// them)").
VertexAttributeFormat storage_format(const VertexStorage& storage, const VertexAttributeData& data,
                                     const std::string& origin);

}  // namespace lt::gx
