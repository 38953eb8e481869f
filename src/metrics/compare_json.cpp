#include "metrics/compare_json.h"

#include <limits>

namespace lt {

namespace {

// to_json writes an infinite value as null (JSON has no infinity).
double number_or_infinity(const nlohmann::ordered_json& j) {
  return j.is_null() ? std::numeric_limits<double>::infinity() : j.get<double>();
}

int channel_of_name(const std::string& name) {
  return name == "R" ? 0 : name == "G" ? 1 : name == "B" ? 2 : -1;
}

}  // namespace

ErrorStats error_stats_from_json(const nlohmann::ordered_json& j) {
  ErrorStats s;
  s.pixels = j.at("pixels").get<size_t>();
  s.max_lsb = j.at("max_lsb").get<double>();
  const auto& at = j.at("max_at");
  if (!at.is_null()) {
    s.max_x = at.at("x").get<int>();
    s.max_y = at.at("y").get<int>();
    s.max_channel = channel_of_name(at.at("channel").get<std::string>());
  }
  s.mean_lsb = j.at("mean_lsb").get<double>();
  s.rmse_lsb = j.at("rmse_lsb").get<double>();
  s.psnr_db = number_or_infinity(j.at("psnr_db"));
  s.p99_lsb = j.at("p99_lsb").get<double>();
  s.percent_over_1_lsb = j.at("percent_over_1_lsb").get<double>();
  s.percent_over_4_lsb = j.at("percent_over_4_lsb").get<double>();
  return s;
}

Tolerance tolerance_from_json(const nlohmann::ordered_json& j) {
  Tolerance t;
  t.fail_lsb = j.at("fail_lsb").get<double>();
  t.fail_percent = j.at("fail_percent").get<double>();
  t.hard_fail_lsb = number_or_infinity(j.at("hard_fail_lsb"));
  t.region = j.at("region").get<std::string>() == "image" ? Region::kImage : Region::kCovered;
  t.max_mismatch_percent = j.at("max_mismatch_percent").get<double>();
  t.warn_lsb = number_or_infinity(j.at("warn_lsb"));
  t.warn_percent = j.at("warn_percent").get<double>();
  t.hard_warn_lsb = number_or_infinity(j.at("hard_warn_lsb"));
  t.edge_shift_percent = j.at("edge_shift_percent").get<double>();
  return t;
}

Verdict verdict_from_json(const nlohmann::ordered_json& j) {
  Verdict v;
  v.pass = j.at("pass").get<bool>();
  v.failing_pixels = j.at("failing_pixels").get<size_t>();
  v.failing_percent = j.at("failing_percent").get<double>();
  v.hard_failing_pixels = j.at("hard_failing_pixels").get<size_t>();
  v.edge_shift_pixels = j.at("edge_shift_pixels").get<size_t>();
  v.shading_pixels = j.at("shading_pixels").get<size_t>();
  v.shading_max_lsb = j.at("shading_max_lsb").get<double>();
  v.edge_shifts_excused = j.at("edge_shifts_excused").get<bool>();
  // The comparison apply_tolerance makes, on the same doubles: the share of the region's pixels
  // the fail criterion judged (the shading ones when edge shifts are excused).
  const auto& thresholds = j.at("thresholds");
  const size_t pixels = j.at(thresholds.at("region").get<std::string>()).at("pixels").get<size_t>();
  const size_t judged = v.edge_shifts_excused ? v.shading_pixels : v.failing_pixels;
  const double judged_percent =
      pixels > 0 ? 100.0 * static_cast<double>(judged) / static_cast<double>(pixels) : 0.0;
  v.over_fail_percent = judged_percent > thresholds.at("fail_percent").get<double>();
  v.reasons = j.at("reasons").get<std::vector<std::string>>();
  v.warn = j.at("warn").get<bool>();
  v.warnings = j.at("warnings").get<std::vector<std::string>>();
  return v;
}

}  // namespace lt
