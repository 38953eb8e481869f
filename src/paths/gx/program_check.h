// What a program must satisfy before the emulator runs it with the scene's vertex stream: every
// texgen reads an attribute the stream has (the mesh's UVs only where every mesh of the
// material has them), texture coordinates declared without a gap, every vertex-colour source
// exists, every fetched
// texture map holds a texture, and the rasteriser has room for its texgens. A program that
// fails gets one InputError naming the file and the pass function, never a silent fallback.
#pragma once

#include <string>

#include "gx/program/pass_programs.h"

namespace lt::gx {

// `has_lut_fallback`: GX_TEXMAP0 holds the material's LUT where the program loaded none
// (gx.md §1). `has_uvs`: every mesh the program draws has UVs (a GX_TEX_ST texcoord may be read).
void check_renderable(const PassProgram& program, const std::string& file, bool has_lut_fallback,
                      bool has_uvs);

}  // namespace lt::gx
