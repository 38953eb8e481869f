// Names of files ltrender makes from user-given names (scenes, paths, variants): letters, digits,
// '-' and '_' are kept and anything else becomes '_', so "pow=lut:256:u8" is a file name on every
// file system and in every URL of the report page.
#pragma once

#include <cctype>
#include <string>

namespace lt {

inline std::string file_name_safe(const std::string& s) {
  std::string r = s;
  for (char& c : r) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  }
  return r;
}

}  // namespace lt
