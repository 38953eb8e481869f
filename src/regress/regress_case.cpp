#include "regress/regress_case.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/file_name.h"
#include "core/fs.h"
#include "regress/regress_tolerance.h"

namespace lt {

std::string RegressCase::id() const {
  return scene + "/" + path->name + "/" + variant;
}

std::string RegressCase::golden_name() const {
  const std::string base = scene + "__" + path->name;
  return (default_variant ? base : base + "__" + file_name_safe(variant)) + ".png";
}

std::vector<fs::path> collect_scene_files(const std::vector<fs::path>& inputs) {
  std::vector<fs::path> files;
  for (const fs::path& input : inputs) {
    std::error_code ec;
    if (fs::is_directory(input, ec)) {
      std::vector<fs::path> found;
      for (const auto& e : fs::directory_iterator(input, ec)) {
        if (e.path().extension() == ".json") found.push_back(e.path());
      }
      if (ec) throw InputError(input.string(), "", "cannot list the folder: " + ec.message());
      if (found.empty()) throw InputError(input.string(), "", "a folder without scenes (*.json)");
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::exists(input, ec)) {
      files.push_back(input);  // load_scene says what is wrong with anything but a scene
    } else {
      throw InputError(input.string(), "", "no such scene file or folder");
    }
  }
  std::map<std::string, fs::path> by_name;
  for (const fs::path& f : files) {
    const auto [it, fresh] = by_name.emplace(f.stem().string(), f);
    if (!fresh) {
      throw InputError(f.string(), "",
                       "has the same name as " + it->second.string() +
                           " (goldens are named by the scene: SCENE__PATH.png)");
    }
  }
  return files;
}

namespace {

PathRequest parse_path_request(const std::string& entry) {
  const size_t colon = entry.find(':');  // variants hold colons (pow=lut:256:u8), paths do not
  const std::string name = entry.substr(0, colon);
  PathRequest r;
  try {
    r.path = &find_path(name);
    if (colon == std::string::npos) {
      r.variants = {r.path->variants.front().name};
    } else if (entry.substr(colon + 1) == "*") {
      for (const VariantInfo& v : r.path->variants) r.variants.push_back(v.name);
    } else {
      r.variants = {resolve_variant(*r.path, entry.substr(colon + 1))};
    }
  } catch (const InputError& e) {
    throw InputError("--paths", entry, e.what_only());
  }
  return r;
}

}  // namespace

std::vector<PathRequest> parse_path_list(const std::string& list) {
  std::vector<PathRequest> out;
  std::stringstream ss(list);
  for (std::string entry; std::getline(ss, entry, ',');) {
    if (!entry.empty()) out.push_back(parse_path_request(entry));
  }
  if (!out.empty()) return out;
  for (const PathInfo& p : all_paths()) {
    if (p.role != PathRole::Baseline) out.push_back({&p, {p.variants.front().name}});
  }
  return out;
}

std::vector<RegressCase> expand_cases(const std::vector<fs::path>& scene_files,
                                      const std::vector<Scene>& scenes,
                                      const std::vector<PathRequest>& requests) {
  std::vector<RegressCase> cases;
  std::map<std::string, std::string> golden_owner;  // golden name -> case id
  std::set<std::string> ids;
  for (size_t s = 0; s < scenes.size(); ++s) {
    for (const PathRequest& r : requests) {
      for (const std::string& variant : r.variants) {
        RegressCase c;
        c.scene = scene_files[s].stem().string();
        c.scene_index = s;
        c.path = r.path;
        c.variant = variant;
        c.default_variant = variant == r.path->variants.front().name;
        c.skip_reason = r.path->refusal(scenes[s], variant);
        c.tolerance = regress_tolerance(scenes[s], *r.path);
        // The same case asked twice (glsl and glsl:pow=exact) runs once.
        if (!ids.insert(c.id()).second) continue;
        const auto [it, fresh] = golden_owner.emplace(c.golden_name(), c.id());
        if (!fresh) {
          throw InputError(
              "--paths", variant,
              "its golden " + c.golden_name() + " would be the same file as " + it->second + "'s");
        }
        cases.push_back(std::move(c));
      }
    }
  }
  return cases;
}

}  // namespace lt
