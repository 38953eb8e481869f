#include "report/bench_compare.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/fixed.h"
#include "core/fs.h"

namespace lt {

namespace {

std::string row_key(const std::string& scene, const std::string& path, const std::string& v) {
  return scene + " | " + path + " | " + v;
}

}  // namespace

EarlierBench read_earlier_bench(const std::filesystem::path& report_json) {
  EarlierBench out;
  out.file = report_json;
  const std::string file = report_json.string();
  const std::string text = read_input_file(report_json, InputKind::Scene);
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    throw InputError(file, "", "not a bench report (invalid JSON)");
  if (!j.contains("rows") || !j["rows"].is_array())
    throw InputError(file, "rows", "not a bench report (no rows array)");
  for (std::size_t i = 0; i < j["rows"].size(); ++i) {
    const auto& r = j["rows"][i];
    const std::string at = "rows[" + std::to_string(i) + "]";
    for (const char* key : {"scene", "path", "variant"}) {
      if (!r.is_object() || !r.contains(key) || !r[key].is_string())
        throw InputError(file, at + "." + key, "expected a string");
    }
    if (!r.contains("ratio_interval")) {
      ++out.without_interval;
      continue;
    }
    const auto& iv = r["ratio_interval"];
    EarlierBench::Row row{r["scene"], r["path"], r["variant"], {}};
    for (const char* key : {"low", "high"}) {
      if (!iv.is_object() || !iv.contains(key) || !iv[key].is_number())
        throw InputError(file, at + ".ratio_interval." + key, "expected a number");
    }
    row.ratio.low = iv["low"];
    row.ratio.high = iv["high"];
    row.ratio.median = r.contains("ratio_to_flat") && r["ratio_to_flat"].is_number()
                           ? r["ratio_to_flat"].get<double>()
                           : (row.ratio.low + row.ratio.high) / 2;
    if (iv.contains("pairs") && iv["pairs"].is_number_unsigned()) row.ratio.pairs = iv["pairs"];
    out.rows.push_back(std::move(row));
  }
  return out;
}

std::size_t BenchComparison::slower() const {
  std::size_t n = 0;
  for (const auto& c : changed) n += c.slower();
  return n;
}

BenchComparison compare_bench(const EarlierBench& before, const std::vector<BenchRow>& now) {
  BenchComparison c;
  std::vector<bool> matched(before.rows.size(), false);
  for (const BenchRow& r : now) {
    const std::string key = row_key(r.scene, r.path, r.variant);
    bool found = false;
    for (std::size_t i = 0; i < before.rows.size(); ++i) {
      const auto& b = before.rows[i];
      if (matched[i] || row_key(b.scene, b.path, b.variant) != key) continue;
      matched[i] = found = true;
      const bool apart = r.ratio.low > b.ratio.high || r.ratio.high < b.ratio.low;
      if (apart) {
        c.changed.push_back({r.scene, r.path, r.variant, b.ratio, r.ratio});
      } else {
        ++c.unchanged;
      }
      break;
    }
    if (!found) ++c.only_now;
  }
  for (bool m : matched) c.only_before += !m;
  return c;
}

std::string comparison_markdown(const EarlierBench& before, const BenchComparison& c) {
  std::ostringstream s;
  s << "# ltrender bench against " << before.file.string() << "\n\n"
    << "A row changed when the two 95% intervals of its ratio to flat do not overlap. "
    << c.changed.size() << " changed (" << c.slower() << " slower), " << c.unchanged
    << " within the noise, " << c.only_now << " new, " << c.only_before << " gone";
  if (before.without_interval) s << ", " << before.without_interval << " without an interval";
  s << ".\n\n";
  if (!c.changed.empty()) {
    s << "| scene | path | variant | before | now | change |\n|---|---|---|---|---|---|\n";
    for (const auto& r : c.changed) {
      const double pct = r.before.median > 0 ? 100 * (r.after.median / r.before.median - 1) : 0;
      s << "| " << r.scene << " | " << r.path << " | " << r.variant << " | "
        << fixed(r.before.median, 3) << " (" << fixed(r.before.low, 3) << "-"
        << fixed(r.before.high, 3) << ") | " << fixed(r.after.median, 3) << " ("
        << fixed(r.after.low, 3) << "-" << fixed(r.after.high, 3) << ") | "
        << (r.slower() ? "slower " : "faster ") << (pct >= 0 ? "+" : "") << fixed(pct, 3)
        << "% |\n";
    }
  }
  return s.str();
}

}  // namespace lt
