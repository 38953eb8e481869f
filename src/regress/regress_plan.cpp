#include "regress/regress_plan.h"

#include <optional>

#include "core/error.h"
#include "core/fs.h"
#include "render/session.h"

namespace lt {

namespace {

// A scene a path cannot take at all (gx: two materials with one C name, a thickness map over
// 1024 texels) is refused when the path is built: bad input like a bad scene. Every case's path
// is built once here, at 1x1 (enough to build programs, as `info` does), every shard's cases,
// so that the run stops before any golden is written. A variant that cannot be exact is a
// skipped case instead (expand_cases).
void check_every_path_builds(const RegressPlan& plan) {
  for (size_t s = 0; s < plan.scenes.size(); ++s) {
    std::optional<RenderSession> session;
    for (const RegressCase& c : plan.cases) {
      if (c.scene_index != s || !c.skip_reason.empty()) continue;
      if (!session) session.emplace(plan.scenes[s], 1, 1);
      (void)session->build(*c.path, c.variant);
    }
  }
}

}  // namespace

// A directory every output needs before any work: its parent must exist (as for every output
// of ltrender) or be the report directory that -o creates (`-o out --junit out/junit.xml`), and
// an output never names an input.
void check_output_file(const fs::path& file, const std::vector<fs::path>& inputs,
                       const fs::path& report_dir) {
  if (file.empty()) return;
  std::error_code ec;
  const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  const bool in_report_dir =
      !report_dir.empty() && dir.lexically_normal() == report_dir.lexically_normal();
  if (!in_report_dir && !fs::is_directory(dir, ec))
    throw InputError(file.string(), "", "its directory does not exist");
  ensure_not_an_input(file, inputs);
}

void make_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string(), "", "cannot create the directory: " + ec.message());
}

RegressPlan make_regress_plan(const RegressOptions& o) {
  RegressPlan plan;
  plan.scene_files = collect_scene_files(o.inputs);
  for (const fs::path& f : plan.scene_files) plan.scenes.push_back(load_scene(f, o.scene_options));
  const std::vector<PathRequest> requests = parse_path_list(o.paths);
  plan.cases = expand_cases(plan.scene_files, plan.scenes, requests);
  // Every render's size before the first one: a scene too large to render is bad input, found
  // before any golden is written.
  const bool resized = o.width > 0 || o.height > 0;
  for (const Scene& s : plan.scenes) {
    check_image_size(o.width > 0 ? o.width : s.width, o.height > 0 ? o.height : s.height,
                     resized ? "--width/--height" : s.file.string(), resized ? "" : "image");
  }
  std::vector<fs::path> inputs = plan.scene_files;
  for (const Scene& s : plan.scenes) {
    for (const SceneObject& obj : s.objects) inputs.push_back(obj.mesh_path);
  }
  check_output_file(o.junit_file, inputs, o.report_dir);
  check_output_file(o.json_file, inputs, o.report_dir);
  if (o.goldens.empty()) throw InputError("--goldens", "", "a folder of goldens is required");
  std::error_code ec;
  if (fs::exists(o.goldens, ec) && !fs::is_directory(o.goldens, ec))
    throw InputError(o.goldens.string(), "", "--goldens must be a folder");
  if (!o.golden_key.empty()) {
    const fs::path overrides = o.goldens / o.golden_key;
    if (fs::exists(overrides, ec) && !fs::is_directory(overrides, ec))
      throw InputError(
          overrides.string(), "",
          "the folder of the golden key's overrides is a file (--golden-key " + o.golden_key + ")");
  }
  // Without --update a missing folder is a wrong path, not a dozen missing goldens; --update
  // creates it (the first run of a new suite).
  if (!o.update && !fs::exists(o.goldens, ec))
    throw InputError(o.goldens.string(), "",
                     "no such folder of goldens (--update creates it and writes them)");
  check_every_path_builds(plan);
  return plan;
}

}  // namespace lt
