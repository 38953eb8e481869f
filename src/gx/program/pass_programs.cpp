#include "gx/program/pass_programs.h"

#include <map>
#include <set>

#include "core/error.h"
#include "gx/program/interpreter.h"

namespace lt::gx {

namespace {

constexpr const char* kPrefix = "ltrender_";

std::string where(const SourcePos& p) {
  return std::to_string(p.line) + ":" + std::to_string(p.column);
}

}  // namespace

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

}  // namespace lt::gx
