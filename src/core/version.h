// ltrender's own version: project(VERSION) of CMakeLists.txt, with `git describe` when built from
// a checkout ("0.1.0 (git 6831d86-dirty)"). Defined in build/generated/version.cpp
// (cmake/version.cmake), the one file a commit recompiles.
#pragma once

namespace lt {

const char* ltrender_version();

}  // namespace lt
