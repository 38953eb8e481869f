// Output files are never half-written and inputs are never overwritten (cli.md): every writer
// goes through write_atomically, which writes a temporary beside the target and renames it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lt {

namespace fs = std::filesystem;

// Calls `write(tmp)` with a temporary path in the target's directory that keeps the target's
// extension (OpenImageIO and OpenMesh pick the format from it), then renames tmp -> target.
// If `write` throws, the temporary is removed and the target is left as it was. A process killed
// while writing leaves its temporary: the next write of the same target removes every one whose
// process is gone. Throws InputError if the target's directory does not exist, or with the
// rename's reason if it fails.
void write_atomically(const fs::path& target,
                      const std::function<void(const fs::path& tmp)>& write);

// A set of outputs written as one (bench's images and reports): `write(staging)` fills a
// staging directory beside `dir` (".out.ltrender-partial.1234" for out/), then every file is
// moved into `dir`, created if needed, and the staging directory removed. A failure removes
// the staging directory and leaves `dir` as it was; a process killed while writing leaves its
// staging directory, which the next write of `dir` removes once that process is gone. So a
// killed run never leaves new images beside an old report.
void write_directory_atomically(const fs::path& dir,
                                const std::function<void(const fs::path& staging)>& write);

// write_atomically of a text file (reports, XML, JSON). Throws InputError naming the target.
void write_text_file(const fs::path& target, const std::string& text);
// write_atomically of bytes as they are (a FIFO log), without a copy into a string.
void write_binary_file(const fs::path& target, std::span<const std::uint8_t> bytes);

// Every temporary's name holds this: ".out.png.ltrender-partial.1234.png" for out.png, pid 1234.
inline constexpr const char* kPartialOutputTag = ".ltrender-partial.";

// The temporary write_atomically uses for `target` in process `pid`.
fs::path partial_output_path(const fs::path& target, long pid);

// Throws InputError if `output` names the same file as one of `inputs` (an input is never
// overwritten, even through a different spelling of its path).
void ensure_not_an_input(const fs::path& output, const std::vector<fs::path>& inputs);

// The one input layer: every file ltrender reads goes through check_input_file or
// read_input_file. Only regular files are read (after following symlinks): a FIFO blocks
// forever, a device such as /dev/zero never ends, a directory is not a file. Each kind has a
// size cap far above any real input of its kind, so a wrong or hostile file is refused by its
// size instead of exhausting memory (docs/input-files.md).
enum class InputKind {
  Scene,    // scene JSON: 16 MiB
  Mesh,     // PLY, OBJ, OFF, STL, OM: 256 MiB
  Image,    // PNG, EXR, ... (compare, goldens): 512 MiB
  Program,  // GX program files and any other text input: 16 MiB
  Gltf,     // a .gltf or .glb and every buffer or image file it names: 256 MiB each
};

// The cap in bytes of one kind.
std::uintmax_t input_size_cap(InputKind kind);

// Throws InputError naming the file unless it exists, is a regular file and is within its
// kind's cap; returns its size. For readers that open the file by name (OpenImageIO, the OM
// reader); the others use read_input_file.
std::uintmax_t check_input_file(const fs::path& path, InputKind kind);

// check_input_file, then the whole file, read from the descriptor that was checked (a file
// swapped for a FIFO in between is still refused) and never beyond the cap (a file that grows
// while it is read is refused too). Throws InputError naming the file.
std::string read_input_file(const fs::path& path, InputKind kind);

// read_input_file(path, InputKind::Program): a text input other than a scene.
std::string read_text_file(const fs::path& path);

// The UTF-8 byte-order mark a Windows editor writes before text. Each text reader decides what
// it means as its model does: GCC and JSON readers skip it, Mesa's ARB parser ends its text there.
inline constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
inline bool starts_with_utf8_bom(std::string_view text) {
  return text.substr(0, kUtf8Bom.size()) == kUtf8Bom;
}

}  // namespace lt
