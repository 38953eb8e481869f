#pragma once
// Where this build's files are: the source tree (scenes/, meshes/, tests/data/) and the build
// directory (the image module, the ltrender binary, what tests leave for a person to read).
//
// Why functions and not -D defines: CMake writes them into one generated file
// (build/generated/build_paths.cpp, cmake/build_paths.cmake), so no other compile command names
// a checkout's absolute path. Every other object is then the same for every checkout of the
// tree, and ccache (with CCACHE_BASEDIR) shares them between worktrees.

#include <filesystem>

namespace lt::build_paths {

// The source tree this binary was configured from.
std::filesystem::path source_dir();
// The build directory (where ltrender, the test binaries and libltrender_imageio.so are).
std::filesystem::path binary_dir();
// The ltrender executable of this build.
std::filesystem::path ltrender_binary();

}  // namespace lt::build_paths
