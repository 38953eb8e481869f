#include "core/error.h"
#include "paths/arbfp/arbfp_path.h"
#include "paths/combiners/combiners_path.h"
#include "paths/flat/flat_path.h"
#include "paths/glsl/glsl_path.h"
#include "paths/gx/gx_path.h"
#include "paths/half/half_path.h"
#include "paths/path.h"
#include "paths/reference/reference_path.h"

namespace lt {

const std::vector<std::reference_wrapper<const PathInfo>>& all_paths() {
  static const std::vector<std::reference_wrapper<const PathInfo>> paths = {
      reference_path_info(), glsl_path_info(), flat_path_info(), arbfp_path_info(),
      combiners_path_info(), half_path_info(), gx_path_info(),
  };
  return paths;
}

const PathInfo& find_path(const std::string& name) {
  std::string names;
  for (const PathInfo& p : all_paths()) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw InputError("--path", name, "unknown path (valid: " + names + ")");
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

const PathInfo& default_budget_path() {
  for (const PathInfo& p : all_paths()) {
    if (!p.budget_profiles.empty()) return p;
  }
  check_failed("budget_profiles", __FILE__, __LINE__, "no path has a budget");
}

std::string resolve_variant(const PathInfo& path, const std::string& requested) {
  if (requested.empty()) return path.variants.front().name;
  return path.parse_variant(requested);
}

void throw_unknown_variant(const std::string& path, const std::vector<VariantInfo>& variants,
                           const std::string& requested) {
  std::string names;
  for (const VariantInfo& v : variants) names += (names.empty() ? "" : ", ") + v.name;
  throw InputError("--variant", requested,
                   "path " + path + " has no such variant (valid: " + names + ")");
}

// The defaults of what a path may leave out: listed variant names, no refusal; the capabilities
// a path declares by its data (budget_profiles, program files, writes_fifo_log, export_formats)
// and overrides.
std::string PathInfo::parse_variant(const std::string& variant) const {
  for (const VariantInfo& v : variants) {
    if (v.name == variant) return variant;
  }
  throw_unknown_variant(name, variants, variant);
}

std::string PathInfo::refusal(const Scene&, const std::string&) const {
  return "";
}

budget::Report PathInfo::budget(const Scene&, const std::string&, const std::string&) const {
  check_failed("budget_profiles.empty()", __FILE__, __LINE__,
               "path " + name + " has no budget (callers check budget_profiles)");
}

budget::Report PathInfo::budget_file(const std::string&, const std::string&) const {
  check_failed("program_extensions.empty()", __FILE__, __LINE__,
               "path " + name + " reads no program files (callers check program_extensions)");
}

bool PathInfo::reads_program_text(const std::string&) const { return false; }

std::vector<std::uint8_t> PathInfo::fifo_log(const Scene&, const std::string&, const PathOptions&,
                                             int, int) const {
  check_failed("!writes_fifo_log", __FILE__, __LINE__,
               "path " + name + " writes no FIFO log (callers check writes_fifo_log)");
}

std::string PathInfo::export_variant(const ExportRequest& r) const {
  const char* given = !r.program_file.empty()  ? "--program"
                      : r.frames != 1          ? "--frames"
                      : r.width || r.height    ? "--width/--height"
                      : !r.light_range.empty() ? "--light-range"
                                               : nullptr;
  if (given) throw InputError("export", given, "path " + name + "'s export takes no " + given);
  return resolve_variant(*this, r.variant);
}

std::string PathInfo::export_scene(const ExportRequest&, const ExportInput&) const {
  check_failed("export_formats.empty()", __FILE__, __LINE__,
               "path " + name + " exports nothing (callers check export_formats)");
}

}  // namespace lt
