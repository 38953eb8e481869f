// Mesh input and output. OpenMesh 9.0 is the mesh library, but its readers trust their input
// and lose precision: the PLY reader rounds positions to float, truncates float colours to 8 bits
// and loops forever on a truncated header; the OBJ reader writes outside its arrays on an
// out-of-range index; a corrupt OM file aborts or segfaults inside the library; and a text value
// a reader cannot parse silently shifts every value after it. So PLY has a reader of its own,
// OBJ, OFF and STL are checked before OpenMesh reads them, OM is read in a child process (one
// section per format below), and OpenMesh's log streams are captured so that the user sees our
// one-line error rather than its chatter.
#include "scene/mesh.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>
#include <string_view>
#include <thread>

#include "core/error.h"
#include "core/fs.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#endif

namespace lt {

namespace {

using OpenMesh::IO::Options;

// ---------------------------------------------------------------------------------------------
// Small helpers

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string read_bytes(const fs::path& path) {
  return read_input_file(path, InputKind::Mesh);
}

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Whole-token number parsing: "1.5x" is not a number (istream would read 1.5 and stop).
bool parse_double(std::string_view token, double& out) {
  if (token.empty() || token.size() > 256) return false;
  std::string s(token);
  char* end = nullptr;
  errno = 0;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

bool parse_int(std::string_view token, long long& out) {
  if (token.empty() || token.size() > 32) return false;
  std::string s(token);
  char* end = nullptr;
  errno = 0;
  out = std::strtoll(s.c_str(), &end, 10);
  return end == s.c_str() + s.size() && errno != ERANGE;
}

// OpenMesh's text readers read numbers with `istream >> float`: NaN, Inf and anything beyond
// float range put the stream into a failed state, after which every later value is garbage.
bool fits_openmesh_float(double v) {
  return std::isfinite(v) && std::fabs(v) <= static_cast<double>(std::numeric_limits<float>::max());
}

std::vector<std::string_view> split_whitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// Text split into lines, without '\n' and a trailing '\r' (line n of the file is lines[n - 1]).
std::vector<std::string_view> split_lines(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

glm::dvec3 to_glm(const OpenMesh::Vec3d& v) {
  return {v[0], v[1], v[2]};
}
OpenMesh::Vec3d to_om(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

bool is_finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Normalises without overflow or underflow (a normal of length 1e-200 still has a direction);
// returns zero for zero and non-finite input.
glm::dvec3 safe_normalize(glm::dvec3 v) {
  if (!is_finite(v)) return glm::dvec3(0.0);
  double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (!(m > 0.0)) return glm::dvec3(0.0);
  v /= m;
  return v / glm::length(v);
}

// ---------------------------------------------------------------------------------------------
// OpenMesh's log streams (omerr, omlog, omout) are process-wide and print to the terminal.
// While OpenMesh works for us they are re-routed into a buffer; the mutex serialises all our
// OpenMesh I/O because the streams (and the IOManager) are shared.

std::mutex& openmesh_io_mutex() {
  static std::mutex m;
  return m;
}

class OpenMeshLogCapture {
 public:
  OpenMeshLogCapture() : lock_(openmesh_io_mutex()) {
    detach(omerr(), std::cerr);
    detach(omlog(), std::clog);
    detach(omout(), std::cout);
    for (auto* s : {&omerr(), &omlog(), &omout()}) s->connect(buffer_);
  }
  ~OpenMeshLogCapture() {
    for (auto* s : {&omerr(), &omlog(), &omout()}) {
      // Flush first: a message without a final '\n' would otherwise surface on the terminal
      // later, once the terminal is connected again.
      s->flush();
      s->disconnect(buffer_);
    }
    for (auto& d : detached_) d.stream->connect(*d.target);
  }
  OpenMeshLogCapture(const OpenMeshLogCapture&) = delete;
  OpenMeshLogCapture& operator=(const OpenMeshLogCapture&) = delete;

  // The last non-empty line OpenMesh printed, for error messages.
  std::string last_line() {
    for (auto* s : {&omerr(), &omlog(), &omout()}) s->flush();
    // split_lines returns views into its argument: the text must outlive the loop (a
    // temporary from str() dies before the loop body runs, and the views would read freed
    // memory).
    const std::string text = buffer_.str();
    std::string last;
    for (auto line : split_lines(text)) {
      auto t = trim(line);
      if (!t.empty()) last = std::string(t);
    }
    return last;
  }

 private:
  struct Detached {
    OpenMesh::mostream* stream;
    std::ostream* target;
  };
  void detach(OpenMesh::mostream& stream, std::ostream& target) {
    if (stream.disconnect(target)) detached_.push_back({&stream, &target});
  }

  std::unique_lock<std::mutex> lock_;
  std::ostringstream buffer_;
  std::vector<Detached> detached_;
};

// What the attributes request: normals and colours. ColorFloat is not requested: it only
// changes OpenMesh's binary OFF reader, and there it would misread the usual integer colours.
Options requested_options() {
  return Options(Options::VertexNormal | Options::VertexColor);
}

void read_with_openmesh(PolyMesh& mesh, const std::string& file, Options& options,
                        OpenMeshLogCapture& capture) {
  bool ok = false;
  try {
    ok = OpenMesh::IO::read_mesh(mesh, file, options);
  } catch (const std::exception& e) {
    // e.g. std::bad_alloc from a reserve() sized by a corrupt count.
    throw InputError(file, "", std::string("OpenMesh could not read it: ") + e.what());
  }
  if (!ok) {
    const std::string why = capture.last_line();
    throw InputError(file, "",
                     "OpenMesh could not read it" + (why.empty() ? std::string() : ": " + why));
  }
}

// ---------------------------------------------------------------------------------------------
// What the format checks learn about a file, used once OpenMesh has read it.

struct FileFacts {
  std::size_t vertices = 0;        // vertex records in the file; 0 when the check cannot tell
  std::size_t repeated_faces = 0;  // faces naming a vertex twice (OpenMesh drops or shrinks them)
  std::vector<char> normal_given;  // per vertex: the file gave it a normal (OBJ: via a face)
  std::vector<glm::vec3> colors;   // exact colours when we parsed them ourselves
  bool has_colors = false;         // `colors` is valid for every vertex
  bool partial_colors = false;     // some vertices had colours and others not: dropped
  bool colors_checked = false;     // our pass decides about colours, not OpenMesh's options
};

[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& what) {
  throw InputError(file, line ? std::to_string(line) : "", what);
}

// =============================================================================================
// PLY: our own reader. OpenMesh 9.0's PLY reader rounds coordinates to float (a sphere near
// 1e6 collapses onto a 1/16 grid), truncates float colours to 8 bits (0.5 comes back as
// 127/255), loops forever on a header without end_header, and skips list properties other than
// vertex_indices by a single value. The values are parsed here; the mesh is assembled through
// OpenMesh's ImporterT, the same face handling (non-manifold splitting) its readers use.

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> ply_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return std::nullopt;
}

std::size_t ply_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 8;
}

bool ply_is_float(PlyType t) {
  return t == PlyType::Float32 || t == PlyType::Float64;
}

// X..Z, NX..NZ and Red..Blue must stay consecutive: parse_ply indexes with them.
enum class PlyRole { Other, X, Y, Z, NX, NY, NZ, Red, Green, Blue, Alpha, VertexIndices };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  PlyRole role = PlyRole::Other;
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
        p.name = std::string(tokens[4]);
      } else {
        if (tokens.size() != 3) fail(file, line_no, "property must be 'property <type> <name>'");
        auto t = ply_type(tokens[1]);
        if (!t) fail(file, line_no, "unknown property type '" + std::string(tokens[1]) + "'");
        p.type = *t;
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
double load(const unsigned char* bytes) {
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
        return load<std::int8_t>(b);
      case PlyType::UInt8:
        return load<std::uint8_t>(b);
      case PlyType::Int16:
        return load<std::int16_t>(b);
      case PlyType::UInt16:
        return load<std::uint16_t>(b);
      case PlyType::Int32:
        return load<std::int32_t>(b);
      case PlyType::UInt32:
        return load<std::uint32_t>(b);
      case PlyType::Float32:
        return load<float>(b);
      case PlyType::Float64:
        return load<double>(b);
    }
    return 0;
  }

  const std::string& data_;
  std::size_t pos_;
  std::size_t line_;
  std::size_t token_line_ = 0;
  PlyFormat format_;
};

// A mesh as plain arrays (a parsed PLY file, or what an OM file's halfedges describe), before
// it becomes a PolyMesh.
struct RawMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // empty when the file has none
  std::vector<glm::vec3> colors;    // empty when the file has none
  bool float_colors = false;
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_indices;
  bool binary = false;
  std::vector<std::string> warnings;  // what the reader accepted but the user should know
};

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
  for (auto& p : vertex->properties) {
    static const std::map<std::string, PlyRole> roles = {
        {"x", PlyRole::X},         {"y", PlyRole::Y},
        {"z", PlyRole::Z},         {"nx", PlyRole::NX},
        {"ny", PlyRole::NY},       {"nz", PlyRole::NZ},
        {"red", PlyRole::Red},     {"diffuse_red", PlyRole::Red},
        {"green", PlyRole::Green}, {"diffuse_green", PlyRole::Green},
        {"blue", PlyRole::Blue},   {"diffuse_blue", PlyRole::Blue},
        {"alpha", PlyRole::Alpha}};
    auto it = roles.find(p.name);
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
      try {
        for (auto& p : e.properties) {
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
          if (p.role >= PlyRole::X && p.role <= PlyRole::Z) {
            out.positions[i][role - static_cast<int>(PlyRole::X)] = v;
          } else if (p.role >= PlyRole::NX && p.role <= PlyRole::NZ) {
            out.normals[i][role - static_cast<int>(PlyRole::NX)] = v;
          } else if (p.role >= PlyRole::Red && p.role <= PlyRole::Blue) {
            out.colors[i][role - static_cast<int>(PlyRole::Red)] = c;
          }
        }
      } catch (const PlyBody::End&) {
        fail(file, 0,
             "file ends inside " + e.name + " " + std::to_string(i) + " of " +
                 std::to_string(e.count) + " (truncated?)");
      } catch (const PlyBody::BadToken& bad) {
        fail(file, body.line(),
             "'" + bad.token + "' in " + e.name + " " + std::to_string(i) +
                 " is not a number of the declared type");
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
    }
    // Elements after the faces carry nothing we use (OpenMesh stops there too).
    if (&e == (face ? face : vertex)) break;
  }
  return out;
}

// Builds the mesh from arrays through OpenMesh's importer, so that the connectivity is whatever
// add_face makes of the faces (consistent by construction), whatever the file said.
void build_mesh(const RawMesh& raw, LoadedMesh& loaded, FileFacts& facts) {
  PolyMesh& mesh = loaded.mesh;
  mesh.clear();
  const std::size_t nv = raw.positions.size();
  const std::size_t nf = raw.face_offsets.size() - 1;
  mesh.reserve(nv, 3 * nv, nf);
  for (const auto& p : raw.positions) mesh.add_vertex(to_om(p));

  // Which file vertex each mesh vertex came from: itself, or for the copies the importer makes
  // to split off a non-manifold face, the corner it copied (copies are made in corner order).
  std::vector<std::uint32_t> origin(nv);
  for (std::size_t v = 0; v < nv; ++v) origin[v] = static_cast<std::uint32_t>(v);

  OpenMesh::IO::ImporterT<PolyMesh> importer(mesh);
  std::vector<OpenMesh::VertexHandle> handles;
  for (std::size_t f = 0; f < nf; ++f) {
    handles.clear();
    for (auto k = raw.face_offsets[f]; k < raw.face_offsets[f + 1]; ++k) {
      handles.emplace_back(static_cast<int>(raw.face_indices[k]));
    }
    auto sorted = handles;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      ++facts.repeated_faces;
      continue;
    }
    const std::size_t before = mesh.n_vertices();
    importer.add_face(handles);
    for (std::size_t v = before; v < mesh.n_vertices(); ++v) {
      origin.push_back(raw.face_indices[raw.face_offsets[f] + (v - before)]);
    }
  }

  loaded.read_options = Options();
  if (raw.binary) loaded.read_options += Options::Binary;
  facts.vertices = nv;
  facts.normal_given.assign(mesh.n_vertices(), 0);
  if (!raw.normals.empty()) {
    loaded.read_options += Options::VertexNormal;
    for (auto vh : mesh.vertices()) {
      mesh.set_normal(vh, to_om(raw.normals[origin[vh.idx()]]));
      facts.normal_given[vh.idx()] = 1;
    }
  }
  if (!raw.colors.empty()) {
    loaded.read_options += Options::VertexColor;
    if (raw.float_colors) loaded.read_options += Options::ColorFloat;
    for (auto vh : mesh.vertices()) {
      const auto& c = raw.colors[origin[vh.idx()]];
      mesh.set_color(vh, OpenMesh::Vec3f(c.r, c.g, c.b));
    }
  }
  if (mesh.n_vertices() > nv) {
    loaded.warnings.push_back(plural(mesh.n_vertices() - nv, "vertex", "vertices") +
                              " duplicated to split off non-manifold faces");
  }
}

// =============================================================================================
// OBJ: checked line by line, then read by OpenMesh. Its reader indexes its arrays with the
// file's indices unchecked (index 0, or one past the end, writes outside the mesh), skips a
// vertex whose numbers it cannot parse (shifting every later index), gives normals only to
// vertices that a face corner names (isolated ones keep uninitialised memory), and sets colours
// by position in a list that skips uncoloured vertices. So indices are checked here, and the
// normals and colours OpenMesh could not be trusted with are taken from this pass.

FileFacts check_obj(const std::string& text, const std::string& file) {
  FileFacts facts;
  const auto lines = split_lines(text);
  // Pass 1: how many positions and normals (OpenMesh resolves positive indices against all of
  // them, so a face may name a vertex defined further down).
  std::size_t total_v = 0, total_vn = 0;
  for (auto raw : lines) {
    auto t = split_whitespace(trim(raw));
    if (t.empty()) continue;
    if (t[0] == "v") ++total_v;
    if (t[0] == "vn") ++total_vn;
  }
  std::vector<glm::vec3> colors;
  std::size_t colored = 0, seen_v = 0, seen_vn = 0;
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
          fail(file, line_no, "'" + std::string(t[k + 1]) + "' is not a number");
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
      double uv;
      if (t.size() < 3 || !parse_double(t[1], uv) || !parse_double(t[2], uv)) {
        fail(file, line_no, "vt needs two numbers");  // OpenMesh gives up on the whole file
      }
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
        long long v = 0;
        if (parts[0].empty() || !parse_int(parts[0], v) || v == 0) {
          fail(file, line_no,
               "face corner '" + std::string(corner) + "' has no valid vertex index");
        }
        // Negative indices count back from the last vertex defined so far (OBJ spec, OpenMesh).
        long long resolved = v < 0 ? static_cast<long long>(seen_v) + v + 1 : v;
        if (resolved < 1 || resolved > static_cast<long long>(total_v)) {
          fail(file, line_no,
               "face vertex index " + std::to_string(v) + " is out of range (the file has " +
                   plural(total_v, "vertex", "vertices") + ")");
        }
        corners.push_back(resolved - 1);
        if (!parts[2].empty()) {
          long long n = 0;
          if (!parse_int(parts[2], n) || n == 0) {
            fail(file, line_no,
                 "face corner '" + std::string(corner) + "' has an invalid normal index");
          }
          long long rn = n < 0 ? static_cast<long long>(seen_vn) + n + 1 : n;
          if (rn < 1 || rn > static_cast<long long>(total_vn)) {
            fail(file, line_no,
                 "face normal index " + std::to_string(n) + " is out of range (the file has " +
                     plural(total_vn, "normal", "normals") + ")");
          }
          facts.normal_given[static_cast<std::size_t>(resolved - 1)] = 1;
        }
      }
      auto sorted = corners;
      std::sort(sorted.begin(), sorted.end());
      sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
      if (sorted.size() != corners.size()) ++facts.repeated_faces;
    }
  }
  facts.vertices = total_v;
  facts.colors_checked = true;
  if (colored > 0 && colored == total_v) {
    facts.has_colors = true;
    facts.colors = std::move(colors);
  } else if (colored > 0) {
    facts.partial_colors = true;
  }
  return facts;
}

// =============================================================================================
// OFF: OpenMesh reads the counts and the values token by token, colours from the rest of each
// vertex line, has no comments, and reads `n` indices for a face whatever the line holds; a
// short file leaves it repeating stale values. Checked here line by line: one vertex or face per
// line, counts that match, indices in range, colours OpenMesh will understand.

struct OffHeader {
  bool texcoords = false, colors = false, normals = false, binary = false;
};

OffHeader parse_off_keyword(std::string_view first_line, const std::string& file) {
  OffHeader h;
  auto tokens = split_whitespace(first_line);
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
  } else if (tokens.size() > 1) {
    // OpenMesh discards the rest of the first line: counts written there would be lost.
    fail(file, 1, "the counts must be on the line after '" + std::string(tokens[0]) + "'");
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
    if (h.texcoords)
      for (int k = 0; k < 2; ++k) f32("a vertex");
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

// OpenMesh's getColorType: items are counted by single spaces, and a '.' in the first one means
// float colours.
FileFacts check_off(const std::string& data, const std::string& file) {
  const auto lines = split_lines(data);
  if (lines.empty()) fail(file, 0, "file is empty");
  const OffHeader h = parse_off_keyword(lines[0], file);
  if (h.binary) return check_off_binary(data, h, file);

  FileFacts facts;
  std::size_t li = 1;
  auto next_content_line = [&](std::string_view& line) {
    while (li < lines.size()) {
      line = trim(lines[li++]);
      if (line.empty()) continue;
      if (line[0] == '#')
        fail(file, li, "comment lines are not supported by OpenMesh's OFF reader");
      return true;
    }
    return false;
  };
  std::string_view line;
  if (!next_content_line(line)) fail(file, 0, "file ends before the vertex and face counts");
  auto counts = split_whitespace(line);
  long long nv = 0, nf = 0, ne = 0;
  if (counts.size() != 3 || !parse_int(counts[0], nv) || !parse_int(counts[1], nf) ||
      !parse_int(counts[2], ne) || nv < 0 || nf < 0 || ne < 0) {
    fail(file, li, "expected '<vertices> <faces> <edges>'");
  }
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
    if (t.size() < fixed)
      fail(file, li,
           "vertex " + std::to_string(i) + " needs " + std::to_string(fixed) + " numbers");
    for (std::size_t k = 0; k < fixed; ++k) {
      double v;
      if (!parse_double(t[k], v)) fail(file, li, "'" + std::string(t[k]) + "' is not a number");
      if (!fits_openmesh_float(v)) {
        fail(file, li,
             "vertex " + std::to_string(i) +
                 (k < 3 ? " has a non-finite coordinate" : " has a non-finite normal") + " ('" +
                 std::string(t[k]) + "'; OpenMesh reads OFF numbers as float)");
      }
    }
    if (!h.colors) continue;
    if (h.texcoords && t.size() < fixed + 2) {
      fail(file, li, "vertex " + std::to_string(i) + " lacks texture coordinates");
    }
    const std::size_t items = t.size() - fixed - (h.texcoords ? 2 : 0);
    glm::vec3 c(0.0f);
    if (items == 3 || items == 4) {
      // OpenMesh counts items by single spaces; anything else changes its reading.
      std::string_view rest = line.substr(static_cast<std::size_t>(t[fixed].data() - line.data()));
      if (h.texcoords)
        rest = rest.substr(0, static_cast<std::size_t>(t[t.size() - 2].data() - rest.data()));
      rest = trim(rest);
      std::size_t spaces = static_cast<std::size_t>(std::count(rest.begin(), rest.end(), ' '));
      if (spaces + 1 != items || rest.find('\t') != std::string_view::npos) {
        fail(file, li, "colour values must be separated by single spaces (OpenMesh counts spaces)");
      }
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
    // A plain OFF face is read token by token: extra values would be taken as the next face.
    if (!h.colors && t.size() > static_cast<std::size_t>(n) + 1) {
      fail(file, li,
           "face " + std::to_string(i) + " has values after its " + std::to_string(n) + " indices");
    }
    std::vector<long long> idx;
    for (long long k = 1; k <= n; ++k) {
      long long x;
      if (!parse_int(t[static_cast<std::size_t>(k)], x))
        fail(file, li,
             "'" + std::string(t[static_cast<std::size_t>(k)]) + "' is not a vertex index");
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
  facts.colors_checked = true;
  if (h.colors && colored == static_cast<std::size_t>(nv) && nv > 0) {
    facts.has_colors = true;
    facts.colors = std::move(colors);
  } else if (colored > 0) {
    facts.partial_colors = true;
  }
  return facts;
}

// =============================================================================================
// STL: OpenMesh takes a file as binary when its size is 84 + 50 * (triangle count), and as
// ASCII otherwise, so a truncated binary file is parsed as text and yields nothing. Say so, and
// reject non-finite coordinates before its vertex-merging map compares NaNs.

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
        fail(file, li + 1,
             "'" + std::string(t[static_cast<std::size_t>(k)]) + "' is not a finite number");
      }
    }
  }
}

// =============================================================================================
// OM: OpenMesh's own binary format, whose chunks describe the halfedge structure directly.
// Corrupt files make its reader abort (asserts compiled into libOpenMeshCore, double frees),
// segfault, allocate without end, or quietly write outside its arrays and leave a halfedge
// structure whose circulators crash later. Checking the format ourselves would mean
// re-implementing it, so the reader runs in a child process, which walks the faces with every
// handle checked and sends back plain arrays; this process never runs the OM reader.

RawMesh faces_of_om_mesh(const PolyMesh& raw, const Options& options, const std::string& file) {
  RawMesh out;
  out.binary = options.is_binary();
  const std::size_t nv = raw.n_vertices(), nh = raw.n_halfedges();
  for (auto vh : raw.vertices()) {
    const auto& p = raw.point(vh);
    out.positions.emplace_back(p[0], p[1], p[2]);
    if (options.vertex_has_normal()) out.normals.push_back(to_glm(raw.normal(vh)));
    if (options.vertex_has_color()) {
      const auto& c = raw.color(vh);
      out.colors.emplace_back(c[0], c[1], c[2]);
    }
  }
  auto corrupt = [&](std::size_t f) {
    fail(file, 0, "face " + std::to_string(f) + " has a broken halfedge loop (corrupt OM file)");
  };
  for (std::size_t f = 0; f < raw.n_faces(); ++f) {
    const auto start = raw.halfedge_handle(OpenMesh::FaceHandle(static_cast<int>(f)));
    if (start.idx() < 0 || static_cast<std::size_t>(start.idx()) >= nh) corrupt(f);
    auto h = start;
    std::size_t steps = 0;
    do {
      const auto v = raw.to_vertex_handle(h);
      if (v.idx() < 0 || static_cast<std::size_t>(v.idx()) >= nv) corrupt(f);
      out.face_indices.push_back(static_cast<std::uint32_t>(v.idx()));
      h = raw.next_halfedge_handle(h);
      if (h.idx() < 0 || static_cast<std::size_t>(h.idx()) >= nh || ++steps > nh) corrupt(f);
    } while (h != start);
    if (steps < 3) corrupt(f);
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_indices.size()));
  }
  return out;
}

// RawMesh over the pipe: counts, then the arrays as they are in memory (same process image).
std::string serialize(const RawMesh& m) {
  std::string out;
  auto put = [&out](const void* p, std::size_t n) {
    if (n) out.append(static_cast<const char*>(p), n);
  };
  const std::uint64_t counts[5] = {m.positions.size(), m.normals.size(), m.colors.size(),
                                   m.face_offsets.size(), m.face_indices.size()};
  put(counts, sizeof counts);
  const char binary = m.binary ? 1 : 0;
  put(&binary, 1);
  put(m.positions.data(), m.positions.size() * sizeof(glm::dvec3));
  put(m.normals.data(), m.normals.size() * sizeof(glm::dvec3));
  put(m.colors.data(), m.colors.size() * sizeof(glm::vec3));
  put(m.face_offsets.data(), m.face_offsets.size() * sizeof(std::uint32_t));
  put(m.face_indices.data(), m.face_indices.size() * sizeof(std::uint32_t));
  return out;
}

// Checks sizes and indices: the child's memory may have been damaged by the file it read.
RawMesh deserialize(const std::string& data, const std::string& file) {
  auto broken = [&]() {
    fail(file, 0, "OpenMesh's OM reader returned an inconsistent mesh (corrupt file?)");
  };
  std::uint64_t counts[5];
  if (data.size() < sizeof counts + 1) broken();
  std::memcpy(counts, data.data(), sizeof counts);
  const auto [nv, nn, nc, no, ni] = counts;
  if (nv > (1u << 31) || (nn != 0 && nn != nv) || (nc != 0 && nc != nv) || no < 1 ||
      no > (1u << 31) || ni > (1ull << 34))
    broken();
  const std::size_t expected = sizeof counts + 1 + (nv + nn) * sizeof(glm::dvec3) +
                               nc * sizeof(glm::vec3) + (no + ni) * sizeof(std::uint32_t);
  if (data.size() != expected) broken();
  RawMesh m;
  std::size_t pos = sizeof counts;
  m.binary = data[pos++] != 0;
  auto get = [&](auto& vec, std::size_t n) {
    vec.resize(n);
    if (n) std::memcpy(vec.data(), data.data() + pos, n * sizeof(vec[0]));
    pos += n * sizeof(vec[0]);
  };
  get(m.positions, nv);
  get(m.normals, nn);
  get(m.colors, nc);
  get(m.face_offsets, no);
  get(m.face_indices, ni);
  if (m.face_offsets.front() != 0 || m.face_offsets.back() != ni) broken();
  for (std::size_t f = 0; f + 1 < no; ++f) {
    if (m.face_offsets[f + 1] < m.face_offsets[f] + 3) broken();
  }
  for (auto i : m.face_indices) {
    if (i >= nv) broken();
  }
  return m;
}

// In a sanitized build (./test.sh --sanitize) the OM reader's overflows and runaway allocations
// are sanitizer reports, which end the child with exit code 1 rather than a signal; the death
// callback gives them a code of their own, so the parent reports a crash as it does for the
// release build's signals. Only the child's death is handled: the sanitizer stays on everywhere.
constexpr int kChildSanitizerDied = 86;

void on_sanitizer_death_in_child() {
#if defined(__SANITIZE_ADDRESS__)
  __sanitizer_set_death_callback([] { ::_exit(kChildSanitizerDied); });
#endif
}

bool write_all(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

RawMesh read_om_in_child(const fs::path& path, const std::string& file,
                         OpenMeshLogCapture& capture) {
  std::error_code ec;
  const std::uintmax_t file_size = fs::file_size(path, ec);
  const std::size_t size = ec ? 0 : static_cast<std::size_t>(file_size);
  // OM reads at well over 100 MB/s; 2 s per MB is a generous bound before calling it a hang.
  const auto limit = std::chrono::seconds(10 + static_cast<long long>(size >> 19));
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) fail(file, 0, "cannot read OM files: pipe() failed");
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    fail(file, 0, "cannot read OM files: fork() failed");
  }
  if (pid == 0) {
    ::close(pipe_fds[0]);
    on_sanitizer_death_in_child();
    const int devnull = ::open("/dev/null", O_WRONLY);
    if (devnull >= 0) {
      ::dup2(devnull, 1);
      ::dup2(devnull, 2);
    }
    // Cap the address space above what the child already maps (inherited from us, GL
    // included) and its CPU time, so that a runaway file ends in a failed allocation or
    // SIGXCPU, not with the OOM killer.
    const std::size_t budget = (std::size_t{512} << 20) + 64 * size;
    char statm[128] = {};
    const int fd = ::open("/proc/self/statm", O_RDONLY);
    if (fd >= 0) {
      const auto got = ::read(fd, statm, sizeof statm - 1);
      ::close(fd);
      if (got > 0) {
        const std::size_t mapped =
            std::strtoull(statm, nullptr, 10) * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
        const rlimit as{mapped + budget, mapped + budget};
        ::setrlimit(RLIMIT_AS, &as);
      }
    }
    const rlimit cpu{static_cast<rlim_t>(limit.count()), static_cast<rlim_t>(limit.count())};
    ::setrlimit(RLIMIT_CPU, &cpu);
    int code = 0;
    std::string payload;
    try {
      PolyMesh raw;
      Options options = requested_options();
      // The log streams still point into the parent's capture buffer, copied by fork.
      read_with_openmesh(raw, file, options, capture);
      payload = serialize(faces_of_om_mesh(raw, options, file));
    } catch (const InputError& e) {
      code = 3;
      payload = e.what_only();
    } catch (const std::exception& e) {
      code = 3;
      payload = std::string("OpenMesh could not read it: ") + e.what();
    }
    write_all(pipe_fds[1], payload);
    ::_exit(code);
  }
  ::close(pipe_fds[1]);
  // Drain the pipe while the child works (it blocks once the pipe buffer is full).
  const auto start = std::chrono::steady_clock::now();
  auto timed_out = [&]() {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    ::close(pipe_fds[0]);
    fail(file, 0, "OpenMesh's OM reader did not finish reading this file (corrupt?)");
  };
  std::string data;
  char buf[1 << 16];
  for (;;) {
    const auto left = limit - (std::chrono::steady_clock::now() - start);
    if (left <= std::chrono::steady_clock::duration::zero()) timed_out();
    pollfd pfd{pipe_fds[0], POLLIN, 0};
    const int ready = ::poll(
        &pfd, 1,
        static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(left).count()) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline check above ends it
    const ssize_t n = ::read(pipe_fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child is done (or dead)
    data.append(buf, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    fail(file, 0,
         "OpenMesh's OM reader crashed on this file (signal " + std::to_string(WTERMSIG(status)) +
             "; corrupt or truncated?)");
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == kChildSanitizerDied) {
    fail(file, 0,
         "OpenMesh's OM reader crashed on this file (sanitizer report; corrupt or truncated?)");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    fail(file, 0, data.empty() ? "OpenMesh could not read it" : data);
  return deserialize(data, file);
}

// =============================================================================================
// After reading: the checks every format shares.

// The importer copies the vertices of a face it cannot add without breaking the manifold
// structure; the copies get the position but neither the normal nor the colour. Find each
// copy's original by its (exactly copied) position.
std::size_t repair_split_vertices(PolyMesh& mesh, const Options& opts, FileFacts& facts) {
  std::vector<OpenMesh::VertexHandle> copies;
  for (auto vh : mesh.vertices()) {
    if (mesh.status(vh).fixed_nonmanifold()) copies.push_back(vh);
  }
  facts.normal_given.resize(mesh.n_vertices(), opts.vertex_has_normal() ? 1 : 0);
  if (facts.has_colors) facts.colors.resize(mesh.n_vertices(), glm::vec3(0.0f));
  if (copies.empty()) return 0;
  std::map<std::array<double, 3>, int> originals;
  for (auto vh : mesh.vertices()) {
    if (mesh.status(vh).fixed_nonmanifold()) continue;
    const auto& p = mesh.point(vh);
    originals.emplace(std::array<double, 3>{p[0], p[1], p[2]}, vh.idx());
  }
  for (auto vh : copies) {
    const auto& p = mesh.point(vh);
    auto it = originals.find({p[0], p[1], p[2]});
    const auto i = static_cast<std::size_t>(vh.idx());
    if (it == originals.end()) {
      facts.normal_given[i] = 0;
      mesh.set_color(vh, OpenMesh::Vec3f(0.0f));
      continue;
    }
    const OpenMesh::VertexHandle from(it->second);
    const auto j = static_cast<std::size_t>(from.idx());
    mesh.set_normal(vh, mesh.normal(from));
    mesh.set_color(vh, mesh.color(from));
    facts.normal_given[i] = facts.normal_given[j];
    if (facts.has_colors) facts.colors[i] = facts.colors[j];
  }
  return copies.size();
}

// Twice the area times the unit normal: Newell's sum as a fan of cross products relative to the
// first corner, so that coordinates near 1e6 do not cancel away the face's own size.
glm::dvec3 face_area_vector(const PolyMesh& mesh, OpenMesh::FaceHandle fh) {
  glm::dvec3 sum(0.0), first(0.0), prev(0.0);
  int k = 0;
  for (auto vh : mesh.fv_range(fh)) {
    const glm::dvec3 p = to_glm(mesh.point(vh));
    if (k == 0) {
      first = p;
    } else if (k >= 2) {
      sum += glm::cross(prev - first, p - first);
    }
    prev = p;
    ++k;
  }
  return sum;
}

// Recomputes the vertex normals where `keep` is 0 (all when `keep` is empty) and every face
// normal; returns how many recomputed vertices are left without a normal.
std::size_t recompute_normals(PolyMesh& mesh, const std::vector<char>& keep) {
  std::vector<glm::dvec3> area(mesh.n_faces());
  for (auto fh : mesh.faces()) {
    area[static_cast<std::size_t>(fh.idx())] = face_area_vector(mesh, fh);
    mesh.set_normal(fh, to_om(safe_normalize(area[static_cast<std::size_t>(fh.idx())])));
  }
  std::size_t without = 0;
  for (auto vh : mesh.vertices()) {
    if (!keep.empty() && keep[static_cast<std::size_t>(vh.idx())]) continue;
    // Area vectors of a 1e-6 mesh are ~1e-12 long; safe_normalize rescales before it
    // normalises, so their sum keeps its direction.
    glm::dvec3 sum(0.0);
    for (auto fh : mesh.vf_range(vh)) sum += area[static_cast<std::size_t>(fh.idx())];
    const glm::dvec3 n = safe_normalize(sum);
    if (n == glm::dvec3(0.0)) ++without;
    mesh.set_normal(vh, to_om(n));
  }
  return without;
}

void finish(LoadedMesh& loaded, const std::string& file, FileFacts& facts) {
  PolyMesh& mesh = loaded.mesh;
  if (mesh.n_vertices() == 0) fail(file, 0, "mesh is empty (no vertices)");
  if (mesh.n_faces() == 0) {
    fail(file, 0, "mesh has " + plural(mesh.n_vertices(), "vertex", "vertices") + " but no faces");
  }
  for (auto vh : mesh.vertices()) {
    const glm::dvec3 p = to_glm(mesh.point(vh));
    if (!is_finite(p)) {
      std::ostringstream what;
      what << "vertex " << vh.idx() << " has a non-finite coordinate (" << p.x << ", " << p.y
           << ", " << p.z << ")";
      fail(file, 0, what.str());
    }
  }
  if (facts.repeated_faces > 0) {
    loaded.warnings.push_back(plural(facts.repeated_faces, "face", "faces") +
                              " naming a vertex twice dropped (a halfedge mesh cannot hold them)");
  }

  // Colours: ours where we parsed them, none where only some vertices had one.
  if (facts.partial_colors || (facts.colors_checked && !facts.has_colors)) {
    loaded.read_options -= Options::VertexColor;
    loaded.read_options -= Options::ColorFloat;
    if (facts.partial_colors)
      loaded.warnings.push_back("only some vertices have colours: colours ignored");
  } else if (facts.has_colors) {
    loaded.read_options += Options::VertexColor;
    for (auto vh : mesh.vertices()) {
      const auto& c = facts.colors[static_cast<std::size_t>(vh.idx())];
      mesh.set_color(vh, OpenMesh::Vec3f(c.r, c.g, c.b));
    }
  }
  if (loaded.read_options.vertex_has_color()) {
    for (auto vh : mesh.vertices()) {
      const auto& c = mesh.color(vh);
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
        fail(file, 0, "vertex " + std::to_string(vh.idx()) + " has a non-finite colour");
      }
    }
  }

  // Normals: keep the file's where they are usable (normalised), recompute the rest.
  std::vector<char> keep(mesh.n_vertices(), 0);
  std::size_t zero = 0, nonfinite = 0, nonunit = 0, missing = 0;
  if (loaded.read_options.vertex_has_normal()) {
    for (auto vh : mesh.vertices()) {
      const auto i = static_cast<std::size_t>(vh.idx());
      if (i >= facts.normal_given.size() || !facts.normal_given[i]) {
        ++missing;
        continue;
      }
      const glm::dvec3 n = to_glm(mesh.normal(vh));
      if (!is_finite(n)) {
        ++nonfinite;
      } else if (n == glm::dvec3(0.0)) {
        ++zero;
      } else {
        // Float normals in files are off by ~1e-7; only count what is clearly not unit length.
        if (std::fabs(glm::length(n) - 1.0) > 1e-5) ++nonunit;
        mesh.set_normal(vh, to_om(safe_normalize(n)));
        keep[i] = 1;
      }
    }
  } else {
    loaded.warnings.push_back(
        "no vertex normals in the file: computed from the faces (area-weighted)");
  }
  const std::size_t without = recompute_normals(mesh, keep);
  if (zero)
    loaded.warnings.push_back(plural(zero, "zero-length normal", "zero-length normals") +
                              " recomputed from the faces");
  if (nonfinite)
    loaded.warnings.push_back(plural(nonfinite, "non-finite normal", "non-finite normals") +
                              " recomputed from the faces");
  if (missing)
    loaded.warnings.push_back(plural(missing, "vertex", "vertices") +
                              " without a normal in the file: computed from the faces");
  if (nonunit)
    loaded.warnings.push_back(plural(nonunit, "non-unit normal", "non-unit normals") +
                              " normalised");
  if (without) {
    loaded.warnings.push_back(
        plural(without, "vertex has", "vertices have") +
        " no normal (isolated, or only degenerate faces around it): left zero");
  }
}

// =============================================================================================
// PLY writer: double positions (see write_mesh in mesh.h), float normals, float or 8-bit colours.

void write_ply(const fs::path& tmp, const fs::path& target, const PolyMesh& mesh,
               const Options& options) {
  std::ofstream out(tmp, std::ios::binary);
  if (!out)
    throw InputError(target.string(), "",
                     "cannot write output: " + std::string(std::strerror(errno)));
  const bool binary = options.is_binary();
  const bool normals = options.vertex_has_normal();
  const bool colors = options.vertex_has_color();
  const bool float_colors = options.color_is_float();
  std::size_t max_valence = 0;
  for (auto fh : mesh.faces()) max_valence = std::max<std::size_t>(max_valence, mesh.valence(fh));

  std::ostringstream header;
  header << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
         << "comment written by ltrender\n"
         << "element vertex " << mesh.n_vertices() << "\n"
         << "property double x\nproperty double y\nproperty double z\n";
  if (normals) header << "property float nx\nproperty float ny\nproperty float nz\n";
  if (colors) {
    const char* t = float_colors ? "float" : "uchar";
    header << "property " << t << " red\nproperty " << t << " green\nproperty " << t << " blue\n";
  }
  header << "element face " << mesh.n_faces() << "\n"
         << "property list " << (max_valence > 255 ? "int" : "uchar") << " int vertex_indices\n"
         << "end_header\n";
  out << header.str();

  auto color8 = [](float c) {
    return static_cast<unsigned char>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
  };
  if (binary) {
    // binary_little_endian: values are copied as they are in memory.
    static_assert(std::endian::native == std::endian::little, "PLY I/O assumes little-endian");
    std::string buf;
    auto put = [&buf](const auto& v) { buf.append(reinterpret_cast<const char*>(&v), sizeof v); };
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      for (int k = 0; k < 3; ++k) put(p[k]);
      if (normals) {
        const auto& n = mesh.normal(vh);
        for (int k = 0; k < 3; ++k) put(static_cast<float>(n[k]));
      }
      if (colors) {
        const auto& c = mesh.color(vh);
        for (int k = 0; k < 3; ++k) {
          if (float_colors) {
            put(c[k]);
          } else {
            put(color8(c[k]));
          }
        }
      }
    }
    for (auto fh : mesh.faces()) {
      const auto n = mesh.valence(fh);
      if (max_valence > 255) {
        put(static_cast<std::int32_t>(n));
      } else {
        put(static_cast<unsigned char>(n));
      }
      for (auto vh : mesh.fv_range(fh)) put(static_cast<std::int32_t>(vh.idx()));
    }
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
  } else {
    char line[512];
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      std::string s;
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g", p[0], p[1], p[2]);
      s = line;
      if (normals) {
        const auto& n = mesh.normal(vh);
        std::snprintf(line, sizeof line, " %.9g %.9g %.9g",
                      static_cast<double>(static_cast<float>(n[0])),
                      static_cast<double>(static_cast<float>(n[1])),
                      static_cast<double>(static_cast<float>(n[2])));
        s += line;
      }
      if (colors) {
        const auto& c = mesh.color(vh);
        if (float_colors) {
          std::snprintf(line, sizeof line, " %.9g %.9g %.9g", static_cast<double>(c[0]),
                        static_cast<double>(c[1]), static_cast<double>(c[2]));
        } else {
          std::snprintf(line, sizeof line, " %d %d %d", color8(c[0]), color8(c[1]), color8(c[2]));
        }
        s += line;
      }
      out << s << '\n';
    }
    for (auto fh : mesh.faces()) {
      out << mesh.valence(fh);
      for (auto vh : mesh.fv_range(fh)) out << ' ' << vh.idx();
      out << '\n';
    }
  }
  out.flush();
  if (!out)
    throw InputError(target.string(), "",
                     "cannot write output: " + std::string(std::strerror(errno)));
}

const char* const kReadable = ".ply, .obj, .off, .stl, .stla, .stlb, .om";

}  // namespace

// =============================================================================================

namespace {

LoadedMesh read_mesh_unguarded(const fs::path& path) {
  const std::string file = path.string();
  // Regular files within the size cap only, before anything opens it (the OM reader in its
  // child opens it by name).
  check_input_file(path, InputKind::Mesh);
  const std::string ext = lower_extension(path);
  const bool stl = ext == ".stl" || ext == ".stla" || ext == ".stlb";
  if (ext != ".ply" && ext != ".obj" && ext != ".off" && ext != ".om" && !stl) {
    throw InputError(file, "", "unknown mesh format '" + ext + "' (readable: " + kReadable + ")");
  }

  LoadedMesh loaded;
  FileFacts facts;
  if (ext == ".ply") {
    const RawMesh ply = parse_ply(read_bytes(path), file);
    loaded.warnings = ply.warnings;
    OpenMeshLogCapture capture;  // the importer reports through omerr
    build_mesh(ply, loaded, facts);
  } else if (ext == ".om") {
    OpenMeshLogCapture capture;
    // Rebuilt from the face loops: whatever halfedges the file held, the mesh we hand on has
    // the connectivity add_face makes.
    build_mesh(read_om_in_child(path, file, capture), loaded, facts);
  } else {
    const std::string data = read_bytes(path);
    if (ext == ".obj") facts = check_obj(data, file);
    if (ext == ".off") facts = check_off(data, file);
    if (stl) check_stl(data, file);
    OpenMeshLogCapture capture;
    PolyMesh& mesh = loaded.mesh;
    // Vertex status lets the importer mark the copies it makes for non-manifold faces.
    mesh.request_vertex_status();
    Options options = requested_options();
    read_with_openmesh(mesh, file, options, capture);
    // STL has neither vertex normals nor colours, but its reader hands the request back as if
    // the file had them (and leaves them uninitialised).
    if (stl) options -= Options::VertexNormal | Options::VertexColor | Options::ColorFloat;
    loaded.read_options = options;
    const std::size_t split = repair_split_vertices(mesh, options, facts);
    if (split) {
      loaded.warnings.push_back(plural(split, "vertex", "vertices") +
                                " duplicated to split off non-manifold faces");
    }
    if (facts.vertices && mesh.n_vertices() != facts.vertices + split) {
      throw InputError(file, "",
                       "OpenMesh read " + plural(mesh.n_vertices() - split, "vertex", "vertices") +
                           " where the file has " + std::to_string(facts.vertices));
    }
    mesh.release_vertex_status();
  }
  finish(loaded, file, facts);
  return loaded;
}

// A mesh within the size cap can still be too large for the machine (a 256 MiB file becomes a
// few GB of halfedges): that is this file's failure, so it is named.
[[noreturn]] void out_of_memory(const fs::path& path) {
  throw InputError(path.string(), "",
                   "out of memory reading this mesh (too large for this machine?)");
}

}  // namespace

LoadedMesh read_mesh(const fs::path& path) {
  try {
    return read_mesh_unguarded(path);
  } catch (const std::bad_alloc&) {
    out_of_memory(path);
  }
}

TriangleMesh to_triangle_mesh(const LoadedMesh& loaded) {
  const PolyMesh& mesh = loaded.mesh;
  TriangleMesh out;
  out.positions.reserve(mesh.n_vertices());
  out.normals.reserve(mesh.n_vertices());
  for (auto vh : mesh.vertices()) {
    out.positions.push_back(to_glm(mesh.point(vh)));
    out.normals.push_back(to_glm(mesh.normal(vh)));
  }
  if (loaded.read_options.vertex_has_color()) {
    out.colors.reserve(mesh.n_vertices());
    for (auto vh : mesh.vertices()) {
      const auto& c = mesh.color(vh);
      out.colors.emplace_back(c[0], c[1], c[2]);
    }
  }
  // A fan from the face's first corner keeps the polygon's winding (and so its orientation).
  out.triangles.reserve(mesh.n_faces());
  std::vector<unsigned int> corners;
  for (auto fh : mesh.faces()) {
    corners.clear();
    for (auto vh : mesh.fv_range(fh)) corners.push_back(static_cast<unsigned int>(vh.idx()));
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      out.triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
    }
  }
  return out;
}

TriangleMesh load_triangle_mesh(const fs::path& path) {
  LoadedMesh loaded = read_mesh(path);
  try {
    return to_triangle_mesh(loaded);
  } catch (const std::bad_alloc&) {
    out_of_memory(path);
  }
}

void write_mesh(const fs::path& path, const PolyMesh& mesh, Options options) {
  const std::string ext = lower_extension(path);
  if (ext == ".ply") {
    write_atomically(path, [&](const fs::path& tmp) { write_ply(tmp, path, mesh, options); });
    return;
  }
  static const char* const writable[] = {".obj", ".off", ".om", ".stl", ".stla", ".stlb", ".vtk"};
  if (std::find(std::begin(writable), std::end(writable), ext) == std::end(writable)) {
    throw InputError(
        path.string(), "",
        "unknown mesh format '" + ext + "' (writable: .ply, .obj, .off, .om, .stl, .vtk)");
  }
  write_atomically(path, [&](const fs::path& tmp) {
    OpenMeshLogCapture capture;
    // 17 significant digits: OpenMesh's default of 6 would move a vertex at 1e6 by up to 0.5.
    if (!OpenMesh::IO::write_mesh(mesh, tmp.string(), options, 17)) {
      const std::string why = capture.last_line();
      throw InputError(path.string(), "",
                       "OpenMesh could not write it" + (why.empty() ? std::string() : ": " + why));
    }
  });
}

std::size_t compute_normals(PolyMesh& mesh) {
  return recompute_normals(mesh, {});
}

}  // namespace lt
