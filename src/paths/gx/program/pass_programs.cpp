#include "paths/gx/program/pass_programs.h"

#include <cctype>
#include <map>
#include <set>

#include "core/error.h"
#include "paths/gx/program/interpreter.h"

namespace lt::gx {

namespace {

constexpr const char* kPrefix = "ltrender_";

std::string where(const SourcePos& p) {
  return std::to_string(p.line) + ":" + std::to_string(p.column);
}

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

std::string pass_function_name(const std::string& c_name, int pass) {
  return kPrefix + c_name + "_pass" + std::to_string(pass);
}

std::vector<PassProgram> file_programs(const ProgramFile& file) {
  std::vector<PassProgram> out;
  if (file.functions.empty()) {
    out.push_back({"(whole file)", "", 0, run_program(file.file, {&file.top_level})});
    return out;
  }
  std::map<std::pair<std::string, int>, bool> seen;
  for (const Function& f : file.functions) {
    const std::string& n = f.name;
    const auto at = n.rfind("_pass");
    int pass = -1;
    if (n.rfind(kPrefix, 0) == 0 && at != std::string::npos && at > std::string(kPrefix).size() &&
        at + 5 < n.size() && n.find_first_not_of("0123456789", at + 5) == std::string::npos &&
        n.size() - at - 5 <= 2) {
      pass = std::stoi(n.substr(at + 5));
    }
    if (pass < 0)
      throw InputError(file.file, where(f.pos),
                       "function " + n + ": pass functions are named ltrender_<material>_pass<N>");
    PassProgram p;
    p.name = n;
    p.material = n.substr(std::string(kPrefix).size(), at - std::string(kPrefix).size());
    p.pass = pass;
    if (seen[{p.material, pass}])
      throw InputError(file.file, where(f.pos), "function " + n + " is defined twice");
    seen[{p.material, pass}] = true;
    p.state = run_program(file.file, {&file.top_level, &f.body});
    out.push_back(std::move(p));
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
