// The figures of compare.h's to_json read back: what a regress worker sends its parent and what
// `regress merge` reads from each shard's JSON is rebuilt from them, so the page and the JUnit of
// a merge say exactly what the shards measured. Throws nlohmann::json::exception for a record of
// another shape (the caller names the file).
#pragma once

#include <nlohmann/json.hpp>

#include "metrics/compare.h"

namespace lt {

// One region's figures ("covered" or "image" of to_json).
ErrorStats error_stats_from_json(const nlohmann::ordered_json& stats);
// to_json's "thresholds".
Tolerance tolerance_from_json(const nlohmann::ordered_json& thresholds);
// The verdict of a whole to_json object.
Verdict verdict_from_json(const nlohmann::ordered_json& comparison);

}  // namespace lt
