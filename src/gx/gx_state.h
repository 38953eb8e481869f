// The whole GX state one pass draws with: what libogc's calls leave in the XF, TEV, texture and
// pixel-engine registers. It starts as GX_Init leaves it (each member's defaults cite
// libogc's __GX_InitGX [OGC gx.c]); a program file's calls change it (program/interpreter.h).
#pragma once

#include <array>
#include <optional>

#include "gx/efb.h"
#include "gx/tev.h"
#include "gx/texture_unit.h"
#include "gx/vertex_storage.h"
#include "gx/xf_lighting.h"
#include "gx/xf_texgen.h"

namespace lt::gx {

// Vertex attributes GX_VA_POS (9) .. GX_VA_TEX7 (20), as GX_SetVtxDesc declares them: GX_NONE 0,
// GX_DIRECT 1, GX_INDEX8 2 or GX_INDEX16 3 (the draw then sends indices: DeclaredStorage). GX_Init
// clears the descriptor [OGC gx.c __GX_InitGX: GX_ClearVtxDesc].
inline constexpr int kVaPos = 9, kVaNrm = 10, kVaClr0 = 11, kVaClr1 = 12, kVaTex0 = 13,
                     kVaTex7 = 20;
inline constexpr int kVertexAttributes = 21;
// GX_VA_NBT: the normal sent as normal, binormal and tangent; it shares GX_VA_NRM's descriptor
// field and array [OGC gx.c __SETVCDATTR "case GX_VA_NBT", GX_SetArray "if(attr==GX_VA_NBT)
// attr = GX_VA_NRM"], so the descriptor keeps it in kVaNrm's slot.
inline constexpr int kVaNbt = 25;
struct VertexDescriptor {
  std::array<u8, kVertexAttributes> type{};
  bool has(int attribute) const { return type[static_cast<size_t>(attribute)] != 0; }
  int count() const {
    int n = 0;
    for (u8 t : type) n += t != 0;
    return n;
  }
  bool operator==(const VertexDescriptor&) const = default;
};

// What the scene's vertex stream sends in each GX_VA_TEXn, by the component count the program
// gives it in GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_TEXn, ...): GX_TEX_S is the CPU's t of the pass's
// light (one float), GX_TEX_ST the mesh's UV (two floats, v = 0 at the map's bottom row). A
// program that sets no format for GX_VA_TEXn gets t in GX_VA_TEX0 (gx.md §1's default, what
// programs without a map always had) and the UV in GX_VA_TEX1..7. The format is not part of the
// descriptor: GX_ClearVtxDesc leaves it, as it leaves the hardware's VAT.
struct TexCoordFormats {
  enum Kind : u8 { Unset = 0, S = 1, ST = 2 };
  std::array<u8, kMaxTexGens> kind{};
  bool is_uv(int n) const {
    const u8 k = kind[static_cast<size_t>(n)];
    return k == ST || (k == Unset && n >= 1);
  }
  bool operator==(const TexCoordFormats&) const = default;
};

// GX_SetZMode(enable, func, update) [OGC gx.h L2810]. GX_Init: GX_ENABLE, GX_LEQUAL, GX_TRUE.
struct ZMode {
  bool enable = true;
  u8 func = 3;
  bool update = true;
  bool operator==(const ZMode&) const = default;
};

// GX_SetCullMode(mode) in libogc's values [OGC gx.h L649-652]: GX_CULL_NONE 0, GX_CULL_FRONT 1,
// GX_CULL_BACK 2, GX_CULL_ALL 3. GX_Init: GX_CULL_BACK [OGC gx.c __GX_InitGX L645]. Which faces
// are "back": libogc writes the mode swapped into genmode (cm2hw = {0, 2, 1, 3} [OGC gx.c
// L3931]), and the setup unit culls hardware mode 1 where the clip-space signed area is positive
// and mode 2 where it is not [DSW Clipper.cpp CullTest]. So GX_CULL_BACK removes the triangles
// that are counter-clockwise in clip space (y up) - the faces GL calls front - and GX_CULL_FRONT
// the ones GL calls back: a mesh wound for GL drawn under GX_Init's mode shows its inside.
inline constexpr u8 kCullNone = 0, kCullFront = 1, kCullBack = 2, kCullAll = 3;

// GX_SetPixelFmt(pix_fmt, z_fmt) [OGC gx.c GX_SetPixelFmt]: how the EFB stores a pixel (kPixel*,
// gx_types.h). GX_Init: GX_PF_RGB8_Z24, GX_ZC_LINEAR [OGC gx.c __GX_InitGX]. The colour formats are
// modelled as Dolphin's software renderer keeps them (efb.h); the z format only matters for a
// 16-bit depth buffer, which Dolphin's software renderer does not have (it keeps 24 bits in
// every format [DSW SWEfbInterface.cpp SetPixelDepth, "RGB565_Z16 is not supported correctly
// yet"]), so it is kept for the FIFO log and changes no pixel.
struct PixelFormat {
  u8 pixel = kPixelRgb8Z24;
  u8 z = 0;  // GX_ZC_LINEAR
  bool operator==(const PixelFormat&) const = default;
};

// What a program file declares of how the scene's mesh is stored and sent: each attribute's
// GX_SetVtxAttrFmt on the format the scene draws with as a storage key's attribute
// (gx/vertex_storage.h), and whether GX_SetVtxDesc sends the position GX_DIRECT or indexed. The
// gx path turns it into the variant's own storage, :vat= and :draw= (paths/gx/
// program_storage.h): one representation. Positions are (line, column) of the call, line 0 where
// nothing was declared.
//
// Which of the eight formats draws: a program has no GX_Begin (the scene's geometry is drawn for
// it), so the format whose GX_SetVtxAttrFmt declares GX_VA_POS is the one the draws use (a
// vertex without a position format draws nothing a port would want), GX_VTXFMT0 where none
// does. The other formats are kept apart in `by_format` as the CP keeps its eight VATs
// [DHW VertexLoaderManager.cpp RefreshLoader: g_main_cp_state.vtx_attr[vtx_attr_group]]: a
// declaration in a format that does not draw changes nothing read.
struct FormatDeclarations {
  using At = std::array<int, 2>;
  VertexStorage storage;
  std::array<At, 4> storage_at{};               // per kVertexStorageKeys entry (vtx, nrm, clr, uv)
  std::array<u8, kMaxTexGens> texcoord_kind{};  // TexCoordFormats::Kind of each GX_VA_TEXn
  std::array<At, 2> color_at{};                 // GX_VA_CLR0's and GX_VA_CLR1's declaration
  bool operator==(const FormatDeclarations&) const = default;
};
inline constexpr int kVertexFormats = 8;  // GX_VTXFMT0..7 [OGC gx.h GX_MAXVTXFMT]

struct DeclaredStorage {
  using At = std::array<int, 2>;
  // The drawing format's declarations (a copy of by_format[format]).
  VertexStorage storage;
  std::array<At, 4> storage_at{};  // per kVertexStorageKeys entry (vtx, nrm, clr, uv)
  int format = 0;                  // GX_VTXFMTn the scene draws with
  At format_at{};                  // the GX_SetVtxAttrFmt of GX_VA_POS that picked it
  std::array<FormatDeclarations, kVertexFormats> by_format{};
  bool indexed = false;  // GX_VA_POS is GX_INDEX8 or GX_INDEX16
  // Each attribute's GX_SetVtxDesc in force, by array number (kArrayPosition: GX_VA_POS's).
  std::array<At, kVertexArrays> input_at{};
  // GX_SetArray(attr, array, stride): each array's stride (0: not set) and where; the bytes are
  // the scene's mesh stored as declared, so only the stride is the program's to say.
  std::array<int, kVertexArrays> array_stride{};
  std::array<At, kVertexArrays> array_at{};
  bool operator==(const DeclaredStorage&) const = default;
};

struct GxState {
  XfLightingState lighting;
  XfTexGenState texgen;
  TevState tev;
  // GX_LoadTexObj: what each texture map holds; empty where nothing was loaded.
  std::array<std::optional<TextureObject>, kMaxTexMaps> textures;
  AlphaCompare alpha_compare;
  BlendMode blend;
  ZMode z;
  VertexDescriptor vertex;
  TexCoordFormats texcoord_formats;
  DeclaredStorage declared;
  u8 cull_mode = kCullBack;
  int cull_mode_line = 0;  // the program's line of the GX_SetCullMode in force; 0: GX_Init's
  PixelFormat pixel_format;
  // GX_SetDither(enable): GX_Init enables it [OGC gx.c __GX_InitGX]; it acts on RGBA6_Z24 only
  // (efb.h).
  bool dither = true;

  GxState();  // GX_Init's state
};

// The setup unit's size of each texture coordinate (SU_SSIZE / SU_TSIZE, BP 0x30 + 2n): s and t
// are multiplied by it per vertex, before rasterisation [DSW TransformUnit.cpp
// TransformTexCoord, "*= (scale_minus_1 + 1)"]. libogc writes it at the next draw from the
// texture each TEV stage fetches with that coordinate, stage by stage, so the last stage wins
// [OGC gx.c __GX_SetSUTexRegs L869-921]. A stage with GX_TEXCOORDNULL and a map reads texture
// coordinate 0 (GX_SetTevOrder programs 0 [OGC gx.c GX_SetTevOrder]) and sets its size. A
// coordinate no stage fetches with keeps scale 0 here (its register is not written; nothing
// samples with it). `textures[m]` is what map m holds this pass.
struct TexCoordScale {
  u32 s = 0, t = 0;           // texture width and height; 0: not written this pass
  u8 wrap_s = 0, wrap_t = 0;  // the same texture's wrap modes (the register's bit 16)
};
std::array<TexCoordScale, kMaxTexGens> texcoord_scales(
    const GxState& state, const std::array<const TextureObject*, kMaxTexMaps>& textures);

}  // namespace lt::gx
