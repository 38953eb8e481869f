// The module's textures as one TPL file (issue 47): every LUT, map and palette the passes load,
// embedded as the byte array `ltrender_textures_tpl` that the module opens once with libogc's
// TPL_OpenTPLFromMemory, and each pass taking its texture with TPL_GetTexture /
// TPL_GetTextureCI where the `--format c` program calls GX_InitTexObj / GX_InitTexObjCI over a
// raw array [OGC tpl.c L147-187, L210-309]. Embedded rather than a .tpl beside the module: a
// game links its TPLs into the executable (devkitPro's template turns data/*.tpl into a
// `<name>_tpl` array with bin2o and passes it to TPL_OpenTPLFromMemory), needs no file system
// (libfat) to draw, and the module stays one file to #include.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gx/program/program_file.h"
#include "gx/tpl_file.h"
#include "paths/gx/pass_plan.h"

namespace lt::gx {

inline constexpr const char* kModuleTplArray = "ltrender_textures_tpl";
inline constexpr const char* kModuleTplFile = "ltrender_tpl";

struct ModuleTextures {
  std::vector<TplTexture> textures;  // in TPL order
  std::vector<std::string> names;    // each texture's u8 array in the `--format c` program
  std::map<std::string, int> id;     // names[id] -> id
  std::vector<std::string> arrays;   // every u8 array the TPL replaces (texels and palettes)
};

// The distinct textures of every pass of every material, in plan order, with their bytes from
// the materials' arrays: the same bytes the `--format c` program holds.
ModuleTextures module_textures(const ScenePlan& plan);

// The pass function with its GX_InitTexObj / GX_InitTlutObj + GX_InitTexObjCI calls replaced by
// TPL_GetTexture / TPL_GetTextureCI on the module's TPL (GX_LoadTlut and GX_LoadTexObj stay).
Function take_textures_from_tpl(Function f, const ModuleTextures& t);

// The top-level statements without the arrays the TPL replaces, and with the TPL's array and
// its TPLFile declared (the array non-const: TPL_OpenTPLFromMemory turns its offsets into
// pointers in place [OGC tpl.c L171-179]).
std::vector<Statement> with_textures_in_tpl(const std::vector<Statement>& top_level,
                                            const ModuleTextures& t);

// `void ltrender_flush_textures(void)`, which a game calls once before the first draw: opens the
// TPL (once: TPL_OpenTPLFromMemory rewrites the array's offsets as pointers) and invalidates the
// texture cache. Each TPL_GetTexture flushes its texels from the CPU cache [OGC tpl.c L244].
std::string open_textures_function(const ModuleTextures& t);

}  // namespace lt::gx
