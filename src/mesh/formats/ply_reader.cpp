#include "mesh/formats/ply_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>

#include "mesh/formats/ply_types.h"
#include "mesh/normals.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

namespace {

// X..Z, NX..NZ, Red..Blue and U..V must stay consecutive: parse_ply indexes with them.
enum class PlyRole { Other, X, Y, Z, NX, NY, NZ, Red, Green, Blue, Alpha, U, V, VertexIndices };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  PlyRole role = PlyRole::Other;
  std::string type_name;  // as written in the header
  int extra = -1;         // index into RawMesh::extras for a vertex property we keep as it is
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, BinaryLittle, BinaryBig };

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  // first byte after end_header's line
  std::size_t body_line = 0;    // line number of the first body line (ascii)
  std::vector<std::string> warnings;
};

// A header line that is no PLY keyword (Blender writes "Created by Blender3D ..." without
// `comment`). Common readers take such lines as comments, so we do, and say so once per file.
class UnknownHeaderLines {
 public:
  void add(std::size_t line_no, std::string_view line) {
    if (count_++ > 0) return;
    first_line_ = line_no;
    // The warning is one line of text: non-printable bytes would break it.
    std::string_view shown = line.substr(0, 80);
    for (char c : shown) first_ += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    if (line.size() > shown.size()) first_ += "...";
  }
  void report(std::vector<std::string>& warnings) const {
    if (count_ == 0) return;
    const std::string where = "line " + std::to_string(first_line_) + " '" + first_ + "'";
    warnings.push_back(count_ == 1 ? "header " + where + " is not a PLY keyword: read as a comment"
                                   : std::to_string(count_) +
                                         " header lines are not PLY keywords (the first: " + where +
                                         "): read as comments");
  }

 private:
  std::size_t count_ = 0, first_line_ = 0;
  std::string first_;
};

PlyHeader parse_ply_header(const std::string& data, const std::string& file) {
  PlyHeader h;
  std::size_t pos = 0, line_no = 0;
  bool have_format = false, have_end = false;
  auto next_line = [&](std::string_view& line) {
    if (pos >= data.size()) return false;
    std::size_t end = data.find('\n', pos);
    if (end == std::string::npos) end = data.size();
    line = std::string_view(data.data() + pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = std::min(end + 1, data.size());
    ++line_no;
    return true;
  };
  UnknownHeaderLines unknown;
  std::string_view line;
  if (!next_line(line) || trim(line) != "ply") {
    fail(file, data.empty() ? 0 : 1,
         data.empty() ? "file is empty" : "not a PLY file (no 'ply' magic)");
  }
  while (next_line(line)) {
    auto tokens = split_whitespace(line);
    if (tokens.empty()) continue;
    const auto key = tokens[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      have_end = true;
      break;
    }
    if (key == "format") {
      if (tokens.size() < 2) fail(file, line_no, "format line needs a format name");
      if (tokens[1] == "ascii") {
        h.format = PlyFormat::Ascii;
      } else if (tokens[1] == "binary_little_endian") {
        h.format = PlyFormat::BinaryLittle;
      } else if (tokens[1] == "binary_big_endian") {
        h.format = PlyFormat::BinaryBig;
      } else {
        fail(file, line_no, "unknown PLY format '" + std::string(tokens[1]) + "'");
      }
      have_format = true;
    } else if (key == "element") {
      long long count = 0;
      if (tokens.size() != 3 || !parse_int(tokens[2], count) || count < 0) {
        fail(file, line_no, "element line must be 'element <name> <count>'");
      }
      // OpenMesh handles are int: more than 2^31 - 1 elements cannot be represented.
      if (count > std::numeric_limits<std::int32_t>::max()) {
        fail(file, line_no, "element count " + std::to_string(count) + " is too large");
      }
      h.elements.push_back({std::string(tokens[1]), static_cast<std::uint64_t>(count), {}});
    } else if (key == "property") {
      if (h.elements.empty()) fail(file, line_no, "property before any element");
      PlyProperty p;
      if (tokens.size() >= 2 && tokens[1] == "list") {
        if (tokens.size() != 5)
          fail(file, line_no, "list property must be 'property list <count type> <type> <name>'");
        auto ct = ply_type(tokens[2]);
        auto et = ply_type(tokens[3]);
        if (!ct || ply_is_float(*ct))
          fail(file, line_no,
               "list count type '" + std::string(tokens[2]) + "' is not an integer type");
        if (!et) fail(file, line_no, "unknown property type '" + std::string(tokens[3]) + "'");
        p.is_list = true;
        p.count_type = *ct;
        p.type = *et;
        p.type_name = std::string(tokens[3]);
        p.name = std::string(tokens[4]);
      } else {
        if (tokens.size() != 3) fail(file, line_no, "property must be 'property <type> <name>'");
        auto t = ply_type(tokens[1]);
        if (!t) fail(file, line_no, "unknown property type '" + std::string(tokens[1]) + "'");
        p.type = *t;
        p.type_name = std::string(tokens[1]);
        p.name = std::string(tokens[2]);
      }
      h.elements.back().properties.push_back(p);
    } else {
      unknown.add(line_no, trim(line));
    }
  }
  if (!have_end) fail(file, 0, "PLY header has no end_header line (file truncated?)");
  unknown.report(h.warnings);
  if (!have_format) fail(file, 0, "PLY header has no format line");
  h.body_offset = pos;
  h.body_line = line_no + 1;
  return h;
}

template <typename T>
double load_as_double(const unsigned char* bytes) {
  T v;
  std::memcpy(&v, bytes, sizeof v);
  return static_cast<double>(v);
}

// Reads values of the body one at a time, in either encoding.
class PlyBody {
 public:
  // Thrown when the data runs out, and for an ascii token that is not a number of its type.
  struct End {};
  struct BadToken {
    std::string token;
  };

  PlyBody(const std::string& data, const PlyHeader& h)
      : data_(data), pos_(h.body_offset), line_(h.body_line), format_(h.format) {}

  double read(PlyType type) {
    if (format_ == PlyFormat::Ascii) return read_ascii(type);
    return read_binary(type);
  }
  std::size_t line() const { return format_ == PlyFormat::Ascii ? token_line_ : 0; }
  std::size_t remaining() const { return data_.size() - pos_; }

 private:
  double read_ascii(PlyType type) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) {
      if (data_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= data_.size()) throw End{};
    std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    token_line_ = line_;
    std::string_view token(data_.data() + start, pos_ - start);
    if (ply_is_float(type)) {
      double v = 0;
      if (!parse_double(token, v)) throw BadToken{std::string(token)};
      return v;
    }
    long long v = 0;
    if (!parse_int(token, v)) throw BadToken{std::string(token)};
    return static_cast<double>(v);
  }

  double read_binary(PlyType type) {
    const std::size_t n = ply_size(type);
    if (remaining() < n) throw End{};
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    if (format_ == PlyFormat::BinaryBig) std::reverse(b, b + n);  // to native (little) order
    switch (type) {
      case PlyType::Int8:
        return load_as_double<std::int8_t>(b);
      case PlyType::UInt8:
        return load_as_double<std::uint8_t>(b);
      case PlyType::Int16:
        return load_as_double<std::int16_t>(b);
      case PlyType::UInt16:
        return load_as_double<std::uint16_t>(b);
      case PlyType::Int32:
        return load_as_double<std::int32_t>(b);
      case PlyType::UInt32:
        return load_as_double<std::uint32_t>(b);
      case PlyType::Float32:
        return load_as_double<float>(b);
      case PlyType::Float64:
        return load_as_double<double>(b);
    }
    return 0;
  }

  const std::string& data_;
  std::size_t pos_;
  std::size_t line_;
  std::size_t token_line_ = 0;
  PlyFormat format_;
};

// The names PLY writers give texture coordinates (Blender and meshlab: s/t or u/v; the Stanford
// and VCG tools: texture_u/texture_v). The first pair the vertex has both of, as float or double,
// is the mesh's UVs; anything else (an integer u, a lone s) stays an extra property.
std::pair<PlyProperty*, PlyProperty*> find_uv_pair(PlyElement& vertex) {
  static const std::pair<const char*, const char*> names[] = {
      {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}};
  auto scalar = [&](const char* name) -> PlyProperty* {
    for (auto& p : vertex.properties) {
      if (p.name == name && !p.is_list && ply_is_float(p.type)) return &p;
    }
    return nullptr;
  };
  for (const auto& [u, v] : names) {
    PlyProperty* pu = scalar(u);
    PlyProperty* pv = scalar(v);
    if (pu && pv) return {pu, pv};
  }
  return {nullptr, nullptr};
}

}  // namespace

RawMesh parse_ply(const std::string& data, const std::string& file) {
  PlyHeader h = parse_ply_header(data, file);
  RawMesh out;
  out.binary = h.format != PlyFormat::Ascii;
  out.warnings = h.warnings;

  // Find the vertex and face elements and give each property its role.
  PlyElement* vertex = nullptr;
  PlyElement* face = nullptr;
  for (auto& e : h.elements) {
    if (e.name == "vertex") {
      if (vertex) fail(file, 0, "PLY header has two vertex elements");
      vertex = &e;
    } else if (e.name == "face") {
      if (face) fail(file, 0, "PLY header has two face elements");
      if (!vertex) fail(file, 0, "the face element comes before the vertex element");
      face = &e;
    }
  }
  if (!vertex) fail(file, 0, "PLY file has no vertex element");
  bool has_xyz[3] = {false, false, false};
  bool has_normal = false, has_color = false;
  const auto [uv_u, uv_v] = find_uv_pair(*vertex);
  if (uv_u) {
    uv_u->role = PlyRole::U;
    uv_v->role = PlyRole::V;
  }
  for (auto& p : vertex->properties) {
    if (p.role == PlyRole::U || p.role == PlyRole::V) continue;
    static const std::map<std::string, PlyRole> roles = {
        {"x", PlyRole::X},         {"y", PlyRole::Y},
        {"z", PlyRole::Z},         {"nx", PlyRole::NX},
        {"ny", PlyRole::NY},       {"nz", PlyRole::NZ},
        {"red", PlyRole::Red},     {"diffuse_red", PlyRole::Red},
        {"green", PlyRole::Green}, {"diffuse_green", PlyRole::Green},
        {"blue", PlyRole::Blue},   {"diffuse_blue", PlyRole::Blue},
        {"alpha", PlyRole::Alpha}};
    auto it = roles.find(p.name);
    if (it == roles.end() && !p.is_list) {
      // Not ours to interpret (quality, id, ...): carried through to what bake writes.
      p.extra = static_cast<int>(out.extras.size());
      out.extras.push_back({p.name, p.type_name, {}});
    }
    if (it == roles.end() || p.is_list) continue;
    p.role = it->second;
    if (p.role == PlyRole::X || p.role == PlyRole::Y || p.role == PlyRole::Z) {
      has_xyz[static_cast<int>(p.role) - static_cast<int>(PlyRole::X)] = true;
    }
    if (p.role == PlyRole::NX || p.role == PlyRole::NY || p.role == PlyRole::NZ) has_normal = true;
    if (p.role == PlyRole::Red || p.role == PlyRole::Green || p.role == PlyRole::Blue) {
      has_color = true;
      // 8-bit colours mean v/255; wider integers have no agreed meaning in PLY.
      if (!ply_is_float(p.type) && p.type != PlyType::UInt8) {
        fail(file, 0, "colour property '" + p.name + "' must be uchar, float or double");
      }
      if (ply_is_float(p.type)) out.float_colors = true;
    }
  }
  if (!has_xyz[0] || !has_xyz[1] || !has_xyz[2]) {
    fail(file, 0, "vertex element needs x, y and z properties");
  }
  if (face) {
    bool found = false;
    for (auto& p : face->properties) {
      if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index") && !found) {
        if (ply_is_float(p.type)) fail(file, 0, "face vertex indices must be integers");
        p.role = PlyRole::VertexIndices;
        found = true;
      }
    }
    if (!found) fail(file, 0, "face element has no vertex_indices list");
  }

  // A count that the rest of the file cannot possibly hold is a truncated file or a corrupt
  // header; checking it first avoids reserving memory for billions of elements.
  std::size_t remaining = data.size() - h.body_offset;
  for (auto& e : h.elements) {
    std::size_t min_record = 0;
    for (auto& p : e.properties) {
      min_record += out.binary ? ply_size(p.is_list ? p.count_type : p.type) : 2;
    }
    if (min_record > 0 && e.count > remaining / min_record) {
      fail(file, 0,
           "header declares " + std::to_string(e.count) + " " + e.name +
               " elements but the file is too short to hold them (truncated?)");
    }
  }

  const std::size_t nv = vertex->count;
  out.positions.resize(nv);
  if (has_normal) out.normals.assign(nv, glm::dvec3(0.0));
  if (has_color) out.colors.assign(nv, glm::vec3(0.0f));
  if (uv_u) out.uvs.assign(nv, glm::dvec2(0.0));
  for (auto& extra : out.extras) extra.values.assign(nv, 0.0);

  PlyBody body(data, h);
  for (auto& e : h.elements) {
    // A record without properties is zero bytes: there is nothing to read whatever the count
    // claims, and looping over 2^31 - 1 empty records costs seconds each. Every other record
    // takes at least one byte (the check above), so the work is bounded by the file's size.
    if (e.properties.empty()) continue;
    const bool is_vertex = &e == vertex, is_face = &e == face;
    if (is_face) {
      out.face_offsets.reserve(e.count + 1);
      out.face_indices.reserve(3 * e.count);
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const PlyProperty* reading = nullptr;  // for the message of a token that is no number
      try {
        for (auto& p : e.properties) {
          reading = &p;
          if (p.is_list) {
            double count = body.read(p.count_type);
            if (count < 0)
              fail(file, body.line(), e.name + " " + std::to_string(i) + ": negative list length");
            auto n = static_cast<std::size_t>(count);
            if (p.role == PlyRole::VertexIndices) {
              if (n < 3) {
                fail(file, body.line(),
                     "face " + std::to_string(i) + " has " + plural(n, "vertex", "vertices") +
                         " (a face needs at least 3)");
              }
              for (std::size_t k = 0; k < n; ++k) {
                double index = body.read(p.type);
                if (index < 0 || index >= static_cast<double>(nv)) {
                  fail(file, body.line(),
                       "face " + std::to_string(i) + ": vertex index " +
                           std::to_string(static_cast<long long>(index)) +
                           " is out of range (the file has " + plural(nv, "vertex", "vertices") +
                           ")");
                }
                out.face_indices.push_back(static_cast<std::uint32_t>(index));
              }
              out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_indices.size()));
            } else {
              for (std::size_t k = 0; k < n; ++k) body.read(p.type);
            }
            continue;
          }
          double v = body.read(p.type);
          if (!is_vertex) continue;
          // Integer colours are 8-bit (checked above): v / 255, as OpenMesh's color_cast does.
          const float c =
              ply_is_float(p.type) ? static_cast<float>(v) : static_cast<float>(v) / 255.0f;
          const int role = static_cast<int>(p.role);
          if (p.extra >= 0) {
            // Kept as its declared type holds it, so the writer gives back what was read.
            out.extras[static_cast<std::size_t>(p.extra)].values[i] = ply_value_as(p.type, v);
          } else if (p.role >= PlyRole::X && p.role <= PlyRole::Z) {
            out.positions[i][role - static_cast<int>(PlyRole::X)] = v;
          } else if (p.role >= PlyRole::NX && p.role <= PlyRole::NZ) {
            out.normals[i][role - static_cast<int>(PlyRole::NX)] = v;
          } else if (p.role >= PlyRole::Red && p.role <= PlyRole::Blue) {
            out.colors[i][role - static_cast<int>(PlyRole::Red)] = c;
          } else if (p.role == PlyRole::U || p.role == PlyRole::V) {
            // As the declared type holds it: an ascii "0.1" of a float u is the float 0.1f.
            out.uvs[i][role - static_cast<int>(PlyRole::U)] = ply_value_as(p.type, v);
          }
        }
      } catch (const PlyBody::End&) {
        fail(file, 0,
             "file ends inside " + e.name + " " + std::to_string(i) + " of " +
                 std::to_string(e.count) + " (truncated?)");
      } catch (const PlyBody::BadToken& bad) {
        fail(file, body.line(),
             "'" + bad.token + "' in " + e.name + " " + std::to_string(i) +
                 " is not a number of the declared type (property " +
                 (reading->is_list ? "list " : "") + reading->name + ")");
      }
      if (is_vertex && !is_finite(out.positions[i])) {
        std::ostringstream what;
        what << "vertex " << i << " has a non-finite coordinate (" << out.positions[i].x << ", "
             << out.positions[i].y << ", " << out.positions[i].z << ")";
        fail(file, body.line(), what.str());
      }
      if (is_vertex && has_color) {
        const auto& c = out.colors[i];
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) {
          fail(file, body.line(), "vertex " + std::to_string(i) + " has a non-finite colour");
        }
      }
      if (is_vertex && uv_u && !is_finite(out.uvs[i])) {
        fail(file, body.line(),
             "vertex " + std::to_string(i) + " has a non-finite texture coordinate (" + uv_u->name +
                 ", " + uv_v->name + ")");
      }
    }
    // Elements after the faces carry nothing we use (OpenMesh stops there too).
    if (&e == (face ? face : vertex)) break;
  }
  return out;
}

}  // namespace lt::meshio
