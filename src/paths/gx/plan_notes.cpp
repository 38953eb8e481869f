// describe_pass: the plan as the note a porter reads above each pass function and in
// `info --source` / the export's header ("light 0, 3 stages, 1 texture (LUT 256 texels), scales:
// translucency x2, diffuse x1").
#include <sstream>

#include "paths/gx/generator.h"

namespace lt::gx {

std::string note_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

namespace {

// ", 1 texture (LUT 256 texels)", " + thickness map 64x64 GX_TF_I8, 4096 bytes": what the pass's
// texgens fetch, the LUT first.
std::string textures(const PassPlan& p) {
  const TexturePlan* lut = nullptr;
  const TexturePlan* map = nullptr;
  for (const TexGenPlan& g : p.texgens) {
    if (!g.texture) continue;
    (g.texture->role == TexturePlan::Role::Lut ? lut : map) = &*g.texture;
  }
  std::string s;
  if (lut) s += ", 1 texture (LUT " + std::to_string(lut->width) + " texels)";
  if (map)
    s += std::string(lut ? " + " : ", 1 texture (") + "thickness map " +
         std::to_string(map->width) + "x" + std::to_string(map->height) + " " + map->format.name() +
         ", " + std::to_string(map->bytes) + " bytes" + (lut ? "" : ")");
  return s;
}

}  // namespace

std::string describe_pass(const PassPlan& p) {
  const PassFigures& f = p.figures;
  if (f.diffuse_only) {
    std::string note = "diffuse only, 1 stage, scale x" + std::to_string(f.diffuse_scale);
    if (f.diffuse_saturates) note += "; diffuse over x4 saturates";
    return note;
  }
  const size_t stages = p.stages.size();
  std::ostringstream note;
  note << "light " << f.light << ", " << stages << (stages == 1 ? " stage" : " stages")
       << textures(p) << ", scales: translucency x" << f.translucency_scale << ", diffuse x"
       << f.diffuse_scale;
  if (f.fit_error) note << ", lobe fit max error " << note_number(*f.fit_error) << " of (a+s)";
  if (f.translucency_saturates) note << "; translucency over x4 saturates";
  if (f.diffuse_saturates) note << "; diffuse over x4 saturates";
  return note.str();
}

}  // namespace lt::gx
