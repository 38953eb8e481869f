#include "regress/case_record.h"

#include "metrics/compare_json.h"

namespace lt {

nlohmann::ordered_json case_record(const CaseResult& r) {
  const RegressCase& c = r.regress_case;
  nlohmann::ordered_json images = nullptr;
  if (!r.image.empty())
    images = {{"render", r.image}, {"golden", r.golden_image}, {"heatmap", r.heatmap}};
  return {{"id", c.id()},
          {"scene", c.scene},
          {"path", c.path->name},
          {"variant", c.variant},
          {"status", to_string(r.status)},
          {"failed", is_failure(r.status)},
          {"golden", r.golden.string()},
          {"message", r.message},
          {"seconds", r.seconds},
          {"edge_shift_pixels", r.verdict.edge_shift_pixels},
          {"shading_pixels", r.verdict.shading_pixels},
          {"comparison", r.comparison_json},
          {"width", r.width},
          {"height", r.height},
          {"images", images},
          {"details", r.details}};
}

CaseResult case_result_from_record(const nlohmann::ordered_json& j, const RegressCase& c,
                                   const std::string& file) {
  CaseResult r;
  r.regress_case = c;
  r.status = case_status_from_string(j.at("status").get<std::string>(), file, c.id() + ".status");
  r.golden = j.at("golden").get<std::string>();
  r.message = j.at("message").get<std::string>();
  r.seconds = j.at("seconds").get<double>();
  r.comparison_json = j.at("comparison");
  if (!r.comparison_json.is_null()) {
    r.verdict = verdict_from_json(r.comparison_json);
    r.figures = error_stats_from_json(
        r.comparison_json.at(r.comparison_json.at("thresholds").at("region").get<std::string>()));
  }
  r.width = j.at("width").get<int>();
  r.height = j.at("height").get<int>();
  const auto& images = j.at("images");
  if (!images.is_null()) {
    r.image = images.at("render").get<std::string>();
    r.golden_image = images.at("golden").get<std::string>();
    r.heatmap = images.at("heatmap").get<std::string>();
  }
  r.details = j.at("details").get<std::string>();
  return r;
}

}  // namespace lt
