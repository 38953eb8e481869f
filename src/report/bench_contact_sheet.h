// Which renders of a bench go on its contact sheet (contact.png), and where. Ordinarily one row
// per scene: the reference, then each path's default variant with its error heatmap (every
// variant is in index.html; all of them here would make a sheet too wide to look at). When the
// scenes are the talk's parameter figures (figure_pairs.h), one row per figure instead: the left
// scene's renders, then the right one's, side by side at the scenes' own size (up to 320x240),
// each captioned with the parameter and its value, as the talk's slides show them.
#pragma once

#include <filesystem>
#include <vector>

#include "report/bench.h"
#include "report/contact_sheet.h"

namespace lt {

// No rows: an empty sheet (nothing to draw).
ContactSheet bench_contact_sheet(const std::filesystem::path& out_dir,
                                 const std::vector<BenchRow>& rows);

}  // namespace lt
