// One case of a regress run: rendered in its scene's session, compared with its golden, and (with
// --update) its golden written. The same in this process and in a worker (regress_workers.h).
#pragma once

#include <filesystem>

#include "regress/regress.h"
#include "render/session.h"

namespace lt {

CaseResult run_case(const RegressOptions& options, const std::filesystem::path& scene_file,
                    RenderSession& session, const RegressCase& regress_case);

// A case whose variant the scene cannot take exactly: nothing is rendered.
CaseResult skipped_case(const RegressOptions& options, const RegressCase& regress_case);

}  // namespace lt
