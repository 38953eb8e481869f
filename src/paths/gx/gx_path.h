// The gx path: the Wii's fixed-function pipeline in its own arithmetic (gx.md), all on the CPU,
// as Dolphin's software renderer models it. Per draw, in the console's order: the XF lights and
// texgens every vertex (vertex_stage) and transforms its position (transform_unit), the setup
// unit rejects, culls and clips each triangle (setup_unit, clipper) and sets it up
// (rasteriser), and every pixel it covers runs the depth test, the texture unit, the TEV and the
// EFB blend (pixel_stage, efb). The programs are libogc calls: generated per material and pass
// (generator), or read from a file with `--program` (program/).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "paths/gx/gx_variant.h"
#include "paths/gx/scene_pass_programs.h"
#include "paths/path.h"

namespace lt::gx {

// The programs a scene draws with: generated for `variant`, or read from `program_file` when it
// is not empty; checked against what the emulator models (program_check.h).
// One draw of a frame: the objects of one material in one pass, with that pass's program.
struct MaterialDraw {
  int pass = 0;
  size_t material = 0;
  std::vector<size_t> objects;  // in scene order
};

struct ScenePrograms {
  ProgramFile file;
  std::map<std::string, std::string> notes;  // generated programs: per pass function
  std::vector<std::vector<PassProgram>> by_material;
  std::string source;  // where the programs come from, for messages ("generated", the file)
  // (C name, scene name) of every material some object uses, in scene order: the export's
  // comment maps each pass function back to the scene's (or glTF's) material.
  std::vector<std::pair<std::string, std::string>> material_names;
  // The variant the frame is drawn with: the given one, with a program file's declared vertex
  // storage and draw (program_storage.h). The emulator, the FIFO log and the exports read this.
  GxVariant variant;

  int passes() const;  // the most any used material needs
  // The frame's draws in the order the console receives them: pass by pass, every material that
  // has that pass and draws some object, its objects in scene order. The FIFO log encodes this
  // order (fifo/frame_recording.h) and the emulator draws it: the EFB's depth and blend make the
  // order part of the image.
  std::vector<MaterialDraw> draws(const Scene& scene) const;
  // The EFB pixel format the frame draws in: its first draw's (GX_Init's when nothing is drawn).
  // scene_programs_for refuses programs whose draws set different formats.
  PixelFormat pixel_format(const Scene& scene) const;
};
ScenePrograms scene_programs_for(const Scene& scene, const GxVariant& variant,
                                 const std::string& program_file);

}  // namespace lt::gx

namespace lt {
const PathInfo& gx_path_info();
}  // namespace lt
