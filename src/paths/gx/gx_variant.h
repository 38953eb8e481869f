// The gx path's variants as a typed key (Filament's Variant: named, orthogonal axes, one parser):
//   t=vertex      t per vertex on the CPU, sent as GX_VA_TEX0 (any light, any camera): default
//   t=texgen      t from the raw normal through a 2x4 texture matrix (directional lights and an
//                 orthographic camera only: where t is affine in the normal)
//   lobe=xf-spec  no texture: the lobe from the XF specular attenuation, fitted per material
// and for t=texgen and lobe=xf-spec `:view=object`: V and L taken once per object (object_view.h)
// instead of exactly, so t is affine in the normal under a perspective camera and point lights,
// e.g. `t=texgen:view=object` (an approximation: its error is the bench's to say).
// and for the LUT variants `:lut=N` (2..1024 texels, default 256), e.g. `t=vertex:lut=64`,
// and `:lut-format=FMT`, the power LUT's texture format (docs/textures.md "The LUT's format"):
//   i8 (default, GX_TF_I8), i4 (GX_TF_I4: 16 levels), ia4, ia8 (the intensity also in alpha, so
//   the TEV reads what I8 or I4 gives it); a lobe ramp in colour keeps GX_TF_RGBA8.
// Two axes pick the other side where the sources disagree on the hardware (gx-hardware.md §2.4,
// §2.5), so docs/porting-to-the-wii.md can say how far each choice moves the image:
//   :colors=round       interpolated channel colours rounded, as Dolphin's shader backends do
//                       (default: truncated, as its software rasteriser does)
//   :lights=round-each  each light's XF contribution rounded before the sum, as the shader
//                       backends do (default: summed in float and truncated once, the software
//                       renderer)
// One axis follows the console where dolphin-emu/hwtests show it differs from Dolphin's software
// renderer (gx-hardware.md §2.6):
//   :coverage=console   the rasteriser samples each pixel at 7/12 from vertices held exactly, as
//                       the hwtests measured (default :coverage=dolphin: 9/16 from vertices
//                       rounded to 1/16, Dolphin's software renderer); attributes, depth and
//                       clipping stay Dolphin's (rasteriser.h console_subpixels)
// One axis picks the texture format of the maps (thickness and albedo; docs/textures.md "A
// map's format"). A colour format applies to colour maps, a grey format to grey maps (r = g = b
// in every texel); the maps of the other kind keep their default, so one variant fits every
// scene and `:map=rgb565` means what it always meant:
//   :map=rgb565         colour maps GX_TF_RGB565, 16 bits a texel (default :map=rgba8,
//                       GX_TF_RGBA8, 32 bits: the map's 8 bits kept, as the vertex colours it
//                       replaces keep theirs)
//   :map=rgb5a3         colour maps GX_TF_RGB5A3 (opaque: RGB555), 16 bits a texel
//   :map=cmpr           colour maps GX_TF_CMPR, 4 bits a texel (gx/cmpr_encoder.h)
//   :map=ia8, :map=ia4, :map=i4   grey maps GX_TF_IA8 (16 bits), IA4 (8), I4 (4) (default
//                       :map=i8, GX_TF_I8, 8 bits)
//   :map=ci4, :map=ci8  every map colour-indexed, GX_TF_CI4 (4 bits, 16 entries) or CI8 (8
//                       bits, 256), the palette (gx/palette.h) a TLUT in GX_TL_IA8 for a grey
//                       map and GX_TL_RGB565 for a colour one (map_tlut_format). Not CI14X2:
//                       its 16,384 entries need 32 KiB of TLUT, and libogc's GX_Init makes no
//                       TLUT region over 1,024 entries (gx/tmem.h); at 16 bits a texel it is
//                       RGB565's size anyway
// Two axes mipmap the maps (thickness and albedo; docs/textures.md "Mipmaps"), each map's full
// chain made by gx/mip_chain.h's box filter and stored after level 0 as the console lays it:
//   :mip=lin            GX_LIN_MIP_LIN (trilinear), LOD range 0 .. the last level
//   :mip=near           GX_NEAR_MIP_NEAR (nearest texel of the nearest level)
//   :mip-bias=B         the LOD bias in levels, -4 <= B < 4 (GX_InitTexObjLOD's lodbias, stored
//                       in 1/32 level steps; default 0); only with :mip=
//   :mip-lod=diagonal   GX_InitTexObjLOD's edgelod GX_FALSE: each coordinate's step to the next
//                       pixel across plus the step down, not the larger of the two (default
//                       :mip-lod=edge, edgelod GX_TRUE; texture_lod.h quad_lod); only with :mip=
// and one the maps' wrap:
//   :wrap=repeat        the thickness maps GX_REPEAT both ways (default :wrap=clamp, GX_CLAMP as
//                       the reference's CLAMP_TO_EDGE; an albedo map keeps its sampler's wrap);
//                       the console's repeat masks the texel index, so the sides must be
//                       powers of two
// Mipmaps need power-of-two maps too (the console halves each level's size registers).
// One axis picks where a directional light's translucency base (light x albedo x tint x (a + s))
// is multiplied in (docs/advise.md, "What the gx error is made of"):
//   :base=tev           in the TEV, as a konst colour folded into the LUT stage, with COLOR0 the
//                       unlit thickness: no XF light, no 8-bit truncation of a channel normalised
//                       to its largest component (default :base=xf, the XF light's colour)
// One axis replaces a choice the data made with a bound the user declares (issue 26):
//   :light-range=D      every point light stays at least D (world units) from the vertices it
//                       lights, so the TEV scales come from the attenuation at D (a directional
//                       light: 1) instead of from a scan of the visible vertices; D = 0 holds
//                       for any scene (the attenuation at the light itself, 1 / kc). The scan
//                       is gone from the CPU's frame (the module's setup); the cost is in the
//                       image (docs/porting-to-the-wii.md).
// Four axes store the mesh as a port does (docs/porting-to-the-wii.md "Vertex storage"), one
// attribute each, with the values of a storage key (gx/vertex_storage.h, its one parser):
//   :vtx=s16/8  positions (f32 | u8, s8, u16, s16 with /N fractional bits or /auto),
//   :nrm=s8     normals (f32 | s16 | s8, each alone or as an NBT: s8/nbt, s8/nbt3),
//   :clr=rgb565 colours (rgba8 | rgbx8 | rgb8 | rgba6 | rgba4 | rgb565), :uv=u16/auto texture
//   coordinates (the pass's t and the mesh's UVs);
// e.g. `t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto`. Default f32 / rgba8: the F32
// direct stream. A stored mesh goes through the console's vertex loader (scene_vertices.h).
// One axis picks the vertex format (GX_VTXFMT0..7) the passes declare their storage in and draw
// with (docs/porting-to-the-wii.md "Vertex storage"):
//   :vat=N              N = 0..7 (default 0): the FIFO log writes VAT A/B/C of format N (CP
//                       0x70/0x80/0x90 + N) and each draw command carries N in its low three
//                       bits, which pick the VAT the CP reads the vertices with [DHW
//                       OpcodeDecoding.h detail::RunCommand: vat = cmdbyte & GX_VAT_MASK,
//                       0x07, for opcodes 0x80-0xBF] [DHW
//                       VertexLoaderManager.cpp RunVertices, RefreshLoader]; the module and
//                       `--format c` declare GX_SetVtxAttrFmt(GX_VTXFMTN, ...) and draw with it.
//                       The pixels do not move: the eight VATs are alike but for their number.
// One axis picks how the vertices are sent (docs/porting-to-the-wii.md "How the vertices are
// sent"; paths/gx/object_draw.h):
//   :draw=direct        every triangle's three vertices in the FIFO, GX_TRIANGLES (default)
//   :draw=indexed       the attributes as arrays in MEM1 (GX_SetArray), the FIFO sends each
//                       vertex's indices, GX_TRIANGLES in the mesh's order
//   :draw=strips        indexed, the mesh as one GX_TRIANGLESTRIP (meshoptimizer's vertex-cache
//                       order and stripify, joined by degenerate triangles: mesh/triangle_strips.h)
//   :draw=list          the strips recorded once in a display list, sent as GX_CallDispList
// One axis picks which image the path returns (xfb_copy.h):
//   :out=xfb            what the TV shows: the EFB copied to the XFB as YUYV 4:2:2 and decoded
//                       again, as Dolphin's software renderer dumps it (default :out=efb, the
//                       EFB itself)
#pragma once

#include <optional>
#include <string>

#include "gx/gx_types.h"
#include "gx/texture_format.h"
#include "gx/vertex_storage.h"
#include "scene/scene.h"

namespace lt::gx {

struct GxVariant {
  enum class Lobe { Lut, XfSpec };
  enum class TexCoord { Vertex, Texgen };
  enum class Output { Efb, Xfb };
  enum class Draw { Direct, Indexed, Strips, List };
  Lobe lobe = Lobe::Lut;
  TexCoord t = TexCoord::Vertex;
  int lut_size = 256;
  // :lut-format=: the grey LUT's format when it is not GX_TF_I8 (unset: I8; never I8, so equal
  // images compare equal); one of I4, IA4, IA8.
  std::optional<TexFormat> lut_format;
  bool round_colors = false;
  bool round_each_light = false;
  // The maps' format when it is not the default (unset: colour maps GX_TF_RGBA8, grey maps
  // GX_TF_I8); never RGBA8 or I8 (the parser keeps the default unset, so equal images compare
  // equal).
  std::optional<TexFormat> map_format;
  // :mip=, :mip-bias= and :mip-lod= (the maps' mip chains), :wrap= (their wrap mode).
  enum class Mip { Off, Near, Linear };
  Mip mip = Mip::Off;
  double mip_bias = 0;
  bool mip_diagonal = false;  // :mip-lod=diagonal
  bool map_repeat = false;
  Output out = Output::Efb;
  CoverageRule coverage = CoverageRule::Dolphin;
  // A directional light's translucency base as a TEV konst colour instead of an XF light.
  bool base_in_tev = false;
  // V and L constant per object, from its centre (object_view.h); default: exact (t=texgen and
  // lobe=xf-spec then need an orthographic camera and directional lights).
  bool view_object = false;
  // :light-range=D: the declared closest distance of a point light to a lit vertex; unset: the
  // visible vertices are scanned (pass_planner.cpp light_stats).
  std::optional<double> light_range;
  // :vtx=, :nrm=, :clr=, :uv=: how the port stores the mesh's vertices (gx/vertex_storage.h);
  // default F32 positions, normals and texture coordinates, RGBA8 colours, sent as ltrender
  // always has (scene_vertices.h).
  VertexStorage storage;
  // :draw=: how the vertices are sent (object_draw.h); default each vertex direct, GX_TRIANGLES.
  Draw draw = Draw::Direct;
  // :vat=N: the vertex format (GX_VTXFMTN) the passes declare and draw with.
  int vat = 0;

  bool operator==(const GxVariant&) const = default;
};

inline constexpr int kDefaultLutSize = 256;

// Throws InputError("--variant", text, ...) naming the valid axes and values.
GxVariant parse_gx_variant(const std::string& text);
// The canonical spelling ("t=vertex", "t=vertex:lut=64", "lobe=xf-spec").
std::string to_string(const GxVariant& v);

// The format a map of this kind (grey: r = g = b in every texel) is stored in under `v`.
TexFormat map_texture_format(const GxVariant& v, bool grey_map);
// The TLUT format of a colour-indexed map: GX_TL_IA8 for a grey map (its intensity in 8 bits),
// GX_TL_RGB565 for a colour one (the map has no alpha: RGB5A3's opaque RGB555 keeps a bit less).
TlutFormat map_tlut_format(bool grey_map);
// Whether `format` is one a grey map takes under :map= (I4, IA4, I8, IA8), else a colour map's.
bool is_grey_map_format(TexFormat format);

// Why the variant cannot be exact for this scene (empty when it can): t=texgen and lobe=xf-spec
// need t affine in the normal, so every light directional, an orthographic camera and H not
// normalised (gx-hardware.md §3.1), or with view=object only H not normalised; out=xfb needs an
// even width and height (xfb_copy.h).
std::string refusal(const Scene& scene, const GxVariant& v);

}  // namespace lt::gx
