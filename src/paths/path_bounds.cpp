#include "paths/path_bounds.h"

#include <nlohmann/json.hpp>

#include "core/embedded.h"
#include "core/fixed.h"

namespace lt {

namespace {

constexpr const char* kBoundsFile = "src/paths/bounds/path_bounds.json";

std::vector<PathBound> parse_path_bounds() {
  const auto j = nlohmann::json::parse(embedded::sources().at(kBoundsFile));
  std::vector<PathBound> out;
  for (const auto& r : j.at("bounds")) {
    PathBound b;
    b.path = r.at("path");
    b.variant = r.at("variant");
    b.scene = r.at("scene");
    b.max_lsb = r.at("max");
    b.mean_lsb = r.at("mean");
    if (r.contains("p99")) b.p99_lsb = r.at("p99").get<double>();
    if (r.contains("image_max")) b.image_max_lsb = r.at("image_max").get<double>();
    if (r.contains("min_mean")) b.min_mean_lsb = r.at("min_mean").get<double>();
    b.reason = r.at("reason");
    out.push_back(std::move(b));
  }
  return out;
}

// "covered max 3.20 LSB over the bound's 1.00" when `measured` is over `bound`.
void check_at_most(std::vector<std::string>& out, const char* what, double measured, double bound) {
  if (measured > bound)
    out.push_back(std::string(what) + " " + fixed(measured, 2) + " LSB over the bound's " +
                  fixed(bound, 2));
}

}  // namespace

const std::vector<PathBound>& path_bounds() {
  static const std::vector<PathBound> rows = parse_path_bounds();
  return rows;
}

const PathBound* find_path_bound(const std::string& path, const std::string& variant,
                                 const std::string& scene) {
  const PathBound* any = nullptr;
  for (const PathBound& r : path_bounds()) {
    if (r.path != path || r.variant != variant) continue;
    if (r.scene == scene) return &r;
    if (r.scene == "*") any = &r;
  }
  return any;
}

const PathBound* general_path_bound(const std::string& path, const std::string& variant) {
  for (const PathBound& r : path_bounds())
    if (r.path == path && r.variant == variant && r.scene == "*") return &r;
  return nullptr;
}

std::vector<std::string> pixel_bound_violations(const PathBound& b, const Comparison& c) {
  std::vector<std::string> out;
  check_at_most(out, "covered max", c.covered.max_lsb, b.max_lsb);
  if (b.p99_lsb) check_at_most(out, "covered p99", c.covered.p99_lsb, *b.p99_lsb);
  if (b.image_max_lsb) check_at_most(out, "image max", c.image.max_lsb, *b.image_max_lsb);
  return out;
}

std::vector<std::string> bound_violations(const PathBound& b, const Comparison& c) {
  std::vector<std::string> out = pixel_bound_violations(b, c);
  check_at_most(out, "covered mean", c.covered.mean_lsb, b.mean_lsb);
  if (b.min_mean_lsb && c.covered.mean_lsb < *b.min_mean_lsb)
    out.push_back("covered mean " + fixed(c.covered.mean_lsb, 3) + " LSB under the bound's least " +
                  fixed(*b.min_mean_lsb, 3));
  return out;
}

}  // namespace lt
