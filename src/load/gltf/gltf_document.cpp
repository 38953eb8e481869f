#include "load/gltf/gltf_document.h"

#include <cstring>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/file_name.h"
#include "core/fs.h"
#include "scene/object_reader.h"

namespace lt::gltf {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The extensions whose meaning the importer implements (docs/scenes-and-gltf.md): a file that
// requires any other is refused, since glTF 2.0 §3.12 says a loader that does not support a
// required extension must not load the asset.
const std::set<std::string> kImplementedExtensions = {
    "KHR_materials_volume", "KHR_materials_diffuse_transmission", "KHR_lights_punctual",
    "KHR_texture_transform"};

// What FsCallbacks reads: every file through read_input_file, its refusal kept so that the error
// can name the file's own reason ("is a FIFO", "over the 256 MiB limit") and the buffer's pointer.
struct FileReads {
  std::string failed_file, failed_reason;
};

// Every name "exists" to tinygltf: read_whole_file then asks the input layer, which says why a
// file cannot be read (not found, a FIFO, over the cap) in the project's words.
bool file_exists(const std::string&, void*) {
  return true;
}

std::string keep_path(const std::string& path, void*) {
  return path;  // no `~` or environment expansion: a path in a file means that path
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  try {
    const std::string bytes = read_input_file(path, InputKind::Gltf);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    auto* reads = static_cast<FileReads*>(user);
    reads->failed_file = path;
    reads->failed_reason = e.what_only();
    if (err) *err = e.what_only();
    return false;
  }
}

bool write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;  // reading never writes
}

// Images are kept as their encoded bytes (as_is), whether they come from a file, a data URI or
// a GLB buffer view: a base colour texture is decoded when its material is mapped
// (gltf_textures.h), through the same image reader as every other input; an unused image is
// never decoded.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

std::uint32_t le32(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + i]);
  return v;
}

// GLB layout (glTF 2.0 §4.4): a 12-byte header (magic "glTF", version 2, total length), then a
// JSON chunk and an optional BIN chunk, each with an 8-byte header (length, type). Checked here
// so that a truncated file is named as such, not as tinygltf's "Invalid glTF binary."; returns
// the JSON chunk.
std::string glb_json_chunk(const fs::path& path, const std::string& bytes) {
  const std::string file = path.string();
  auto fail = [&](const std::string& what) -> std::string {
    throw InputError(file, "(GLB header)", what);
  };
  if (bytes.size() < 20)
    fail("truncated: " + std::to_string(bytes.size()) + " bytes, a GLB has at least 20");
  if (bytes.compare(0, 4, "glTF") != 0) fail("not a GLB file (no \"glTF\" magic)");
  if (le32(bytes, 4) != 2)
    fail("GLB version " + std::to_string(le32(bytes, 4)) + ", only 2 is read");
  const std::uint64_t length = le32(bytes, 8);
  if (length > bytes.size()) {
    fail("truncated: the header declares " + std::to_string(length) + " bytes, the file has " +
         std::to_string(bytes.size()));
  }
  const std::uint64_t json_length = le32(bytes, 12);
  if (le32(bytes, 16) != 0x4E4F534Au) fail("the first chunk is not JSON");
  if (20 + json_length > length) {
    fail("truncated: the JSON chunk declares " + std::to_string(json_length) +
         " bytes, the file holds " + std::to_string(length - 20) + " after the header");
  }
  const std::uint64_t bin_at = 20 + json_length;
  if (bin_at + 8 <= length) {
    const std::uint64_t bin_length = le32(bytes, static_cast<std::size_t>(bin_at));
    if (bin_at + 8 + bin_length > length) {
      fail("truncated: the BIN chunk declares " + std::to_string(bin_length) +
           " bytes, the file holds " + std::to_string(length - bin_at - 8));
    }
  }
  return bytes.substr(20, static_cast<std::size_t>(json_length));
}

// tinygltf's error text says which buffer or image failed only in words; the pointer is found
// from the uri of the file that the callbacks could not read (or that does not exist).
std::string pointer_of_uri(const json& doc, const std::string& err) {
  for (const char* collection : {"buffers", "images"}) {
    if (!doc.contains(collection) || !doc[collection].is_array()) continue;
    const json& items = doc[collection];
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (!items[i].is_object() || !items[i].contains("uri") || !items[i]["uri"].is_string())
        continue;
      const std::string uri = items[i]["uri"].get<std::string>();
      if (!uri.empty() && uri.rfind("data:", 0) != 0 && err.find(uri) != std::string::npos) {
        return "/" + std::string(collection) + "/" + std::to_string(i);
      }
    }
  }
  return "";
}

// tinygltf ends its messages with newlines and may join several: one line for the CLI.
std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace

void Document::fail(const std::string& pointer, const std::string& what) const {
  throw InputError(path.string(), pointer, what);
}

bool is_gltf_path(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".gltf" || ext == ".glb";
}

Document read_document(const fs::path& path) {
  Document doc;
  doc.path = path;
  const std::string file = path.string();
  const std::string bytes = read_input_file(path, InputKind::Gltf);
  // A .glb is recognised by its magic, not its name (glTF 2.0 §4.4.2).
  const bool binary = bytes.compare(0, 4, "glTF") == 0;
  const std::string json_text = binary ? glb_json_chunk(path, bytes) : bytes;
  doc.json = parse_json_input(json_text, file);
  if (!doc.json.is_object()) throw InputError(file, "", "the glTF JSON is not an object");

  if (doc.json.contains("extensionsRequired") && doc.json["extensionsRequired"].is_array()) {
    const json& required = doc.json["extensionsRequired"];
    for (std::size_t i = 0; i < required.size(); ++i) {
      const std::string name =
          required[i].is_string() ? required[i].get<std::string>() : required[i].dump();
      if (!kImplementedExtensions.count(name)) {
        doc.fail(
            "/extensionsRequired/" + std::to_string(i),
            "required extension " + name + " is not supported (supported: " +
                "KHR_materials_volume, KHR_materials_diffuse_transmission, KHR_lights_punctual, "
                "KHR_texture_transform)");
      }
    }
  }

  FileReads reads;
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&file_exists, &keep_path, &read_whole_file, &write_nothing, &reads});
  loader.SetImageLoader(&keep_encoded_image, nullptr);
  std::string err, warn;
  const std::string base_dir = path.parent_path().string();
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&doc.model, &err, &warn, data,
                                           static_cast<unsigned int>(bytes.size()), base_dir)
             : loader.LoadASCIIFromString(&doc.model, &err, &warn, bytes.data(),
                                          static_cast<unsigned int>(bytes.size()), base_dir);
  // Images that cannot be read are only a warning to tinygltf (they are optional to render):
  // here every file named is read, so a missing image is an error like a missing buffer.
  const std::string message = one_line(err + (ok ? warn : ""));
  if (!ok || !reads.failed_file.empty() ||
      warn.find("Failed to load external") != std::string::npos) {
    const std::string pointer = pointer_of_uri(doc.json, err + warn);
    if (!reads.failed_file.empty())
      doc.fail(pointer, reads.failed_file + " " + reads.failed_reason);
    doc.fail(pointer, message.empty() ? "tinygltf could not read the file" : message);
  }
  std::istringstream lines(warn);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) doc.warnings.push_back("tinygltf: " + line);
  }
  return doc;
}

}  // namespace lt::gltf
