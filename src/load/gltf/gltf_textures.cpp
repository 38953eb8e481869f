#include "load/gltf/gltf_textures.h"

#include <cmath>

#include "core/error.h"
#include "core/temp_file.h"
#include "load/albedo_map.h"
#include "model/texture_sampling.h"

namespace lt::gltf {

namespace {
using json = nlohmann::json;

// A sampler's wrapS/wrapT: the GL enums glTF names [glTF 2.0 spec 3.8.4 Samplers]; REPEAT when
// absent.
TextureWrap wrap_of(const Document& doc, const json& sampler, const char* key,
                    const std::string& pointer) {
  if (!sampler.contains(key)) return TextureWrap::Repeat;
  const json& v = sampler[key];
  if (v == 33071) return TextureWrap::ClampToEdge;
  if (v == 33648) return TextureWrap::MirroredRepeat;
  if (v == 10497) return TextureWrap::Repeat;
  doc.fail(
      pointer + "/" + key,
      "must be 33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT) or 10497 (REPEAT), not " + v.dump());
}

// KHR_texture_transform: T * R * S with rotation counter-clockwise in UV space
// [KHR_texture_transform README, "Overview"]. Its own texCoord overrides the textureInfo's.
std::optional<glm::dmat3> texture_transform(const Document& doc, const json& info,
                                            const std::string& pointer, int& set, Notes& notes) {
  if (!info.contains("extensions") || !info["extensions"].contains("KHR_texture_transform"))
    return std::nullopt;
  const json& t = info["extensions"]["KHR_texture_transform"];
  const std::string tp = pointer + "/extensions/KHR_texture_transform";
  if (!t.is_object()) doc.fail(tp, "expected an object");
  for (auto it = t.begin(); it != t.end(); ++it) {
    if (it.key() != "offset" && it.key() != "rotation" && it.key() != "scale" &&
        it.key() != "texCoord" && it.key() != "extras" && it.key() != "extensions")
      doc.fail(tp + "/" + it.key(), "unknown key (offset, rotation, scale, texCoord)");
  }
  const std::string file = doc.path.string();
  const auto offset = bounded_numbers(t, "offset", 2, {0, 0}, -1e6, 1e6, file, tp);
  const double rotation = bounded_number(t, "rotation", 0, -1e6, 1e6, file, tp);
  const auto scale = bounded_numbers(t, "scale", 2, {1, 1}, -1e6, 1e6, file, tp);
  if (t.contains("texCoord"))
    set = static_cast<int>(bounded_number(t, "texCoord", 0, 0, 255, file, tp));
  // glm is column-major: m[column][row].
  const double c = std::cos(rotation), s = std::sin(rotation);
  const glm::dmat3 T(1, 0, 0, 0, 1, 0, offset[0], offset[1], 1);
  const glm::dmat3 R(c, -s, 0, s, c, 0, 0, 0, 1);
  const glm::dmat3 S(scale[0], 0, 0, 0, scale[1], 0, 0, 0, 1);
  notes.push_back("applied " + tp + ": offset " + json(offset).dump() + ", rotation " +
                  json(rotation).dump() + ", scale " + json(scale).dump() +
                  " to the primitives' UVs");
  return T * R * S;
}

}  // namespace

glm::dvec2 importer_uv(const TextureCoordinates& c, glm::dvec2 gltf_uv) {
  if (c.transform) gltf_uv = glm::dvec2(*c.transform * glm::dvec3(gltf_uv, 1));
  // glTF's UV origin is the image's top-left (v grows downwards); TriangleMesh::uvs follow
  // OpenGL (v = 0 at the bottom row, model/texture_sampling.h).
  return {gltf_uv.x, 1 - gltf_uv.y};
}

TextureDescription describe_base_colour_texture(const Document& doc, const std::string& pointer,
                                                Notes& notes) {
  const std::string file = doc.path.string();
  const json& info = at_pointer(doc.json, pointer);
  if (!info.is_object() || !info.contains("index") || !info["index"].is_number_integer())
    doc.fail(pointer, "expected a textureInfo with an integer index");
  TextureDescription out;
  out.pointer = pointer;
  const int index = info["index"].get<int>();
  out.coordinates.set =
      static_cast<int>(bounded_number(info, "texCoord", 0, 0, 255, file, pointer));
  out.coordinates.transform = texture_transform(doc, info, pointer, out.coordinates.set, notes);
  if (index < 0 || index >= static_cast<int>(doc.model.textures.size()))
    doc.fail(pointer + "/index", "no such texture");
  const std::string tp = "/textures/" + std::to_string(index);
  const json& texture = at_pointer(doc.json, tp);
  if (!texture.contains("source"))
    doc.fail(tp, "has no source image: an image of an extension (" +
                     (texture.contains("extensions") ? texture["extensions"].dump()
                                                     : std::string("none named")) +
                     ") is not decoded, only PNG and JPEG");
  out.image = doc.model.textures[static_cast<size_t>(index)].source;
  if (out.image < 0 || out.image >= static_cast<int>(doc.model.images.size()))
    doc.fail(tp + "/source", "no such image");
  if (texture.contains("sampler")) {
    const int si = doc.model.textures[static_cast<size_t>(index)].sampler;
    if (si < 0 || si >= static_cast<int>(doc.model.samplers.size()))
      doc.fail(tp + "/sampler", "no such sampler");
    const std::string sp = "/samplers/" + std::to_string(si);
    const json& sampler = at_pointer(doc.json, sp);
    out.wrap_s = wrap_of(doc, sampler, "wrapS", sp);
    out.wrap_t = wrap_of(doc, sampler, "wrapT", sp);
    // magFilter NEAREST (9728) and the mipmapped minFilters (9984..9987): every path samples
    // level 0 with GL_LINEAR, as the thickness maps are sampled; said, not hidden.
    const int mag = sampler.value("magFilter", 9729), min = sampler.value("minFilter", 9729);
    if (mag != 9729 || min != 9729)
      notes.push_back("approximated " + sp + " magFilter " + std::to_string(mag) + ", minFilter " +
                      std::to_string(min) +
                      ": sampled GL_LINEAR (9729) without mipmaps on every path");
  }
  out.notes_at = notes.size();
  return out;
}

std::shared_ptr<const TextureMap> load_base_colour_texture(const Document& doc,
                                                           const TextureDescription& texture,
                                                           Notes& notes) {
  const std::string file = doc.path.string();
  const std::string ip = "/images/" + std::to_string(texture.image);
  const tinygltf::Image& image = doc.model.images[static_cast<size_t>(texture.image)];
  // PNG and JPEG are the image formats glTF core allows [glTF 2.0 spec 3.8.3 Images]; the
  // signature decides the extension the image reader goes by.
  const auto& b = image.image;
  const bool png = b.size() >= 8 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G';
  const bool jpeg = b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF;
  if (!png && !jpeg) doc.fail(ip, "is neither PNG nor JPEG (the image formats glTF 2.0 allows)");
  const TempFile temporary("gltf-image", png ? ".png" : ".jpg", b.data(), b.size());
  if (!temporary.written()) doc.fail(ip, "could not be written to a temporary file for decoding");
  // Errors name the image's pointer, not the temporary file.
  std::shared_ptr<TextureMap> map;
  try {
    map = load_albedo_map(temporary.path(), file, ip, texture.wrap_s, texture.wrap_t);
  } catch (const InputError& e) {
    std::string what = e.what_only();
    const std::string tmp = temporary.path().string();
    for (size_t at = what.find(tmp); at != std::string::npos; at = what.find(tmp))
      what.replace(at, tmp.size(), "the image");
    doc.fail(ip, what);
  }
  map->file = image.uri.empty() || image.uri.rfind("data:", 0) == 0
                  ? std::filesystem::path(file + "#" + ip)
                  : doc.path.parent_path() / image.uri;
  notes.push_back("mapped " + texture.pointer + " -> albedo map " + ip + " (" +
                  std::to_string(map->texture.width) + "x" + std::to_string(map->texture.height) +
                  ", sRGB decoded, wrap " + model::wrap_name(texture.wrap_s) + " x " +
                  model::wrap_name(texture.wrap_t) + ", TEXCOORD_" +
                  std::to_string(texture.coordinates.set) + ")");
  note_unmapped_keys(at_pointer(doc.json, texture.pointer), texture.pointer,
                     {"index", "texCoord", "KHR_texture_transform"}, "not part of the term", notes);
  return map;
}

}  // namespace lt::gltf
