#include "report/bench_json.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/fs.h"

namespace lt {

namespace {

// JSON has no infinity: a PSNR of a perfect match (inf) is written as null and read back as inf.
nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json stats_json(const BenchRow& r) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : r.stats.set_fields()) j[name] = value;
  if (r.shading_mpixels_per_s) j["shading_mpixels_per_s"] = *r.shading_mpixels_per_s;
  return j;
}

nlohmann::json error_json(const ErrorStats& e) {
  return {{"max_lsb", e.max_lsb},
          {"max_at", {e.max_x, e.max_y, e.max_channel}},
          {"pixels", e.pixels},
          {"mean_lsb", e.mean_lsb},
          {"rmse_lsb", e.rmse_lsb},
          {"psnr_db", finite_or_null(e.psnr_db)},
          {"p99_lsb", e.p99_lsb},
          {"percent_over_1_lsb", e.percent_over_1_lsb},
          {"percent_over_4_lsb", e.percent_over_4_lsb}};
}

// Reads the keys of one object, each failure naming the file and the key as a JSON pointer.
class KeyReader {
 public:
  KeyReader(const nlohmann::json& row, const std::string& file, const std::string& pointer)
      : row_(row), file_(file), pointer_(pointer) {
    if (!row.is_object()) fail("", "is not an object");
  }

  const nlohmann::json& at(const nlohmann::json& parent, const std::string& key,
                           const std::string& where) const {
    if (!parent.is_object() || !parent.contains(key)) fail(where + "/" + key, "missing");
    return parent.at(key);
  }
  template <typename T>
  T get(const nlohmann::json& parent, const std::string& key, const std::string& where) const {
    const nlohmann::json& v = at(parent, key, where);
    try {
      return v.get<T>();
    } catch (const nlohmann::json::exception&) {
      fail(where + "/" + key, "has the wrong type");
    }
  }
  double number_or_inf(const nlohmann::json& parent, const std::string& key,
                       const std::string& where) const {
    const nlohmann::json& v = at(parent, key, where);
    return v.is_null() ? std::numeric_limits<double>::infinity() : get<double>(parent, key, where);
  }
  const nlohmann::json& row() const { return row_; }
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw InputError(file_, pointer_ + pointer, what);
  }

 private:
  const nlohmann::json& row_;
  std::string file_, pointer_;
};

ErrorStats error_from_json(const KeyReader& in, const nlohmann::json& e) {
  const std::string w = "/error";
  ErrorStats s;
  s.max_lsb = in.get<double>(e, "max_lsb", w);
  const auto at = in.get<std::vector<int>>(e, "max_at", w);
  if (at.size() != 3) in.fail(w + "/max_at", "is not [x, y, channel]");
  s.max_x = at[0];
  s.max_y = at[1];
  s.max_channel = at[2];
  s.pixels = in.get<std::size_t>(e, "pixels", w);
  s.mean_lsb = in.get<double>(e, "mean_lsb", w);
  s.rmse_lsb = in.get<double>(e, "rmse_lsb", w);
  s.psnr_db = in.number_or_inf(e, "psnr_db", w);
  s.p99_lsb = in.get<double>(e, "p99_lsb", w);
  s.percent_over_1_lsb = in.get<double>(e, "percent_over_1_lsb", w);
  s.percent_over_4_lsb = in.get<double>(e, "percent_over_4_lsb", w);
  return s;
}

}  // namespace

nlohmann::json bench_row_to_json(const BenchRow& r) {
  nlohmann::json x = {{"scene", r.scene},
                      {"path", r.path},
                      {"variant", r.variant},
                      {"ms_median", r.at_scene_size.median_ms},
                      {"ms_min", r.at_scene_size.min_ms},
                      {"ms_median_wide", r.at_wide.median_ms},
                      {"ms_min_wide", r.at_wide.min_ms},
                      {"ratio_to_flat", r.ratio_to_flat},
                      {"ratio_interval",
                       {{"median", r.ratio.median},
                        {"low", r.ratio.low},
                        {"high", r.ratio.high},
                        {"pairs", r.ratio.pairs},
                        {"wide", r.ratio.wide()},
                        {"settling_frames", r.settling_frames},
                        {"rounds", r.rounds}}},
                      {"image", r.image},
                      {"heatmap", r.heatmap},
                      {"size", {r.width, r.height}},
                      {"stats", stats_json(r)},
                      {"cost", r.cost}};
  if (r.work) {
    x["work"] = {{"ops", r.work->total()},
                 {"pixel_ops", r.work->pixel_ops},
                 {"vertex_ops", r.work->vertex_ops},
                 {"pixel_operation", r.work->pixel_operation},
                 {"vertex_operation", r.work->vertex_operation}};
  } else {
    x["work"] = {{"not_counted", r.work_not_counted}};
  }
  if (r.console) {
    nlohmann::json& c = x["console"];
    for (const auto& [name, field] : ConsoleBytes::kFields) c[name] = (*r.console).*field;
  }
  if (r.error) x["error"] = error_json(*r.error);
  if (r.error && r.edge_split) {
    // Beside the figures: the pixels over 1 LSB classed (reference_edge_split.h).
    x["error"]["edge_shift_pixels"] = r.edge_split->edge_shift_pixels;
    x["error"]["shading_pixels"] = r.edge_split->shading_pixels;
    x["error"]["shading_max_lsb"] = r.edge_split->shading_max_lsb;
  }
  return x;
}

BenchRow bench_row_from_json(const nlohmann::json& j, const std::string& file,
                             const std::string& pointer) {
  const KeyReader in(j, file, pointer);
  BenchRow r;
  r.scene = in.get<std::string>(j, "scene", "");
  r.path = in.get<std::string>(j, "path", "");
  r.variant = in.get<std::string>(j, "variant", "");
  r.at_scene_size = {in.get<double>(j, "ms_median", ""), in.get<double>(j, "ms_min", "")};
  r.at_wide = {in.get<double>(j, "ms_median_wide", ""), in.get<double>(j, "ms_min_wide", "")};
  r.ratio_to_flat = in.get<double>(j, "ratio_to_flat", "");
  const nlohmann::json& ri = in.at(j, "ratio_interval", "");
  r.ratio.median = in.get<double>(ri, "median", "/ratio_interval");
  r.ratio.low = in.get<double>(ri, "low", "/ratio_interval");
  r.ratio.high = in.get<double>(ri, "high", "/ratio_interval");
  r.ratio.pairs = in.get<std::size_t>(ri, "pairs", "/ratio_interval");
  r.settling_frames = in.get<std::size_t>(ri, "settling_frames", "/ratio_interval");
  r.rounds = in.get<int>(ri, "rounds", "/ratio_interval");
  r.image = in.get<std::string>(j, "image", "");
  r.heatmap = in.get<std::string>(j, "heatmap", "");
  const auto size = in.get<std::vector<int>>(j, "size", "");
  if (size.size() != 2) in.fail("/size", "is not [width, height]");
  r.width = size[0];
  r.height = size[1];
  const nlohmann::json& stats = in.at(j, "stats", "");
  for (const auto& [name, field] : FrameStats::kFields) {
    if (stats.contains(name)) r.stats.*field = in.get<double>(stats, name, "/stats");
  }
  if (stats.contains("shading_mpixels_per_s"))
    r.shading_mpixels_per_s = in.get<double>(stats, "shading_mpixels_per_s", "/stats");
  r.cost = in.get<std::string>(j, "cost", "");
  const nlohmann::json& work = in.at(j, "work", "");
  if (work.contains("not_counted")) {
    r.work_not_counted = in.get<std::string>(work, "not_counted", "/work");
  } else {
    FrameWork w;
    w.pixel_ops = in.get<double>(work, "pixel_ops", "/work");
    w.vertex_ops = in.get<double>(work, "vertex_ops", "/work");
    w.pixel_operation = in.get<std::string>(work, "pixel_operation", "/work");
    w.vertex_operation = in.get<std::string>(work, "vertex_operation", "/work");
    r.work = w;
  }
  if (j.contains("console")) {
    const nlohmann::json& c = j.at("console");
    ConsoleBytes bytes;
    for (const auto& [name, field] : ConsoleBytes::kFields)
      bytes.*field = in.get<std::size_t>(c, name, "/console");
    r.console = bytes;
  }
  if (j.contains("error")) {
    const nlohmann::json& e = j.at("error");
    r.error = error_from_json(in, e);
    // A report written before the split has none.
    if (e.contains("edge_shift_pixels")) {
      EdgeShiftSplit split;
      split.edge_shift_pixels = in.get<std::size_t>(e, "edge_shift_pixels", "/error");
      split.shading_pixels = in.get<std::size_t>(e, "shading_pixels", "/error");
      split.shading_max_lsb = in.get<double>(e, "shading_max_lsb", "/error");
      r.edge_split = split;
    }
  }
  return r;
}

nlohmann::json bench_report_json(const BenchOptions& o, const std::vector<BenchRow>& rows) {
  nlohmann::json j;
  j["frames"] = o.frames;
  j["warmup"] = o.warmup;
  j["wide"] = {o.wide_width, o.wide_height};
  j["min_time_s"] = o.min_time_s;
  j["target_interval"] = o.target_interval;
  j["max_time_s"] = o.max_time_s;
  j["timing_mode"] = to_string(o.timing_mode);
  j["rounds"] = o.rounds;
  j["timing_overrides"] = o.timing_overrides;
  j["llvmpipe_threads"] = o.llvmpipe_threads;
  j["pinning"] = o.pinning;
  j["cpu_threads"] = o.cpu_threads;
  j["rows"] = nlohmann::json::array();
  for (const BenchRow& r : rows) j["rows"].push_back(bench_row_to_json(r));
  return j;
}

BenchReportFile read_bench_report(const std::filesystem::path& report_json) {
  const std::string file = report_json.string();
  const nlohmann::json j =
      nlohmann::json::parse(read_input_file(report_json, InputKind::Scene), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(file, "", "not a JSON object");
  const KeyReader in(j, file, "");
  BenchReportFile out;
  out.pinning = in.get<std::string>(j, "pinning", "");
  out.llvmpipe_threads = in.get<std::string>(j, "llvmpipe_threads", "");
  out.cpu_threads = in.get<unsigned>(j, "cpu_threads", "");
  const nlohmann::json& rows = in.at(j, "rows", "");
  if (!rows.is_array()) throw InputError(file, "/rows", "is not an array");
  for (std::size_t i = 0; i < rows.size(); ++i)
    out.rows.push_back(bench_row_from_json(rows[i], file, "/rows/" + std::to_string(i)));
  return out;
}

}  // namespace lt
