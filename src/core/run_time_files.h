// Where ltrender finds what it reads at run time: the image module, and the data (the scenes with
// advise's hard cases and bench's demo scenes, the meshes, the examples, the docs).
//
// A binary in the build directory it was configured in (ltrender, the test and bench binaries)
// reads them from that build and its source tree (build_paths.h). Any other binary is installed
// (`cmake --install`, the Debian package) and reads them relative to its own folder only
// (install_layout.h): a moved prefix keeps working, and a copied binary without its prefix fails
// naming the file it looked for rather than reading the tree of the machine that built it.
#pragma once

#include <filesystem>

namespace lt::run_time_files {

// The running executable (/proc/self/exe).
std::filesystem::path executable();
// True when the running executable sits in the build directory of this build.
bool from_build_tree();
// The folder holding scenes/, meshes/, examples/ and docs/.
std::filesystem::path data_dir();
// The folder holding the image module (libltrender_imageio.so).
std::filesystem::path module_dir();

}  // namespace lt::run_time_files
