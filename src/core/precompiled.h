// The standard headers and GLM that most of the core's ~200 files include, parsed once per build
// into a precompiled header (CMakeLists.txt: compile time is most of a fresh ./test.sh, issue 28).
// Headers with configuration macros (nlohmann JSON, tinygltf) stay out, so a file that
// configures one still sees its own configuration.
//
// Why the pragma: GCC 12 loses the system-header mark of code inlined from a precompiled header
// and prints its false -Warray-bounds / -Wstringop-overflow reports from <string> in our -Wall
// build; marking this header as a system header keeps them quiet, as they are without it.
#pragma once
#pragma GCC system_header

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
