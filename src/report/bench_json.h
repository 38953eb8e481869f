// report.json, the one JSON form of a bench: the run's settings and its rows, written by the
// report and read back by `bench --jobs` (each job process writes its scene's rows in this form,
// the parent reads them: cli/bench_jobs.h). A row read back is the row that was written
// (tests/bench_json_test.cpp round-trips every field).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/bench.h"

namespace lt {

nlohmann::json bench_report_json(const BenchOptions& options, const std::vector<BenchRow>& rows);

nlohmann::json bench_row_to_json(const BenchRow& row);

// Throws InputError naming `file` and the key (under `pointer`, e.g. "/rows/3") when a row is
// not of that form.
BenchRow bench_row_from_json(const nlohmann::json& row, const std::string& file,
                             const std::string& pointer);

// What a report.json says of how it was run, and its rows.
struct BenchReportFile {
  std::string pinning, llvmpipe_threads;
  unsigned cpu_threads = 0;
  std::vector<BenchRow> rows;
};
BenchReportFile read_bench_report(const std::filesystem::path& report_json);

}  // namespace lt
