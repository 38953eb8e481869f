// What `ltrender advise` prints and writes: a text summary per material, the whole search as
// JSON (docs/advise.md has the schema), and the picked programs as the target takes them (ARB
// text for arbfp, .comb files for combiners, `export` C for gx).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "advise/advise.h"
#include "scene/scene.h"

namespace lt::advise {

std::string to_text(const Advice& a);
nlohmann::ordered_json to_json(const Advice& a);

// The program files of every material's pick, or of its refinement's variant when the refined
// mesh holds the budget (none for a material without either), written into `dir` (which
// exists); returns their names relative to it.
std::vector<std::string> write_programs(const Advice& a, const Scene& scene,
                                        const std::filesystem::path& dir);

}  // namespace lt::advise
