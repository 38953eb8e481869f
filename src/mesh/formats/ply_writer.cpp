#include "mesh/formats/ply_writer.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "mesh/formats/ply_types.h"
#include "mesh/normals.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

using OpenMesh::IO::Options;

namespace {

// A value as ascii PLY writes it for `type`: integers as integers, floats with enough digits to
// read back bit-exact.
std::string ply_ascii(PlyType type, double value) {
  const double stored = ply_value_as(type, value);
  if (!ply_is_float(type)) return std::to_string(static_cast<long long>(stored));
  char text[64];
  std::snprintf(text, sizeof text, type == PlyType::Float32 ? "%.9g" : "%.17g", stored);
  return text;
}

}  // namespace

void write_ply(const std::filesystem::path& tmp, const std::filesystem::path& target,
               const PolyMesh& mesh, const Options& options,
               const std::vector<ExtraVertexProperty>& extras) {
  std::ofstream out(tmp, std::ios::binary);
  if (!out)
    throw InputError(target.string(), "",
                     "cannot write output: " + std::string(std::strerror(errno)));
  const bool binary = options.is_binary();
  const bool normals = options.vertex_has_normal();
  const bool colors = options.vertex_has_color();
  const bool float_colors = options.color_is_float();
  const bool uvs = options.vertex_has_texcoord();
  // Float when every coordinate is one (what a float u, v read back is), so a round trip keeps
  // the file's type and its values bit for bit; double otherwise.
  bool uv_float = true;
  for (auto vh : mesh.vertices()) {
    if (!uvs) break;
    const auto& t = mesh.texcoord2D(vh);
    for (int k = 0; k < 2; ++k) uv_float = uv_float && ply_value_as(PlyType::Float32, t[k]) == t[k];
  }
  const PlyType uv_type = uv_float ? PlyType::Float32 : PlyType::Float64;
  std::vector<PlyType> extra_types;
  for (const auto& e : extras) {
    if (uvs && (e.name == "u" || e.name == "v")) {
      throw InputError(
          target.string(), "",
          "vertex property '" + e.name + "' would repeat the texture coordinate's name");
    }
    const auto type = ply_type(e.ply_type);
    LT_CHECK(type && e.values.size() == mesh.n_vertices(), "extra vertex property " + e.name);
    extra_types.push_back(*type);
  }
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
  if (uvs) {
    const char* t = uv_float ? "float" : "double";
    header << "property " << t << " u\nproperty " << t << " v\n";
  }
  for (const auto& e : extras) header << "property " << e.ply_type << " " << e.name << "\n";
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
      if (uvs) {
        const auto& t = mesh.texcoord2D(vh);
        for (int k = 0; k < 2; ++k) {
          if (uv_float) {
            put(static_cast<float>(t[k]));
          } else {
            put(t[k]);
          }
        }
      }
      for (std::size_t e = 0; e < extras.size(); ++e) {
        unsigned char bytes[8];
        ply_store(extra_types[e], extras[e].values[static_cast<std::size_t>(vh.idx())], bytes);
        buf.append(reinterpret_cast<const char*>(bytes), ply_size(extra_types[e]));
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
      if (uvs) {
        const auto& t = mesh.texcoord2D(vh);
        s += ' ' + ply_ascii(uv_type, t[0]) + ' ' + ply_ascii(uv_type, t[1]);
      }
      for (std::size_t e = 0; e < extras.size(); ++e) {
        s += ' ' + ply_ascii(extra_types[e], extras[e].values[static_cast<std::size_t>(vh.idx())]);
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

}  // namespace lt::meshio
