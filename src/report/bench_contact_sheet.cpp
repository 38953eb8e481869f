#include "report/bench_contact_sheet.h"

#include <algorithm>
#include <string>
#include <utility>

#include "report/figure_pairs.h"
#include "report/ground_truth_image.h"

namespace lt {

namespace {

using Column = std::pair<std::string, std::string>;  // path, variant

// The reference's render of a scene: the float image, clamped when the sheet is drawn.
std::filesystem::path reference_image(const std::filesystem::path& out_dir,
                                      const std::string& scene) {
  return out_dir / ground_truth_image(scene, ".exr");
}

// The reference, then each port's default variant the rows have, in the rows' order; with_baseline:
// the baseline's too (flat shows the covered pixels, the ordinary sheet has always had it).
std::vector<Column> default_columns(const std::vector<BenchRow>& rows, bool with_baseline) {
  const PathInfo& reference = path_with_role(PathRole::GroundTruth);
  std::vector<Column> columns = {{reference.name, reference.variants.front().name}};
  for (const BenchRow& r : rows) {
    const PathInfo& info = find_path(r.path);
    if (info.role == PathRole::GroundTruth || info.variants.front().name != r.variant) continue;
    if (info.role == PathRole::Baseline && !with_baseline) continue;
    const Column column{r.path, r.variant};
    if (std::find(columns.begin(), columns.end(), column) == columns.end())
      columns.push_back(column);
  }
  return columns;
}

// The renders of one scene into cells[first .. first + columns.size()).
void fill_scene(std::vector<ContactCell>& cells, std::size_t first,
                const std::vector<Column>& columns, const std::string& scene,
                const std::vector<BenchRow>& rows, const std::filesystem::path& out_dir,
                const std::string& caption) {
  cells[first].image = reference_image(out_dir, scene);
  for (std::size_t c = 0; c < columns.size(); ++c) cells[first + c].caption = caption;
  for (const BenchRow& r : rows) {
    if (r.scene != scene) continue;
    const auto column = std::find(columns.begin() + 1, columns.end(), Column{r.path, r.variant});
    if (column == columns.end()) continue;
    ContactCell& cell = cells[first + static_cast<std::size_t>(column - columns.begin())];
    cell.image = out_dir / r.image;
    if (!r.heatmap.empty()) cell.heatmap = out_dir / r.heatmap;
  }
}

std::vector<std::string> scenes_in_order(const std::vector<BenchRow>& rows) {
  std::vector<std::string> scenes;
  for (const BenchRow& r : rows)
    if (scenes.empty() || scenes.back() != r.scene) scenes.push_back(r.scene);
  return scenes;
}

ContactSheet sheet_by_scene(const std::filesystem::path& out_dir, const std::vector<BenchRow>& rows,
                            const std::vector<std::string>& scenes) {
  ContactSheet sheet;
  const std::vector<Column> columns = default_columns(rows, true);
  sheet.column_labels = columns;
  sheet.column_labels.front().second = "(float, clamped)";
  for (const std::string& scene : scenes) {
    sheet.row_labels.push_back(scene);
    sheet.cells.emplace_back(columns.size());
    fill_scene(sheet.cells.back(), 0, columns, scene, rows, out_dir, "");
  }
  return sheet;
}

// The talk's figures at the size their scenes were rendered (320x240), not thumbnails: a pair
// is read by comparing detail, which 160x120 loses.
constexpr int kFigureMaxWidth = 320, kFigureMaxHeight = 240;

ContactSheet sheet_by_figure(const std::filesystem::path& out_dir,
                             const std::vector<BenchRow>& rows,
                             const std::vector<std::string>& scenes,
                             const std::vector<FigureRow>& figures) {
  ContactSheet sheet;
  // The baseline's flat colour says nothing about a parameter.
  const std::vector<Column> columns = default_columns(rows, false);
  for (const char* side : {"left", "right"}) {
    for (const Column& c : columns) {
      const bool reference = c.first == path_with_role(PathRole::GroundTruth).name;
      sheet.column_labels.push_back({side, reference ? c.first : c.first + " " + c.second});
    }
  }
  sheet.thumb_width = sheet.thumb_height = 0;
  for (const BenchRow& r : rows) {
    sheet.thumb_width = std::max(sheet.thumb_width, std::min(r.width, kFigureMaxWidth));
    sheet.thumb_height = std::max(sheet.thumb_height, std::min(r.height, kFigureMaxHeight));
  }
  for (const FigureRow& f : figures) {
    sheet.row_labels.push_back(f.label);
    sheet.cells.emplace_back(2 * columns.size());
    for (std::size_t side = 0; side < f.scenes.size(); ++side) {
      fill_scene(sheet.cells.back(), side * columns.size(), columns, scenes[f.scenes[side]], rows,
                 out_dir, f.captions[side]);
    }
  }
  return sheet;
}

}  // namespace

ContactSheet bench_contact_sheet(const std::filesystem::path& out_dir,
                                 const std::vector<BenchRow>& rows) {
  const std::vector<std::string> scenes = scenes_in_order(rows);
  const std::vector<FigureRow> figures = figure_rows(scenes);
  if (figures.empty()) return sheet_by_scene(out_dir, rows, scenes);
  return sheet_by_figure(out_dir, rows, scenes, figures);
}

}  // namespace lt
