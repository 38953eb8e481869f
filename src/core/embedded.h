// Program sources (legacy_shaders/, combiners/) and the report page (src/report/page/) embedded at
// build time by cmake/embed_sources.cmake, keyed by their path relative to the repository root.
#pragma once

#include <map>
#include <string>

namespace lt::embedded {
const std::map<std::string, std::string>& sources();
}  // namespace lt::embedded
