#include "judge/log_tail.h"

#include <deque>
#include <fstream>
#include <string>

namespace lt::judge {

std::string log_tail(const std::filesystem::path& file, int lines, std::size_t max_chars) {
  std::ifstream in(file, std::ios::binary);
  std::deque<std::string> last;
  std::string line;
  while (std::getline(in, line)) {
    // Control characters (Dolphin ends its output with a NUL) would print as nothing or worse.
    std::erase_if(line, [](char c) { return static_cast<unsigned char>(c) < 0x20 && c != '\t'; });
    const auto begin = line.find_first_not_of(" \t\r");
    if (begin == std::string::npos) continue;
    const auto end = line.find_last_not_of(" \t\r");
    last.push_back(line.substr(begin, end - begin + 1));
    if (static_cast<int>(last.size()) > lines) last.pop_front();
  }
  std::string out;
  for (const std::string& l : last) out += (out.empty() ? "" : " | ") + l;
  if (out.size() > max_chars) out = "..." + out.substr(out.size() - max_chars);
  return out;
}

}  // namespace lt::judge
