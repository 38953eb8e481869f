// describe_pass: the plan as the note a porter reads above each pass function and in
// `info --source` / the export's header ("light 0, 3 stages, 1 texture (LUT 256 texels), scales:
// translucency x2, diffuse x1").
#include <sstream>
#include <vector>

#include "paths/gx/generator.h"

namespace lt::gx {

std::string note_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

namespace {

// ", 1 texture (LUT 256 texels)", " + thickness map 64x64 GX_TF_I8, 4096 bytes", " + albedo map
// 16x16 GX_TF_RGBA8, 1024 bytes": what the pass's texgens fetch, in texgen order (the LUT first).
std::string textures(const PassPlan& p) {
  std::vector<std::string> parts;
  for (const TexGenPlan& g : p.texgens) {
    if (!g.texture) continue;
    const TexturePlan& t = *g.texture;
    if (t.role == TexturePlan::Role::Lut) {
      parts.push_back("LUT " + std::to_string(t.width) + " texels");
      continue;
    }
    parts.push_back(std::string(t.role == TexturePlan::Role::AlbedoMap ? "albedo" : "thickness") +
                    " map " + std::to_string(t.width) + "x" + std::to_string(t.height) + " " +
                    t.format.name() + ", " + std::to_string(t.bytes) + " bytes");
  }
  if (parts.empty()) return "";
  std::string s = ", " + std::to_string(parts.size()) +
                  (parts.size() == 1 ? " texture (" : " textures (") + parts[0];
  for (size_t i = 1; i < parts.size(); ++i) s += " + " + parts[i];
  return s + ")";
}

}  // namespace

std::string describe_pass(const PassPlan& p) {
  const PassFigures& f = p.figures;
  if (f.diffuse_only) {
    const size_t n = p.stages.size();
    std::string note = "diffuse only, " + std::to_string(n) + (n == 1 ? " stage" : " stages") +
                       textures(p) + ", scale x" + std::to_string(f.diffuse_scale);
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
