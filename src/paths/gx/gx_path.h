// The gx path: the Wii's fixed-function pipeline in its own integer arithmetic (gx.md). Per pass:
// the XF lights and texgens every vertex on the CPU (vertex_stage), OSMesa interpolates its
// outputs (attribute_rasteriser), and every covered pixel runs the texture unit, the TEV and the
// EFB blend on the CPU (pixel_stage). The programs are libogc calls: generated per material and
// pass (generator), or read from a file with `--program` (program/).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "paths/gx/gx_variant.h"
#include "paths/gx/program/pass_programs.h"
#include "paths/path.h"

namespace lt::gx {

// The programs a scene draws with: generated for `variant`, or read from `program_file` when it
// is not empty; checked against what the emulator models (program_check.h).
struct ScenePrograms {
  ProgramFile file;
  std::map<std::string, std::string> notes;  // generated programs: per pass function
  std::vector<std::vector<PassProgram>> by_material;
  std::string source;  // where the programs come from, for messages ("generated", the file)
  // (C name, scene name) of every material some object uses, in scene order: the export's
  // comment maps each pass function back to the scene's (or glTF's) material.
  std::vector<std::pair<std::string, std::string>> material_names;

  int passes() const;  // the most any used material needs
};
ScenePrograms scene_programs_for(const Scene& scene, const GxVariant& variant,
                                 const std::string& program_file);

}  // namespace lt::gx

namespace lt {
const PathInfo& gx_path_info();
}  // namespace lt
