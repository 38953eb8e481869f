#include "mesh/formats/off_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>
#include <vector>

#include "mesh/normals.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

namespace {

struct OffHeader {
  bool texcoords = false, colors = false, normals = false, binary = false;
};

// A line without its comment: '#' to the end of the line, as Geomview's OFF allows.
std::string_view without_comment(std::string_view line) {
  return trim(line.substr(0, line.find('#')));
}

// `counts` receives the counts when the keyword line holds them ("OFF 8 6 0").
OffHeader parse_off_keyword(std::string_view first_line, const std::string& file,
                            std::vector<std::string_view>& counts) {
  OffHeader h;
  auto tokens = split_whitespace(without_comment(first_line));
  if (tokens.empty()) fail(file, 1, "not an OFF file (empty first line)");
  std::string_view k = tokens[0];
  if (k.substr(0, 2) == "ST") {
    h.texcoords = true;
    k.remove_prefix(2);
  }
  if (!k.empty() && k[0] == 'C') {
    h.colors = true;
    k.remove_prefix(1);
  }
  if (!k.empty() && k[0] == 'N') {
    h.normals = true;
    k.remove_prefix(1);
  }
  if (!k.empty() && (k[0] == '4' || k[0] == 'n')) {
    fail(file, 1, "OFF with 4D or n-dimensional vertices is not supported");
  }
  if (k != "OFF")
    fail(file, 1, "not an OFF file (first line is '" + std::string(trim(first_line)) + "')");
  if (tokens.size() == 2 && tokens[1] == "BINARY") {
    h.binary = true;
  } else if (tokens.size() == 4) {
    counts.assign(tokens.begin() + 1, tokens.end());
  } else if (tokens.size() > 1) {
    fail(file, 1, "expected the keyword alone, 'BINARY' or the three counts after it");
  }
  return h;
}

FileFacts check_off_binary(const std::string& data, const OffHeader& h, const std::string& file) {
  FileFacts facts;
  std::size_t pos = data.find('\n');
  pos = pos == std::string::npos ? data.size() : pos + 1;
  auto u32 = [&](const char* what) {
    if (data.size() - pos < 4)
      fail(file, 0, std::string("file ends inside ") + what + " (truncated?)");
    std::uint32_t v;
    std::memcpy(&v, data.data() + pos, 4);
    pos += 4;
    return v;
  };
  auto f32 = [&](const char* what) {
    const std::uint32_t bits = u32(what);
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
  };
  const std::uint32_t nv = u32("the counts"), nf = u32("the counts");
  u32("the counts");
  const std::size_t per_vertex =
      4 * (3 + (h.normals ? 3 : 0) + (h.colors ? 3 : 0) + (h.texcoords ? 2 : 0));
  if (nv > std::numeric_limits<std::int32_t>::max() || nv > (data.size() - pos) / per_vertex) {
    fail(file, 0,
         "header declares " + std::to_string(nv) +
             " vertices but the file is too short to hold them (truncated?)");
  }
  for (std::uint32_t i = 0; i < nv; ++i) {
    for (int k = 0; k < 3; ++k) {
      float c = f32("a vertex");
      if (!std::isfinite(c))
        fail(file, 0, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
    if (h.normals)
      for (int k = 0; k < 3; ++k) f32("a vertex");
    if (h.colors) {
      for (int k = 0; k < 3; ++k) {
        if (u32("a vertex") > 255)
          fail(file, 0, "vertex " + std::to_string(i) + ": colour component out of range 0..255");
      }
    }
    if (h.texcoords) {
      for (int k = 0; k < 2; ++k) {
        if (!std::isfinite(f32("a vertex")))
          fail(file, 0, "vertex " + std::to_string(i) + " has a non-finite texture coordinate");
      }
    }
  }
  if (nf > (data.size() - pos) / 16) {
    fail(file, 0,
         "header declares " + std::to_string(nf) +
             " faces but the file is too short to hold them (truncated?)");
  }
  for (std::uint32_t i = 0; i < nf; ++i) {
    const std::uint32_t n = u32("a face");
    if (n < 3)
      fail(file, 0,
           "face " + std::to_string(i) + " has " + plural(n, "vertex", "vertices") +
               " (a face needs at least 3)");
    if (n > (data.size() - pos) / 4)
      fail(file, 0, "file ends inside face " + std::to_string(i) + " (truncated?)");
    std::vector<std::uint32_t> idx(n);
    for (auto& x : idx) {
      x = u32("a face");
      if (x >= nv)
        fail(file, 0,
             "face " + std::to_string(i) + ": vertex index " + std::to_string(x) +
                 " is out of range (the file has " + plural(nv, "vertex", "vertices") + ")");
    }
    std::sort(idx.begin(), idx.end());
    if (std::adjacent_find(idx.begin(), idx.end()) != idx.end()) ++facts.repeated_faces;
  }
  facts.vertices = nv;
  return facts;
}

}  // namespace

// OpenMesh's getColorType: items are counted by single spaces, and a '.' in the first one means
// float colours.
FileFacts check_off(const std::string& data, const std::string& file) {
  const auto lines = split_lines(data);
  if (lines.empty()) fail(file, 0, "file is empty");
  std::vector<std::string_view> counts;
  const OffHeader h = parse_off_keyword(lines[0], file, counts);
  if (h.binary) return check_off_binary(data, h, file);

  FileFacts facts;
  // The file as OpenMesh can read it, built as the check goes: one value per token, single
  // spaces, no comments, the counts on their own line, a face's indices only. Handed on
  // (facts.rewritten) when the file differs from it in a way OpenMesh would misread.
  std::string copy = std::string(split_whitespace(without_comment(lines[0]))[0]) + "\n";
  bool rewrite = !counts.empty() || lines[0].find('#') != std::string_view::npos;
  auto put = [&](const std::vector<std::string_view>& tokens, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) copy.append(tokens[k]).append(k + 1 < n ? " " : "\n");
  };
  std::size_t li = 1;
  auto next_content_line = [&](std::string_view& line) {
    while (li < lines.size()) {
      const std::string_view raw = lines[li++];
      line = without_comment(raw);
      rewrite = rewrite || raw.find('#') != std::string_view::npos;
      if (!line.empty()) return true;
    }
    return false;
  };
  std::string_view line;
  if (counts.empty()) {
    if (!next_content_line(line)) fail(file, 0, "file ends before the vertex and face counts");
    counts = split_whitespace(line);
  }
  long long nv = 0, nf = 0, ne = 0;
  if (counts.size() != 3 || !parse_int(counts[0], nv) || !parse_int(counts[1], nf) ||
      !parse_int(counts[2], ne) || nv < 0 || nf < 0 || ne < 0) {
    fail(file, li, "expected '<vertices> <faces> <edges>'");
  }
  put(counts, 3);
  if (nv > std::numeric_limits<std::int32_t>::max() ||
      nf > std::numeric_limits<std::int32_t>::max() ||
      static_cast<std::size_t>(nv + nf) > lines.size()) {
    fail(file, li,
         "counts (" + std::to_string(nv) + " vertices, " + std::to_string(nf) +
             " faces) exceed the lines in the file (truncated?)");
  }
  const std::size_t fixed = 3 + (h.normals ? 3 : 0);
  std::vector<glm::vec3> colors;
  std::size_t colored = 0;
  for (long long i = 0; i < nv; ++i) {
    if (!next_content_line(line)) {
      fail(file, 0,
           "file ends after " + std::to_string(i) + " of " + std::to_string(nv) +
               " vertices (truncated?)");
    }
    auto t = split_whitespace(line);
    put(t, t.size());
    if (t.size() < fixed)
      fail(file, li,
           "vertex " + std::to_string(i) + " needs " + std::to_string(fixed) + " numbers");
    for (std::size_t k = 0; k < fixed; ++k) {
      double v;
      if (!parse_double(t[k], v)) fail(file, li, quoted(t[k]) + " is not a number");
      if (!fits_openmesh_float(v)) {
        fail(file, li,
             "vertex " + std::to_string(i) +
                 (k < 3 ? " has a non-finite coordinate" : " has a non-finite normal") + " ('" +
                 std::string(t[k]) + "'; OpenMesh reads OFF numbers as float)");
      }
    }
    if (h.texcoords) {
      if (t.size() < fixed + 2) {
        fail(file, li, "vertex " + std::to_string(i) + " lacks texture coordinates");
      }
      // OpenMesh reads s, t after the colour, which is only there in COFF: the last two values.
      const std::size_t st = h.colors ? t.size() - 2 : fixed;
      for (std::size_t k = st; k < st + 2; ++k) {
        double v;
        if (!parse_double(t[k], v) || !fits_openmesh_float(v)) {
          fail(file, li,
               "vertex " + std::to_string(i) + " has a non-finite texture coordinate ('" +
                   std::string(t[k]) + "'; OpenMesh reads OFF numbers as float)");
        }
      }
    }
    if (!h.colors) continue;
    const std::size_t items = t.size() - fixed - (h.texcoords ? 2 : 0);
    glm::vec3 c(0.0f);
    if (items == 3 || items == 4) {
      // OpenMesh counts items by single spaces; anything else changes its reading.
      std::string_view rest = line.substr(static_cast<std::size_t>(t[fixed].data() - line.data()));
      if (h.texcoords)
        rest = rest.substr(0, static_cast<std::size_t>(t[t.size() - 2].data() - rest.data()));
      rest = trim(rest);
      std::size_t spaces = static_cast<std::size_t>(std::count(rest.begin(), rest.end(), ' '));
      rewrite = rewrite || spaces + 1 != items || rest.find('\t') != std::string_view::npos;
      const bool is_float = t[fixed].find('.') != std::string_view::npos;
      for (std::size_t k = 0; k < 3; ++k) {
        const auto tok = t[fixed + k];
        if (is_float) {
          double v;
          if (!parse_double(tok, v) || !fits_openmesh_float(v))
            fail(file, li, "colour '" + std::string(tok) + "' is not a finite number");
          c[static_cast<int>(k)] = static_cast<float>(v);
        } else {
          long long v;
          if (!parse_int(tok, v) || v < 0 || v > 255) {
            fail(file, li,
                 "colour '" + std::string(tok) +
                     "' is not an integer in 0..255 (write all components with a '.' for float "
                     "colours)");
          }
          c[static_cast<int>(k)] = static_cast<float>(v) / 255.0f;
        }
      }
      ++colored;
    } else if (items > 4) {
      fail(file, li, "vertex " + std::to_string(i) + " has too many values");
    }
    colors.push_back(c);
  }
  for (long long i = 0; i < nf; ++i) {
    if (!next_content_line(line)) {
      fail(file, 0,
           "file ends after " + std::to_string(i) + " of " + std::to_string(nf) +
               " faces (truncated?)");
    }
    auto t = split_whitespace(line);
    long long n = 0;
    if (!parse_int(t[0], n) || n < 0)
      fail(file, li,
           "face " + std::to_string(i) + ": '" + std::string(t[0]) + "' is not a vertex count");
    if (n < 3)
      fail(file, li,
           "face " + std::to_string(i) + " has " +
               plural(static_cast<std::size_t>(n), "vertex", "vertices") +
               " (a face needs at least 3)");
    if (t.size() < static_cast<std::size_t>(n) + 1)
      fail(file, li,
           "face " + std::to_string(i) + " lists fewer than " + std::to_string(n) + " vertices");
    // A face's colour (Geomview's OFF allows one after the indices): OpenMesh would read a plain
    // OFF's as the next face, so the copy it reads ends at the indices.
    put(t, static_cast<std::size_t>(n) + 1);
    if (t.size() > static_cast<std::size_t>(n) + 1) {
      ++facts.face_colours_dropped;
      rewrite = true;
    }
    std::vector<long long> idx;
    for (long long k = 1; k <= n; ++k) {
      long long x;
      if (!parse_int(t[static_cast<std::size_t>(k)], x))
        fail(file, li, quoted(t[static_cast<std::size_t>(k)]) + " is not a vertex index");
      if (x < 0 || x >= nv) {
        fail(file, li,
             "face " + std::to_string(i) + ": vertex index " + std::to_string(x) +
                 " is out of range (the file has " +
                 plural(static_cast<std::size_t>(nv), "vertex", "vertices") + ")");
      }
      idx.push_back(x);
    }
    std::sort(idx.begin(), idx.end());
    if (std::adjacent_find(idx.begin(), idx.end()) != idx.end()) ++facts.repeated_faces;
  }
  facts.vertices = static_cast<std::size_t>(nv);
  facts.take_parsed_colors(std::move(colors), colored);
  if (rewrite) facts.rewritten = std::move(copy);
  return facts;
}

}  // namespace lt::meshio
