// Helpers of the tests that write users' GX C program files (gx_map_program_test.cpp,
// gx_tpl_program_test.cpp, dolphin_map_format_test.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lt::test {

// A byte array as users' GX C declares one: `u8 NAME[N] ATTRIBUTE_ALIGN(32) = {...};\n`
// (libogc's macro: a texture or palette starts on a 32-byte boundary [OGC gx.h L4262]).
inline std::string c_byte_array(const std::string& name, const std::vector<std::uint8_t>& bytes) {
  std::string s = "u8 " + name + "[" + std::to_string(bytes.size()) + "] ATTRIBUTE_ALIGN(32) = {";
  for (size_t i = 0; i < bytes.size(); ++i) s += (i ? ", " : "") + std::to_string(bytes[i]);
  return s + "};\n";
}

}  // namespace lt::test
