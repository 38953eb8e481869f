// The report page a person reads (index.html in a report folder): one self-contained HTML file
// (CSS and JavaScript inline, no network) with its images as files beside it. Per scene, one
// card per path and variant with its figures; a click or `f` flips a card's image with the image
// it is judged against at the same spot; `h` lays the error heatmap over it; zoom is pixelated;
// cards sort and filter by error, path and verdict, failures first. `ltrender bench` and
// `ltrender regress` write it from their own results; the page's HTML, CSS and JavaScript are
// files of their own (src/report/page/), embedded at build time.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lt {

struct PageCard {
  std::string scene, path, variant;
  std::string image;                   // relative to the page
  std::string flip_image, flip_label;  // what the card is judged against; empty: nothing
  std::string heatmap;                 // empty: none
  std::string verdict;  // "pass", "fail", "missing", "skipped", ... or empty (bench: measured)
  std::optional<double> error_lsb;                           // the figure cards sort by: max LSB
  std::vector<std::pair<std::string, std::string>> figures;  // label, value, as shown
  std::vector<std::string> notes;  // reasons, the command that makes a missing golden
  int width = 0, height = 0;       // of the image, in pixels
};

struct ReportPage {
  std::string title;
  std::string summary;          // one line under the title
  std::vector<PageCard> cards;  // grouped by scene in first-appearance order
  std::string chart_svg;        // inline speed-against-error chart; empty: none
};

// dir/index.html, atomically.
void write_report_page(const std::filesystem::path& dir, const ReportPage& page);

}  // namespace lt
