#include "report/sweep.h"

#include <algorithm>
#include <sstream>

#include "core/fixed.h"
#include "load/load_scene.h"
#include "render/camera_path.h"
#include "render/evaluate.h"
#include "render/session.h"

namespace lt {

std::vector<SweepRow> run_sweep(const SweepOptions& o) {
  const PathInfo& info = find_path(o.path);
  std::vector<SweepRow> rows;
  for (const std::filesystem::path& file : o.scenes) {
    if (o.progress) o.progress(file.string());
    Scene base = load_scene(file);
    if (o.width > 0 && o.height > 0) {
      base.width = o.width;
      base.height = o.height;
    }
    // The frames move the camera and the lights but keep their kinds and the projection, so
    // what the path refuses for the scene it refuses for every frame.
    std::vector<size_t> measured;
    const size_t first = rows.size();
    std::vector<std::string> names;
    for (const VariantInfo& v : info.variants) {
      if (!selected(info, v, o.variants)) continue;
      names.push_back(v.name);
      if (!o.light_range.empty()) names.push_back(v.name + ":light-range=" + o.light_range);
    }
    for (const std::string& name : names) {
      SweepRow r;
      r.scene = file.stem().string();
      r.variant = name;
      r.refused = info.refusal(base, name);
      if (r.refused.empty()) measured.push_back(rows.size());
      rows.push_back(r);
    }
    std::vector<double> covered(rows.size() - first, 0.0);
    for (int k = 0; k < o.frames; ++k) {
      const Scene s = scene_on_camera_path(base, k, o.frames);
      RenderSession session(s, s.width, s.height);
      const Image reference = render_reference(session);
      for (size_t i : measured) {
        SweepRow& r = rows[i];
        auto path = session.build(info, r.variant);
        path->frame();
        const ErrorStats e = compare_with_reference(*path, reference).covered;
        r.max_lsb = std::max(r.max_lsb, e.max_lsb);
        r.p99_lsb = std::max(r.p99_lsb, e.p99_lsb);
        r.mean_lsb += e.mean_lsb * static_cast<double>(e.pixels);
        covered[i - first] += static_cast<double>(e.pixels);
        ++r.frames;
      }
    }
    for (size_t i : measured) {
      const double n = covered[i - first];
      rows[i].mean_lsb = n > 0 ? rows[i].mean_lsb / n : 0.0;
    }
  }
  return rows;
}

std::string sweep_markdown(const std::vector<SweepRow>& rows) {
  std::ostringstream o;
  o << "| scene | variant | max | mean | p99 |\n|---|---|---:|---:|---:|\n";
  for (const SweepRow& r : rows) {
    o << "| " << r.scene << " | `" << r.variant << "` | ";
    if (!r.refused.empty()) {
      o << "refused | | |\n";
      continue;
    }
    o << fixed(r.max_lsb, 2) << " | " << fixed(r.mean_lsb, 2) << " | " << fixed(r.p99_lsb, 2)
      << " |\n";
  }
  return o.str();
}

}  // namespace lt
