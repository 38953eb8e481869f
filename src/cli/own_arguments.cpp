#include "cli/own_arguments.h"

#include <fstream>
#include <iterator>

namespace lt::cli {

std::vector<std::string> own_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);  // NUL-separated
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  std::string arg;
  for (char c : all) {
    if (c != '\0') {
      arg += c;
      continue;
    }
    args.push_back(arg);
    arg.clear();
  }
  if (!args.empty()) args.erase(args.begin());
  return args;
}

}  // namespace lt::cli
