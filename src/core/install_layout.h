// Where an installed ltrender's files are, relative to the folder of the binary (GNUInstallDirs:
// "../lib/ltrender", "../share/ltrender"). Relative, so a prefix moved elsewhere keeps working.
// Defined in build/generated/install_layout.cpp (cmake/install.cmake), like build_paths.h.
#pragma once

namespace lt::install_layout {

const char* module_dir_from_bin();
const char* data_dir_from_bin();

}  // namespace lt::install_layout
