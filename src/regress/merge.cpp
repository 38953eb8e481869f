#include "regress/merge.h"

#include <cctype>
#include <map>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/fs.h"
#include "metrics/compare_json.h"
#include "regress/case_record.h"
#include "regress/regress_plan.h"

namespace lt {

namespace {

struct ShardFile {
  fs::path file;
  nlohmann::ordered_json json;
  Shard shard;
};

ShardFile read_shard(const fs::path& file) {
  ShardFile s{file, {}, {}};
  const std::string text = read_input_file(file, InputKind::Scene);
  s.json = nlohmann::ordered_json::parse(text, nullptr, false);
  if (s.json.is_discarded() || !s.json.is_object() || !s.json.contains("cases") ||
      !s.json.contains("run") || !s.json.contains("shard"))
    throw InputError(file.string(), "", "not the --json of an ltrender regress run");
  try {
    s.shard = parse_shard(s.json.at("shard").get<std::string>());
  } catch (const InputError& e) {
    throw InputError(file.string(), "shard", e.what_only());
  }
  if (!s.json.at("complete").get<bool>())
    throw InputError(file.string(), "complete",
                     "shard " + s.shard.to_string() + " did not finish (its run was stopped)");
  return s;
}

// The case a record names, rebuilt from the record (a merge has no scenes to expand): its path
// from the registry, its tolerance from the comparison's thresholds.
RegressCase case_of(const nlohmann::ordered_json& record, const std::vector<std::string>& scenes) {
  RegressCase c;
  c.scene = record.at("scene").get<std::string>();
  c.scene_index =
      static_cast<size_t>(std::find(scenes.begin(), scenes.end(), c.scene) - scenes.begin());
  c.path = &find_path(record.at("path").get<std::string>());
  c.variant = record.at("variant").get<std::string>();
  c.default_variant = c.variant == c.path->variants.front().name;
  const auto& comparison = record.at("comparison");
  if (!comparison.is_null()) c.tolerance = tolerance_from_json(comparison.at("thresholds"));
  if (record.at("status").get<std::string>() == "skipped")
    c.skip_reason = record.at("message").get<std::string>();
  return c;
}

void copy_image(const fs::path& from, const fs::path& to) {
  write_atomically(to, [&](const fs::path& tmp) {
    std::error_code ec;
    fs::copy_file(from, tmp, fs::copy_options::overwrite_existing, ec);
    if (ec) throw InputError(from.string(), "", "cannot copy the shard's image: " + ec.message());
  });
}

}  // namespace

void check_name_option(const std::string& option, const std::string& value) {
  const bool fits =
      !value.empty() && value != "." && value != ".." &&
      std::all_of(value.begin(), value.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '-' || ch == '_';
      });
  if (!fits)
    throw InputError(option, value,
                     "may hold only letters, digits, '.', '-' and '_' (it names files and "
                     "JUnit classes)");
}

RegressRun merge_regress_shards(const MergeOptions& m, RegressOptions& o) {
  if (m.shards.empty()) throw InputError("SHARD.json", "", "no shard to merge");
  if (m.label) check_name_option("--label", *m.label);
  std::vector<ShardFile> shards;
  for (const fs::path& f : m.shards) shards.push_back(read_shard(f));
  check_output_file(m.junit_file, m.shards, m.report_dir);
  check_output_file(m.json_file, m.shards, m.report_dir);

  // One run: the first shard's run, count and goldens are every other's.
  const ShardFile& first = shards.front();
  std::map<int, const ShardFile*> by_index;
  for (const ShardFile& s : shards) {
    for (const char* key : {"run", "goldens", "label", "total_cases"}) {
      if (s.json.at(key) != first.json.at(key))
        throw InputError(s.file.string(), key,
                         "another run's shard: its " + std::string(key) + " differs from " +
                             first.file.string() + "'s");
    }
    if (s.shard.count != first.shard.count)
      throw InputError(s.file.string(), "shard",
                       "is shard " + s.shard.to_string() + ", " + first.file.string() + " of " +
                           std::to_string(first.shard.count) + " shards");
    const auto [it, fresh] = by_index.emplace(s.shard.index, &s);
    if (!fresh)
      throw InputError(
          s.file.string(), "shard",
          "shard " + s.shard.to_string() + " twice (also " + it->second->file.string() + ")");
  }
  for (int i = 1; i <= first.shard.count; ++i) {
    if (!by_index.count(i))
      throw InputError("SHARD.json", "",
                       "shard " + std::to_string(i) + "/" + std::to_string(first.shard.count) +
                           " is missing (" + std::to_string(shards.size()) + " of " +
                           std::to_string(first.shard.count) + " given)");
  }

  RegressRun run;
  run.shard = Shard{};
  run.total_cases = first.json.at("total_cases").get<size_t>();
  run.shard_cases = run.total_cases;
  run.complete = true;
  const auto& identity = first.json.at("run");
  try {
    run.scenes = identity.at("scenes").get<std::vector<std::string>>();
    run.scene_files = identity.at("scene_files").get<std::vector<std::string>>();
    run.requested = identity.at("paths").get<std::vector<std::string>>();
    run.width = identity.at("width").get<int>();
    o.golden_key = identity.at("golden_key").get<std::string>();
    run.height = identity.at("height").get<int>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(first.file.string(), "run", e.what());
  }
  o.goldens = first.json.at("goldens").get<std::string>();
  o.label = m.label ? *m.label : first.json.at("label").get<std::string>();
  o.junit_file = m.junit_file;
  o.json_file = m.json_file;
  o.report_dir = m.report_dir;
  o.width = run.width;
  o.height = run.height;

  // Shard I holds the cases at positions I-1, I-1+N, ... (shard.h): put each back in its place.
  const size_t n = static_cast<size_t>(first.shard.count);
  std::vector<std::optional<CaseResult>> placed(run.total_cases);
  std::vector<const ShardFile*> source(run.total_cases, nullptr);
  for (const auto& [index, s] : by_index) {
    const auto& cases = s->json.at("cases");
    const size_t expected =
        run.total_cases / n + (static_cast<size_t>(index - 1) < run.total_cases % n);
    if (cases.size() != expected)
      throw InputError(s->file.string(), "cases",
                       std::to_string(cases.size()) + " cases where shard " + s->shard.to_string() +
                           " of " + std::to_string(run.total_cases) + " has " +
                           std::to_string(expected));
    for (size_t k = 0; k < cases.size(); ++k) {
      const size_t position = static_cast<size_t>(index - 1) + k * n;
      const std::string where = "cases[" + std::to_string(k) + "]";
      try {
        placed[position] =
            case_result_from_record(cases[k], case_of(cases[k], run.scenes), s->file.string());
      } catch (const nlohmann::json::exception& e) {
        throw InputError(s->file.string(), where, e.what());
      } catch (const InputError& e) {
        throw InputError(s->file.string(), where, e.what_only());
      }
      source[position] = s;
      run.seconds = std::max(run.seconds, s->json.at("seconds").get<double>());
    }
  }
  // A case id twice (two shards of different runs that agree on everything else) is no run.
  std::map<std::string, size_t> seen;
  for (size_t p = 0; p < placed.size(); ++p) {
    const std::string id = placed[p]->regress_case.id();
    if (!seen.emplace(id, p).second)
      throw InputError(source[p]->file.string(), "cases", "case " + id + " twice");
  }

  // The images, from each shard's page (its "report", from the shard's folder), into ours.
  if (!o.report_dir.empty()) {
    for (size_t p = 0; p < placed.size(); ++p) {
      CaseResult& r = *placed[p];
      if (r.image.empty()) continue;
      const auto& report = source[p]->json.at("report");
      if (report.is_null())
        throw InputError(source[p]->file.string(), "report",
                         "the shard wrote no page (-o) for -o to take its images from");
      const fs::path from = source[p]->file.parent_path() / report.get<std::string>();
      for (const std::string* image : {&r.image, &r.golden_image, &r.heatmap}) {
        if (image->empty()) continue;
        check_input_file(from / *image, InputKind::Image);
      }
    }
    make_directory(o.report_dir / "images");
    for (size_t p = 0; p < placed.size(); ++p) {
      const CaseResult& r = *placed[p];
      const fs::path from = r.image.empty() ? fs::path()
                                            : source[p]->file.parent_path() /
                                                  source[p]->json.at("report").get<std::string>();
      for (const std::string* image : {&r.image, &r.golden_image, &r.heatmap}) {
        if (!image->empty()) copy_image(from / *image, o.report_dir / *image);
      }
    }
  }
  for (auto& r : placed) run.results.push_back(std::move(*r));
  return run;
}

}  // namespace lt
