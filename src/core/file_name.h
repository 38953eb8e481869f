// File names: those ltrender makes from user-given names, and the extension that picks a format.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace lt {

// Names of files ltrender makes from user-given names (scenes, paths, variants): letters, digits,
// '-' and '_' are kept and anything else becomes '_', so "pow=lut:256:u8" is a file name on every
// file system and in every URL of the report page.
inline std::string file_name_safe(const std::string& s) {
  std::string r = s;
  for (char& c : r) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  }
  return r;
}

// The extension in lower case (".PLY" is a PLY file).
inline std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace lt
