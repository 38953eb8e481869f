// A GX program file's passes given to a scene's materials (gx/program/pass_programs.h reads the
// file's passes; this names them by the scene's materials), for `render --program` and the
// exporters that write the pass functions back.
#pragma once

#include <string>
#include <vector>

#include "gx/program/pass_programs.h"
#include "scene/scene.h"

namespace lt::gx {

// The passes of every scene material (index = material): a plain file's one program for all,
// or the file's pass functions of that material, pass 0..N-1 with none missing. Throws
// InputError naming a material some object uses that the file has no pass for.
std::vector<std::vector<PassProgram>> scene_programs(const ProgramFile& file, const Scene& scene);

// The C identifier of every scene material (index = material), used both to write the pass
// functions and to read them back: the name with every character C does not allow in an
// identifier replaced by '_', and where that is already an earlier material's (e.g.
// "Material.20" and "Material_20"), suffixed _2, _3, ... until it is unique. Materials no object
// uses take part too, so a name does not depend on which objects a scene draws.
std::vector<std::string> material_c_names(const Scene& scene);

}  // namespace lt::gx
