// A .gltf or .glb file read through tinygltf, every byte through the input layer (core/fs.h):
// the file itself, and each external buffer or image it names (FsCallbacks), capped per file.
// Errors name the file and the JSON pointer of what is wrong (RFC 6901, "/accessors/3").
#pragma once

#include <tiny_gltf.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lt::gltf {

struct Document {
  std::filesystem::path path;
  tinygltf::Model model;
  // The document's JSON as written: extension objects (KHR_materials_volume, ...) are read from
  // it, and every property the importer does not map is listed from it (`ltrender info`).
  nlohmann::json json;
  // What tinygltf warned about while reading a file it accepted, one line each (`info`).
  std::vector<std::string> warnings;

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;
};

// True for the extensions load_scene hands to the glTF importer (.gltf, .glb; any case).
bool is_gltf_path(const std::filesystem::path& path);

// Reads and parses. Throws InputError(file, pointer, what) for: a file the input layer refuses,
// a GLB whose header, length or chunks disagree with the file (truncated), invalid JSON, a buffer
// or image that is missing or refused, a buffer shorter than its byteLength, and a required
// extension (extensionsRequired) the importer does not implement.
Document read_document(const std::filesystem::path& path);

}  // namespace lt::gltf
