#include "mesh/formats/stl_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "mesh/normals.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

void check_stl(const std::string& data, const std::string& file) {
  if (data.empty()) fail(file, 0, "file is empty");
  if (data.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, data.data() + 80, 4);
    if (data.size() == 84 + 50 * static_cast<std::size_t>(n)) {
      for (std::uint32_t t = 0; t < n; ++t) {
        float xyz[9];
        std::memcpy(xyz, data.data() + 84 + 50 * static_cast<std::size_t>(t) + 12, sizeof xyz);
        for (float c : xyz) {
          if (!std::isfinite(c))
            fail(file, 0, "triangle " + std::to_string(t) + " has a non-finite vertex coordinate");
        }
      }
      return;
    }
  }
  auto start = trim(std::string_view(data).substr(0, std::min<std::size_t>(data.size(), 80)));
  if (start.substr(0, 5) != "solid") {
    std::string what = "neither ASCII STL (no 'solid') nor binary STL";
    if (data.size() >= 84) {
      std::uint32_t n;
      std::memcpy(&n, data.data() + 80, 4);
      what += " (its header declares " + std::to_string(n) + " triangles, which need " +
              std::to_string(84 + 50 * static_cast<std::size_t>(n)) + " bytes; the file has " +
              std::to_string(data.size()) + ": truncated or corrupt?)";
    }
    fail(file, 0, what);
  }
  const auto lines = split_lines(data);
  for (std::size_t li = 0; li < lines.size(); ++li) {
    auto t = split_whitespace(lines[li]);
    if (t.empty() || t[0] != "vertex") continue;
    if (t.size() < 4) fail(file, li + 1, "vertex needs three numbers");
    for (int k = 1; k <= 3; ++k) {
      double v;
      if (!parse_double(t[static_cast<std::size_t>(k)], v) || !fits_openmesh_float(v)) {
        fail(file, li + 1, quoted(t[static_cast<std::size_t>(k)]) + " is not a finite number");
      }
    }
  }
}

}  // namespace lt::meshio
