// `ltrender export gx` (gx.md §2), behind the gx PathInfo's export interface (path.h): the
// generated programs as libogc C with their figures, as a module a game runs every frame, or as
// the frame(s) a Dolphin FIFO log holds.
#pragma once

#include <string>
#include <vector>

#include "paths/path.h"

namespace lt::gx {

std::vector<ExportFormat> gx_export_formats();
std::string gx_export_variant(const PathInfo& gx, const ExportRequest& request);
std::string gx_export_scene(const PathInfo& gx, const ExportRequest& request,
                            const ExportInput& input);

}  // namespace lt::gx
