// A finished case as JSON: the record `--json` lists under "cases", what a worker process sends
// its parent, and what `regress merge` reads back from each shard. One form for all three, so a
// merge or a worker's case says exactly what an unsharded, in-process run would.
#pragma once

#include <nlohmann/json.hpp>

#include "regress/regress.h"

namespace lt {

nlohmann::ordered_json case_record(const CaseResult& result);

// The result a record describes, for `regress_case` (which the reader has from its own list or
// rebuilds from the record). Throws nlohmann::json::exception for a record of another shape and
// InputError (naming `file`) for an unknown status.
CaseResult case_result_from_record(const nlohmann::ordered_json& record,
                                   const RegressCase& regress_case, const std::string& file);

}  // namespace lt
