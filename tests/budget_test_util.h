// Reading `ltrender budget --json` records (schema ltrender-budget-2, docs/budget.md) in tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace lt::test {

// `budget --json` prints one pretty-printed object per file, each closed by a "}" line.
inline std::vector<nlohmann::json> budget_records(const std::string& out) {
  std::vector<nlohmann::json> all;
  std::string record;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    record += line + "\n";
    if (line == "}") {
      all.push_back(nlohmann::json::parse(record));
      record.clear();
    }
  }
  EXPECT_TRUE(record.empty()) << "a record left open: " << record;
  return all;
}

// The resource `key` of one row (an element of "items"); null when the row has none.
inline nlohmann::json budget_resource(const nlohmann::json& item, const std::string& key) {
  for (const nlohmann::json& r : item["resources"]) {
    if (r["key"] == key) return r;
  }
  return nullptr;
}

// The most any row of the record uses of `key` (the worst pass's TEV stages, the frame's
// passes); -1 when no row counts it.
inline int budget_most(const nlohmann::json& record, const std::string& key) {
  int most = -1;
  for (const nlohmann::json& item : record["items"]) {
    const nlohmann::json r = budget_resource(item, key);
    if (!r.is_null()) most = std::max(most, r["used"].get<int>());
  }
  return most;
}

// The rows of one scope ("program", "pass", "material").
inline std::vector<nlohmann::json> budget_rows(const nlohmann::json& record,
                                               const std::string& scope) {
  std::vector<nlohmann::json> out;
  for (const nlohmann::json& item : record["items"]) {
    if (item["scope"] == scope) out.push_back(item);
  }
  return out;
}

}  // namespace lt::test
