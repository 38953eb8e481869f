#include <algorithm>

#include "core/error.h"
#include "core/find_named.h"
#include "paths/arbfp/arbfp_path.h"
#include "paths/combiners/combiners_path.h"
#include "paths/flat/flat_path.h"
#include "paths/glsl/glsl_path.h"
#include "paths/gx/gx_path.h"
#include "paths/half/half_path.h"
#include "paths/path.h"
#include "paths/reference/reference_path.h"

namespace lt {

const std::vector<PathInfo>& all_paths() {
  static const std::vector<PathInfo> paths = {
      reference_path_info(), glsl_path_info(), flat_path_info(), arbfp_path_info(),
      combiners_path_info(), half_path_info(), gx_path_info(),
  };
  return paths;
}

const PathInfo& find_path(const std::string& name) {
  return find_named(all_paths(), name, "--path", "path");
}

const PathInfo& path_with_role(PathRole role) {
  const PathInfo* found = nullptr;
  for (const PathInfo& p : all_paths()) {
    if (p.role != role) continue;
    LT_CHECK(!found, "two paths share a role that has one path");
    found = &p;
  }
  LT_CHECK(found, "no path has the role");
  return *found;
}

std::string resolve_variant(const PathInfo& path, const std::string& requested) {
  if (requested.empty()) return path.variants.front().name;
  if (path.parse_variant) return path.parse_variant(requested);
  std::string names;
  for (const VariantInfo& v : path.variants) {
    if (v.name == requested) return requested;
    names += (names.empty() ? "" : ", ") + v.name;
  }
  throw InputError("--variant", requested,
                   "path " + path.name + " has no such variant (valid: " + names + ")");
}

}  // namespace lt
