// Small glTF files written by the tests: a JSON document and one binary buffer, saved as .gltf
// (external .bin or a data: URI) or as .glb, built by hand so that bad files can be made too.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "test_util.h"

namespace lt::test {

class GltfWriter {
 public:
  using json = nlohmann::json;
  json doc = {{"asset", {{"version", "2.0"}}}};
  std::string bin;

  // Appends `bytes` as a buffer view (4-byte aligned, §3.6.2.4) and an accessor over it.
  int accessor(const void* data, std::size_t bytes, int component_type, const char* type,
               std::size_t count, bool normalized = false) {
    while (bin.size() % 4) bin.push_back('\0');
    const std::size_t offset = bin.size();
    bin.append(static_cast<const char*>(data), bytes);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    json a = {{"bufferView", doc["bufferViews"].size() - 1},
              {"componentType", component_type},
              {"type", type},
              {"count", count}};
    if (normalized) a["normalized"] = true;
    doc["accessors"].push_back(a);
    return static_cast<int>(doc["accessors"].size() - 1);
  }
  template <typename T>
  int accessor(const std::vector<T>& v, int component_type, const char* type, int components,
               bool normalized = false) {
    return accessor(v.data(), v.size() * sizeof(T), component_type, type, v.size() / components,
                    normalized);
  }
  int floats(const std::vector<float>& v, const char* type, int components) {
    return accessor(v, 5126, type, components);
  }

  void use_extension(const std::string& name) {
    if (!doc.contains("extensionsUsed") ||
        std::find(doc["extensionsUsed"].begin(), doc["extensionsUsed"].end(), name) ==
            doc["extensionsUsed"].end()) {
      doc["extensionsUsed"].push_back(name);
    }
  }
  int node(json n) {
    doc["nodes"].push_back(std::move(n));
    const int i = static_cast<int>(doc["nodes"].size() - 1);
    return i;
  }
  // A root node of scene 0.
  int root(json n) {
    const int i = node(std::move(n));
    doc["scene"] = 0;
    doc["scenes"][0]["nodes"].push_back(i);
    return i;
  }
  int light(json l) {
    use_extension("KHR_lights_punctual");
    doc["extensions"]["KHR_lights_punctual"]["lights"].push_back(std::move(l));
    const int i = static_cast<int>(doc["extensions"]["KHR_lights_punctual"]["lights"].size() - 1);
    root({{"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}});
    return i;
  }

  json with_buffer(const std::string& uri) const {
    json d = doc;
    d["buffers"] = json::array({{{"byteLength", bin.size()}}});
    if (!uri.empty()) d["buffers"][0]["uri"] = uri;
    return d;
  }
  // NAME.gltf beside NAME.bin.
  fs::path write_gltf(const fs::path& dir, const std::string& name) const {
    write_file(dir / (name + ".bin"), bin);
    write_file(dir / (name + ".gltf"), with_buffer(name + ".bin").dump(1));
    return dir / (name + ".gltf");
  }
  fs::path write_gltf_data_uri(const fs::path& dir, const std::string& name) const {
    write_file(dir / (name + ".gltf"),
               with_buffer("data:application/octet-stream;base64," + base64(bin)).dump());
    return dir / (name + ".gltf");
  }
  // GLB (glTF 2.0 §4.4): header, JSON chunk padded with spaces, BIN chunk padded with zeros.
  std::string glb_bytes() const {
    std::string j = with_buffer("").dump();
    while (j.size() % 4) j.push_back(' ');
    std::string b = bin;
    while (b.size() % 4) b.push_back('\0');
    std::string out = "glTF";
    put32(out, 2);
    put32(out, static_cast<std::uint32_t>(12 + 8 + j.size() + 8 + b.size()));
    put32(out, static_cast<std::uint32_t>(j.size()));
    put32(out, 0x4E4F534Au);
    out += j;
    put32(out, static_cast<std::uint32_t>(b.size()));
    put32(out, 0x004E4942u);
    out += b;
    return out;
  }
  fs::path write_glb(const fs::path& dir, const std::string& name) const {
    write_file(dir / (name + ".glb"), glb_bytes());
    return dir / (name + ".glb");
  }

 private:
  static void put32(std::string& s, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  }
  static std::string base64(const std::string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
      const unsigned v = (static_cast<unsigned char>(in[i]) << 16) |
                         (static_cast<unsigned char>(in[i + 1]) << 8) |
                         static_cast<unsigned char>(in[i + 2]);
      for (int k = 3; k >= 0; --k) out.push_back(t[(v >> (6 * k)) & 63]);
    }
    const std::size_t rest = in.size() - i;
    if (rest) {
      unsigned v = static_cast<unsigned char>(in[i]) << 16;
      if (rest == 2) v |= static_cast<unsigned char>(in[i + 1]) << 8;
      out.push_back(t[(v >> 18) & 63]);
      out.push_back(t[(v >> 12) & 63]);
      out.push_back(rest == 2 ? t[(v >> 6) & 63] : '=');
      out.push_back('=');
    }
    return out;
  }
};

// The volume quad: a unit quad (z = 0, facing +Z, indexed u16) with a translucent material,
// a directional light behind it travelling +Z, a camera on +Z. `orthographic` picks the camera.
struct QuadParams {
  double albedo[3] = {0.9, 0.8, 0.7};
  double thickness = 0.5, attenuation_distance = 1;
  double attenuation_color[3] = {0.5, 0.25, 1};
  double transmission = 0.1;
  double transmission_color[3] = {1, 0.8, 0.6};
  double power = 2, distortion = 0.5, scale = 2;
  double intensity = 3.14159265358979323846;  // lux: pi -> scene colour 1 (intensity / pi)
  bool orthographic = true;
};

inline GltfWriter volume_quad(const QuadParams& q = {}) {
  GltfWriter w;
  const int pos = w.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  const int nrm = w.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int idx = w.accessor(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}, 5123, "SCALAR", 1);
  w.use_extension("KHR_materials_volume");
  w.use_extension("KHR_materials_diffuse_transmission");
  w.doc["materials"].push_back(
      {{"name", "jade"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {q.albedo[0], q.albedo[1], q.albedo[2], 1}}}},
       {"extensions",
        {{"KHR_materials_volume",
          {{"thicknessFactor", q.thickness},
           {"attenuationDistance", q.attenuation_distance},
           {"attenuationColor",
            {q.attenuation_color[0], q.attenuation_color[1], q.attenuation_color[2]}}}},
         {"KHR_materials_diffuse_transmission",
          {{"diffuseTransmissionFactor", q.transmission},
           {"diffuseTransmissionColorFactor",
            {q.transmission_color[0], q.transmission_color[1], q.transmission_color[2]}}}}}},
       {"extras", {{"ltrender", {{"power", q.power}, {"distortion", q.distortion}}}}}});
  w.doc["meshes"].push_back({{"name", "quad"},
                             {"primitives",
                              {{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}},
                                {"indices", idx},
                                {"material", 0}}}}});
  w.root({{"name", "Quad"}, {"mesh", 0}});
  // A directional light shines down its node's -Z: rotated 180 degrees about Y, it travels +Z.
  w.light({{"type", "directional"},
           {"intensity", q.intensity},
           {"extras", {{"ltrender", {{"scale", q.scale}}}}}});
  w.doc["nodes"].back()["rotation"] = {0, 1, 0, 0};
  if (q.orthographic) {
    w.doc["cameras"].push_back(
        {{"name", "front"},
         {"type", "orthographic"},
         {"orthographic", {{"xmag", 2}, {"ymag", 1.5}, {"znear", 0.1}, {"zfar", 10}}}});
  } else {
    w.doc["cameras"].push_back(
        {{"name", "front"},
         {"type", "perspective"},
         {"perspective", {{"yfov", 0.7}, {"aspectRatio", 4.0 / 3}, {"znear", 0.1}, {"zfar", 10}}}});
  }
  w.root({{"name", "Eye"}, {"camera", 0}, {"translation", {0, 0, 3}}});
  return w;
}

}  // namespace lt::test
