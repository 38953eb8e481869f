#include "paths/gx/scene_pass_programs.h"

#include <cctype>
#include <map>
#include <set>

#include "core/error.h"

namespace lt::gx {

namespace {

std::string c_identifier(const std::string& name) {
  std::string s = name;
  for (char& c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return s;
}

}  // namespace

std::vector<std::string> material_c_names(const Scene& scene) {
  std::vector<std::string> out;
  std::set<std::string> taken;
  for (const Material& m : scene.materials) {
    const std::string base = c_identifier(m.name);
    std::string name = base;
    for (int n = 2; taken.count(name); ++n) name = base + "_" + std::to_string(n);
    taken.insert(name);
    out.push_back(name);
  }
  return out;
}

std::vector<std::vector<PassProgram>> scene_programs(const ProgramFile& file, const Scene& scene) {
  std::vector<PassProgram> all = file_programs(file);
  std::vector<std::vector<PassProgram>> out(scene.materials.size());
  std::vector<bool> used(scene.materials.size(), false);
  for (const SceneObject& o : scene.objects) used[static_cast<size_t>(o.material)] = true;
  const std::vector<std::string> c_names = material_c_names(scene);
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    if (file.functions.empty()) {
      out[m] = all;
      continue;
    }
    const std::string& id = c_names[m];
    std::map<int, PassProgram> passes;
    for (const PassProgram& p : all) {
      if (p.material == id) passes[p.pass] = p;
    }
    if (!used[m]) continue;
    if (passes.empty())
      throw InputError(file.file, "",
                       "no pass function for material " + scene.materials[m].name + " (expected " +
                           pass_function_name(id, 0) + ")");
    for (const auto& [pass, program] : passes) {
      if (pass != static_cast<int>(out[m].size()))
        throw InputError(file.file, "",
                         "material " + scene.materials[m].name + " has no pass " +
                             std::to_string(out[m].size()) + " (" +
                             pass_function_name(id, static_cast<int>(out[m].size())) +
                             ") before pass " + std::to_string(pass));
      out[m].push_back(program);
    }
  }
  return out;
}

}  // namespace lt::gx
