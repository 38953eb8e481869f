// Output files are never half-written and inputs are never overwritten (cli.md): every writer
// goes through write_atomically, which writes a temporary beside the target and renames it.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lt {

namespace fs = std::filesystem;

// Calls `write(tmp)` with a temporary path in the target's directory that keeps the target's
// extension (OpenImageIO and OpenMesh pick the format from it), then renames tmp -> target.
// If `write` throws, the temporary is removed and the target is left as it was.
// Throws InputError if the target's directory does not exist.
void write_atomically(const fs::path& target,
                      const std::function<void(const fs::path& tmp)>& write);

// Throws InputError if `output` names the same file as one of `inputs` (an input is never
// overwritten, even through a different spelling of its path).
void ensure_not_an_input(const fs::path& output, const std::vector<fs::path>& inputs);

// Reads a whole text file; throws InputError naming the file if it cannot.
std::string read_text_file(const fs::path& path);

}  // namespace lt
