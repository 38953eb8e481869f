#include "mesh/formats/obj_check.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "mesh/normals.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

namespace {

// An OBJ index as a 0-based one: positive indices count from 1, negative ones back from the last
// element defined so far (OBJ spec; OpenMesh resolves them the same way).
long long zero_based(long long index, std::size_t defined_so_far) {
  return index < 0 ? static_cast<long long>(defined_so_far) + index : index - 1;
}

}  // namespace

FileFacts check_obj(const std::string& text, const std::string& file) {
  FileFacts facts;
  const auto lines = split_lines(text);
  // Pass 1: how many positions and normals (OpenMesh resolves positive indices against all of
  // them, so a face may name a vertex defined further down).
  std::size_t total_v = 0, total_vn = 0, total_vt = 0;
  for (auto raw : lines) {
    auto t = split_whitespace(trim(raw));
    if (t.empty()) continue;
    if (t[0] == "v") ++total_v;
    if (t[0] == "vn") ++total_vn;
    if (t[0] == "vt") ++total_vt;
  }
  std::vector<glm::vec3> colors;
  std::size_t colored = 0, seen_v = 0, seen_vn = 0, seen_vt = 0;
  // Whether the first face's corners name texture coordinates. A corner that disagrees leaves
  // its UV undefined in OpenMesh (nothing writes it), so the file's UVs are then dropped.
  int faces_have_vt = -1;
  facts.normal_given.assign(total_v, 0);
  for (std::size_t li = 0; li < lines.size(); ++li) {
    const std::size_t line_no = li + 1;
    auto line = trim(lines[li]);
    if (line.empty() || line[0] == '#') continue;
    auto t = split_whitespace(line);
    const auto key = t[0];
    if (key == "v" || key == "vn") {
      if (t.size() < 4) fail(file, line_no, std::string(key) + " needs three numbers");
      double xyz[3];
      for (int k = 0; k < 3; ++k) {
        if (!parse_double(t[k + 1], xyz[k])) {
          fail(file, line_no, quoted(t[k + 1]) + " is not a number");
        }
        if (!fits_openmesh_float(xyz[k])) {
          fail(file, line_no,
               (key == "v" ? "vertex " + std::to_string(seen_v) + " has a non-finite coordinate "
                           : "normal " + std::to_string(seen_vn) + " is not a finite number ") +
                   "('" + std::string(t[k + 1]) + "'; OpenMesh reads OBJ numbers as float)");
        }
      }
      if (key == "vn") {
        ++seen_vn;
        continue;
      }
      // OpenMesh reads "v x y z r g b" colours when three more numbers follow.
      double rgb[3];
      bool has_rgb = t.size() >= 7;
      for (int k = 0; has_rgb && k < 3; ++k) has_rgb = parse_double(t[k + 4], rgb[k]);
      if (has_rgb) {
        for (double c : rgb) {
          if (!fits_openmesh_float(c))
            fail(file, line_no, "vertex " + std::to_string(seen_v) + " has a non-finite colour");
        }
        colors.emplace_back(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]),
                            static_cast<float>(rgb[2]));
        ++colored;
      } else {
        colors.emplace_back(0.0f);
      }
      ++seen_v;
    } else if (key == "vt") {
      double uv[2];
      if (t.size() < 3 || !parse_double(t[1], uv[0]) || !parse_double(t[2], uv[1])) {
        fail(file, line_no, "vt needs two numbers");  // OpenMesh gives up on the whole file
      }
      for (int k = 0; k < 2; ++k) {
        if (!fits_openmesh_float(uv[k])) {
          fail(file, line_no,
               "texture coordinate " + std::to_string(seen_vt) + " is not a finite number ('" +
                   std::string(t[k + 1]) + "'; OpenMesh reads OBJ numbers as float)");
        }
      }
      ++seen_vt;
    } else if (key == "f") {
      if (t.size() < 4) fail(file, line_no, "a face needs at least 3 vertices");
      std::vector<long long> corners;
      for (std::size_t k = 1; k < t.size(); ++k) {
        const auto corner = t[k];
        // v, v/vt, v//vn or v/vt/vn
        std::array<std::string_view, 3> parts{};
        std::size_t start = 0, part = 0;
        for (std::size_t i = 0; i <= corner.size() && part < 3; ++i) {
          if (i == corner.size() || corner[i] == '/') {
            parts[part++] = corner.substr(start, i - start);
            start = i + 1;
          }
        }
        // One of the corner's indices, 0-based; `invalid` says what a token that is no index
        // lacks, `name` and `names` what it indexes (`seen` so far, `total` in the file).
        auto index = [&](std::string_view token, const char* invalid, const char* name,
                         const char* names, std::size_t seen, std::size_t total) {
          long long i = 0;
          if (!parse_int(token, i) || i == 0)
            fail(file, line_no, "face corner '" + std::string(corner) + "' " + invalid);
          const long long r = zero_based(i, seen);
          if (r < 0 || r >= static_cast<long long>(total)) {
            fail(file, line_no,
                 "face " + std::string(name) + " index " + std::to_string(i) +
                     " is out of range (the file has " + plural(total, name, names) + ")");
          }
          return r;
        };
        const long long vertex =
            index(parts[0], "has no valid vertex index", "vertex", "vertices", seen_v, total_v);
        corners.push_back(vertex);
        const int has_vt = parts[1].empty() ? 0 : 1;
        if (faces_have_vt < 0) faces_have_vt = has_vt;
        if (has_vt != faces_have_vt && facts.uv_mix_line == 0) facts.uv_mix_line = line_no;
        if (has_vt) {
          index(parts[1], "has an invalid texture coordinate index", "texture coordinate",
                "texture coordinates", seen_vt, total_vt);
        }
        if (!parts[2].empty()) {
          index(parts[2], "has an invalid normal index", "normal", "normals", seen_vn, total_vn);
          facts.normal_given[static_cast<std::size_t>(vertex)] = 1;
        }
      }
      auto sorted = corners;
      std::sort(sorted.begin(), sorted.end());
      sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
      if (sorted.size() != corners.size()) ++facts.repeated_faces;
    }
  }
  facts.vertices = total_v;
  facts.take_parsed_colors(std::move(colors), colored);
  return facts;
}

}  // namespace lt::meshio
