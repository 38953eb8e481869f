#include <iostream>
#include <map>

#include "advise/advise.h"
#include "advise/advise_output.h"
#include "advise/advise_page.h"
#include "advise/refined_scene.h"
#include "cli/commands.h"
#include "cli/threads_option.h"
#include "core/error.h"
#include "core/fs.h"
#include "load/load_scene.h"

namespace lt::cli {

// `ltrender advise SCENE --target PROFILE --max-lsb E [--stat max|p99|mean] [--json FILE]
// [-o DIR] [--width W] [--height H] [--exhaustive]` (docs/advise.md): per material, the cheapest
// variant of the target's path within the error budget. Exit 0 when every material has one, 1
// naming the closest candidate of each material that has none, 2 on bad input.
Action add_advise(CLI::App& app) {
  auto o = std::make_shared<advise::AdviseOptions>();
  auto scene = std::make_shared<std::string>();
  auto stat = std::make_shared<std::string>("max");
  auto json = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>();
  auto* sub = app.add_subcommand(
      "advise", "The cheapest variant per material on a target within an error budget");
  sub->add_option("SCENE", *scene, "Scene file (JSON, .gltf or .glb)")->required();
  sub->add_option("--target", o->profile,
                  "A budget's profile: ps_2_0, ps_2_x, arbfp1-min, ... (arbfp), gl13-2units, "
                  "gl13-3units, gl-8units (combiners), wii-tev (gx)")
      ->required();
  // A string, checked here: CLI11's own range check would print its own message, not one line
  // naming the option.
  auto max_lsb = std::make_shared<std::string>();
  sub->add_option("--max-lsb", *max_lsb, "The error budget in 8-bit LSB (>= 0)")->required();
  sub->add_option("--stat", *stat, "Which error figure the budget holds: max (default), p99, mean");
  sub->add_option("--json", *json, "Write the whole search as JSON to FILE");
  sub->add_option("-o,--output", *out_dir,
                  "Directory for the picked programs and the report page (index.html)");
  sub->add_option("--width", o->width, "Render width (default 128)")->check(CLI::Range(1, 4096));
  sub->add_option("--height", o->height, "Render height (default: the scene's aspect)")
      ->check(CLI::Range(1, 4096));
  sub->add_option("--max-vertices", o->max_vertices,
                  "For a material without a pick: refine its meshes where per-vertex evaluation "
                  "errs most until the budget holds or it has this many vertices")
      ->check(CLI::Range(1, 10000000));
  sub->add_flag("--exhaustive", o->exhaustive, "Render every candidate of the grid (no pruning)");
  add_threads_option(sub);
  return [=]() -> int {
    static const std::map<std::string, advise::Stat> stats = {
        {"max", advise::Stat::Max}, {"p99", advise::Stat::P99}, {"mean", advise::Stat::Mean}};
    const auto s = stats.find(*stat);
    if (s == stats.end())
      throw InputError("--stat", *stat, "unknown figure (valid: max, p99, mean)");
    o->stat = s->second;
    std::size_t used = 0;
    try {
      o->max_lsb = std::stod(*max_lsb, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != max_lsb->size())
      throw InputError("--max-lsb", *max_lsb, "not a number");
    o->scene_file = *scene;
    if (!fs::exists(o->scene_file)) throw InputError(*scene, "", "no such scene file");
    if (!json->empty()) ensure_not_an_input(*json, {o->scene_file});
    if (!out_dir->empty()) ensure_not_an_input(*out_dir, {o->scene_file});
    const advise::Advice a = advise::run_advise(*o);
    std::cout << advise::to_text(a);
    if (!json->empty()) write_text_file(*json, advise::to_json(a).dump(2) + "\n");
    if (!out_dir->empty()) {
      const Scene loaded = load_scene(o->scene_file);
      std::vector<std::string> files;
      std::string no_scene;
      write_directory_atomically(*out_dir, [&](const fs::path& staging) {
        files = advise::write_programs(a, loaded, staging);
        advise::RefinedFiles refined = advise::write_refined_scene(a, staging, *out_dir);
        files.insert(files.end(), refined.written.begin(), refined.written.end());
        no_scene = refined.not_written;
        write_text_file(staging / "index.html", advise::advise_page(a));
      });
      for (const std::string& f : files)
        std::cout << "wrote " << (fs::path(*out_dir) / f).string() << "\n";
      std::cout << "wrote " << (fs::path(*out_dir) / "index.html").string() << "\n";
      if (!no_scene.empty()) std::cout << "no refined scene written: " << no_scene << "\n";
    }
    if (!a.every_material_has_pick()) {
      std::string closest;
      for (const advise::MaterialAdvice& m : a.materials) {
        if (m.within_budget()) continue;
        closest += (closest.empty() ? "" : "; ") + m.name + ": " +
                   (m.closest ? "closest " + a.candidates[*m.closest].candidate.variant + " at " +
                                    std::to_string(advise::stat_of(
                                        a.candidates[*m.closest].error[m.index], o->stat)) +
                                    " LSB"
                              : std::string("no candidate renders without a non-finite pixel"));
      }
      throw CheckFailed("advise: no candidate within " + *max_lsb + " LSB " + *stat + " (" +
                        closest + ")");
    }
    return 0;
  };
}

}  // namespace lt::cli
