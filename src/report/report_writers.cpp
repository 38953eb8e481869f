// The reports of `ltrender bench` (report.md, report.csv, report.json, chart.svg, contact.png,
// index.html): writers only, from the rows run_bench measured (bench.cpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/fixed.h"
#include "core/fs.h"
#include "core/markup.h"
#include "render/session.h"
#include "report/bench.h"
#include "report/bench_contact_sheet.h"
#include "report/bench_json.h"
#include "report/ground_truth_image.h"
#include "report/label_placement.h"
#include "report/report_page.h"
#include "report/tool_versions.h"

namespace lt {

namespace {

std::string fmt(double v, int prec = 2) {
  if (!std::isfinite(v)) return v > 0 ? "inf" : "nan";
  return fixed(v, prec);
}

// The error's pixels over 1 LSB as shading and edge shifts: "0.98 / 12 px".
std::string split_cell(const BenchRow& r) {
  if (!r.edge_split) return "-";
  return fmt(r.edge_split->shading_max_lsb) + " / " +
         std::to_string(r.edge_split->edge_shift_pixels) + " px";
}

std::string error_cell(const BenchRow& r, bool max) {
  if (!r.error) return "-";
  return fmt(max ? r.error->max_lsb : r.error->mean_lsb, max ? 2 : 3);
}

// The figures paths report through Path::frame_stats, in words, for the notes column.
std::string stats_note(const BenchRow& r) {
  std::string n;
  auto add = [&](const std::string& s) { n += (n.empty() ? "" : "; ") + s; };
  const FrameStats& st = r.stats;
  if (r.shading_mpixels_per_s) {
    const double threads = st.threads.value_or(1);
    add("CPU shading " + fmt(*r.shading_mpixels_per_s) + " Mpixels/s on " + fmt(threads, 0) +
        (threads == 1 ? " thread" : " threads"));
  }
  if (st.cpu_vertex_seconds)
    add("per-vertex CPU " + fmt(*st.cpu_vertex_seconds * 1e3) + " ms a frame");
  if (st.tev_stage_pixels) {
    add("TEV " + fmt(*st.tev_stage_pixels / 1e6) + " M stage-pixels, XF " +
        fmt(st.xf_light_vertices.value_or(0) / 1e3, 1) + " k light-vertices, CPU pixel stage " +
        fmt(st.tev_seconds.value_or(0) * 1e3) + " ms a frame");
  }
  if (st.nonfinite_pixels && *st.nonfinite_pixels > 0) {
    add(fmt(*st.nonfinite_pixels, 0) + " NaN/Inf pixels (drawn as the path's marker colour)");
  }
  if (st.cube_rebuild_seconds && *st.cube_rebuild_seconds > 0) {
    add("cube-map build " + fmt(*st.cube_rebuild_seconds * 1e3) +
        " ms (once per light/view/material change)");
  }
  return n;
}

// "1.82-1.95 (+-3.4%)", with *wide* when the interval is wider than +-10%.
std::string interval_cell(const RatioEstimate& e) {
  if (e.pairs == 0) return "-";
  return fmt(e.low) + "-" + fmt(e.high) + " (+-" + fmt(100 * e.relative_half_width(), 1) + "%" +
         (e.wide() ? ", *wide*" : "") + ")";
}

// "12.3 (11.1 + 1.2)": millions of operations a frame, pixel + vertex parts.
std::string work_cell(const BenchRow& r) {
  if (!r.work) return "-";
  return fmt(r.work->total() / 1e6) + " (" + fmt(r.work->pixel_ops / 1e6) + " + " +
         fmt(r.work->vertex_ops / 1e6) + ")";
}

// Which timing mode made the report and what it measured: "quick timing (bench --quick): 1
// round, at least 10 pairs and 0.25 s of each path, no more for the interval", then the options
// given after the mode ("; --max-time given").
std::string timing_summary(const BenchOptions& o) {
  std::ostringstream s;
  s << to_string(o.timing_mode) << " timing (bench --" << to_string(o.timing_mode)
    << "): " << o.rounds << (o.rounds == 1 ? " round" : " rounds") << ", at least " << o.frames
    << " pairs and " << fmt(o.min_time_s) << " s of each path";
  if (o.max_time_s > o.min_time_s) {
    s << ", then more while the ratio's interval is wider than +-" << fmt(100 * o.target_interval)
      << "%, up to " << fmt(o.max_time_s) << " s";
  } else {
    s << ", no more for the interval";
  }
  for (std::size_t i = 0; i < o.timing_overrides.size(); ++i)
    s << (i == 0 ? "; given: " : ", ") << o.timing_overrides[i];
  return s.str();
}

// Whether some row is a console path's, with its bytes (console_bytes.h).
bool has_console_rows(const std::vector<BenchRow>& rows) {
  return std::any_of(rows.begin(), rows.end(), [](const BenchRow& r) { return r.console; });
}

// The console's bytes of the rows that have them, beside their error: the cost axis a porter
// reads for the storage and formats of a console path (docs/bench.md).
std::string console_markdown(const std::vector<BenchRow>& rows) {
  if (!has_console_rows(rows)) return "";
  std::ostringstream s;
  s << "\n## The console's bytes\n\nWhat `ltrender budget SCENE --path P --variant V` counts "
       "for each console row, a frame: counts, not time (the console's time is not modelled). "
       "MEM1 = vertex arrays + display lists + textures + palettes.\n\n"
    << "| scene | path | variant | bytes a vertex | MEM1 bytes | FIFO bytes a frame | XF "
       "vertices a frame | triangles | max LSB | mean LSB |\n"
    << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& r : rows) {
    if (!r.console) continue;
    const ConsoleBytes& c = *r.console;
    s << "| " << r.scene << " | " << r.path << " | " << r.variant << " | " << c.vertex_bytes
      << " | " << c.mem1_bytes() << " | " << c.fifo_bytes << " | " << c.xf_vertices << " | "
      << c.triangles << " | " << error_cell(r, true) << " | " << error_cell(r, false) << " |\n";
  }
  return s.str();
}

std::string markdown(const BenchOptions& o, const std::vector<BenchRow>& rows) {
  std::ostringstream s;
  s << "# ltrender bench\n\n"
    << "Made with " << tool_versions_line() << ".\n\n"
    << "**" << timing_summary(o) << ".**\n\n"
    << "Frames, each bounded by glFinish: at the scene's size, median and min of " << o.frames
    << " after " << o.warmup << " warm-up; at " << o.wide_width << "x" << o.wide_height
    << ", each path in interleaved pairs with `flat` in the same session, over " << o.rounds
    << (o.rounds == 1 ? " round" : " rounds")
    << " (each in a session of its own), after a warm-up that lasts until the frame time settles; "
       "flat frames "
       "right after a path frame are not timed until flat is back within 10% of its level. "
       "`ratio` = median of the per-pair ratios; `95% interval` from "
       "order statistics, marked *wide* beyond +-10%. Cores: "
    << o.pinning << "; llvmpipe threads: " << o.llvmpipe_threads
    << "; CPU paths' threads: " << o.cpu_threads
    << ". Error: covered pixels against the reference, in LSB (1/255); of the pixels over 1 LSB, "
       "`edge shifts` are those where each image holds the other's value within one pixel (a "
       "silhouette or edge placed differently, as two rasterisers do) and `shading max` is the "
       "largest error of the rest (a changed shade): a large max with a small shading max is "
       "edges, not a broken shader (docs/regress.md, 'Edge shifts and shading').\n\n"
    << "| scene | path | variant | ms (scene size) median / min | ms (" << o.wide_width << "x"
    << o.wide_height
    << ") median / min | ratio to flat | 95% interval | max LSB | mean LSB | p99 LSB | "
       "% > 1 LSB | shading max LSB / edge shifts | cost | work (M ops) | notes |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& r : rows) {
    const std::string notes = stats_note(r);
    s << "| " << r.scene << " | " << r.path << " | " << r.variant << " | "
      << fmt(r.at_scene_size.median_ms) << " / " << fmt(r.at_scene_size.min_ms) << " | "
      << fmt(r.at_wide.median_ms) << " / " << fmt(r.at_wide.min_ms) << " | " << fmt(r.ratio_to_flat)
      << " | " << interval_cell(r.ratio) << " | " << error_cell(r, true) << " | "
      << error_cell(r, false) << " | " << (r.error ? fmt(r.error->p99_lsb) : "-") << " | "
      << (r.error ? fmt(r.error->percent_over_1_lsb, 3) : "-") << " | " << split_cell(r) << " | "
      << r.cost << " | " << work_cell(r) << " | " << notes << " |\n";
  }
  s << "\n`work`: the operations a frame executes at " << o.wide_width << "x" << o.wide_height
    << ", counted from the built programs and the pixels and vertices drawn (the same on every "
       "machine): pixels x fragment ALU+TEX (arbfp), combiner stages (combiners), TEV stages and "
       "vertices x XF lights (gx), CPU light evaluations (reference, half). GLSL has no count.\n";
  s << console_markdown(rows);
  s << "\n![speed against error](chart.svg)\n\n![work against error](chart_work.svg)\n\n"
       "Contact sheet: `contact.png` (one row per scene: "
       "the reference, then each path's render followed by its error heatmap, in the table's "
       "order; heatmap scale 0..8 LSB black-blue-green-yellow-red-white, grey = background; "
       "scenes that are the talk's figure pairs, `<fig>_<parameter>_a_<value>` then `_b_`, get "
       "one row per figure, left and right side by side) and `index.html` with labels.\n";
  return s.str();
}

std::string csv(const std::vector<BenchRow>& rows) {
  std::ostringstream s;
  s << "scene,path,variant,ms_median,ms_min,ms_median_wide,ms_min_wide,ratio_to_flat,max_lsb,"
       "mean_lsb,rmse_lsb,psnr_db,p99_lsb,percent_over_1_lsb,percent_over_4_lsb,"
       "shading_mpixels_per_s,cost,ratio_low,ratio_high,ratio_pairs,work_ops,work_pixel_ops,"
       "work_vertex_ops,settling_frames,edge_shift_pixels,shading_pixels,shading_max_lsb";
  for (const auto& [name, field] : ConsoleBytes::kFields) s << ",console_" << name;
  s << "\n";
  for (const BenchRow& r : rows) {
    s << r.scene << "," << r.path << "," << r.variant << "," << r.at_scene_size.median_ms << ","
      << r.at_scene_size.min_ms << "," << r.at_wide.median_ms << "," << r.at_wide.min_ms << ","
      << r.ratio_to_flat << ",";
    if (r.error) {
      s << r.error->max_lsb << "," << r.error->mean_lsb << "," << r.error->rmse_lsb << ","
        << (std::isfinite(r.error->psnr_db) ? std::to_string(r.error->psnr_db) : "inf") << ","
        << r.error->p99_lsb << "," << r.error->percent_over_1_lsb << ","
        << r.error->percent_over_4_lsb << ",";
    } else {
      s << ",,,,,,,";
    }
    if (r.shading_mpixels_per_s) s << *r.shading_mpixels_per_s;
    s << ",\"" << r.cost << "\"," << r.ratio.low << "," << r.ratio.high << "," << r.ratio.pairs
      << ",";
    if (r.work)
      s << r.work->total() << "," << r.work->pixel_ops << "," << r.work->vertex_ops;
    else
      s << ",,";
    s << "," << r.settling_frames << ",";
    if (r.edge_split)
      s << r.edge_split->edge_shift_pixels << "," << r.edge_split->shading_pixels << ","
        << r.edge_split->shading_max_lsb;
    else
      s << ",,";
    for (const auto& [name, field] : ConsoleBytes::kFields) {
      s << ",";
      if (r.console) s << (*r.console).*field;
    }
    s << "\n";
  }
  return s.str();
}

// What a chart's x axis shows: its words, and the figure of a row (none: the row is left out).
struct ChartAxis {
  std::string title, caption, name;  // "Speed"; "ms per frame at 1280x720"; "ms per frame"
  std::string label_unit;            // after a point's value in its label
  double label_scale;                // the point's value is divided by this in its label
  std::function<std::optional<double>(const BenchRow&)> value;
};

// One point per path and variant, over all scenes of the run (the table has every scene):
// x = geometric mean of the ms per frame at the wide size, y = the worst max LSB (filled) and the
// average mean LSB (ring). Both axes are logarithmic: times span orders of magnitude (the CPU
// paths), and so do errors, from the 0.5 LSB floor of 8-bit output to 100+ for sg-simplified.
// Errors under 0.1 LSB (the float outputs) sit on the bottom line.
std::string svg_chart(const std::vector<BenchRow>& rows, const ChartAxis& axis) {
  struct Point {
    std::string path, variant;
    double log_ms_sum = 0, worst_max = 0, mean_sum = 0;
    int n = 0;
  };
  std::vector<Point> points;
  for (const BenchRow& r : rows) {
    const std::optional<double> x = axis.value(r);
    if (!r.error || !x || *x <= 0) continue;
    auto it = std::find_if(points.begin(), points.end(), [&](const Point& p) {
      return p.path == r.path && p.variant == r.variant;
    });
    if (it == points.end()) it = points.insert(points.end(), Point{r.path, r.variant});
    it->log_ms_sum += std::log10(*x);
    it->worst_max = std::max(it->worst_max, r.error->max_lsb);
    it->mean_sum += r.error->mean_lsb;
    ++it->n;
  }
  // The list of numbered points beside the plot sets the height when it is the longer, and
  // the width when an entry is longer than its column holds (an added variant spells out every
  // axis: bench --add-variant gx:t=vertex:vtx=s16/auto:...): the plot keeps its 760 pixels.
  // ~6.5 pixels a character of 11-pixel DejaVu Sans (the widest of its lower case and digits);
  // the report page's self-test measures the drawn text against the chart's width.
  std::size_t longest_entry = 0;
  for (const Point& p : points)
    longest_entry = std::max(longest_entry, p.path.size() + p.variant.size() + 5);
  const double L = 70, T = 40, B = 60;
  const double R = std::max(270.0, 16 + 6.5 * static_cast<double>(longest_entry) + 10);
  const double W = L + 760 + R;
  const double H = std::max(600.0, T + 20 + 15.0 * static_cast<double>(points.size()) + B);
  const double y_floor = 0.1;
  double lx0 = 1e30, lx1 = -1e30, ymax = 1;
  for (const Point& p : points) {
    lx0 = std::min(lx0, p.log_ms_sum / p.n);
    lx1 = std::max(lx1, p.log_ms_sum / p.n);
    ymax = std::max(ymax, p.worst_max);
  }
  if (points.empty()) lx0 = 0, lx1 = 1;
  lx0 = std::floor(lx0);
  lx1 = std::max(lx0 + 1, std::ceil(lx1));
  const double ly0 = std::log10(y_floor), ly1 = std::ceil(std::log10(ymax));
  auto X = [&](double log_ms) { return L + (log_ms - lx0) / (lx1 - lx0) * (W - L - R); };
  auto Y = [&](double lsb) {
    return H - B - (std::log10(std::max(lsb, y_floor)) - ly0) / (ly1 - ly0) * (H - T - B);
  };
  static const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                  "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  // A path's colour is its place in the registry, not in this chart's points: the work chart
  // has no glsl points (Mesa counts no GLSL instructions), and numbering the paths it does have
  // gave arbfp the speed chart's glsl red beside it on the report page.
  std::map<std::string, std::string> colour;
  for (const Point& p : points) colour[p.path] = palette[7];  // a path the registry lacks
  for (size_t i = 0; i < all_paths().size(); ++i) {
    const std::string& name = all_paths()[i].get().name;
    if (colour.count(name)) colour[name] = palette[i % 8];
  }
  std::ostringstream s;
  // The viewBox lets the report page scale a chart wider than its column down to fit.
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
    << "' viewBox='0 0 " << W << " " << H
    << "' font-family='sans-serif' font-size='11'>\n<rect width='100%' height='100%' "
       "fill='white'/>\n"
    << "<text x='" << L << "' y='18' font-size='14'>" << axis.title
    << " against error, per path and variant over all scenes</text>\n<text x='" << L
    << "' y='33'>x: geometric mean " << axis.caption << " (log); y: worst max LSB (filled) and "
    << "average mean LSB (ring), log</text>\n";
  for (double e = lx0; e <= lx1; e += 1) {
    for (int m = 1; m < 10; ++m) {
      const double v = e + std::log10(m);
      if (v > lx1) break;
      s << "<line x1='" << X(v) << "' x2='" << X(v) << "' y1='" << T << "' y2='" << H - B
        << "' stroke='" << (m == 1 ? "#bbb" : "#eee") << "'/>\n";
      if (m == 1) {
        s << "<text x='" << X(v) - 10 << "' y='" << H - B + 18 << "'>" << std::pow(10.0, e)
          << "</text>\n";
      }
    }
  }
  for (double e = ly0; e <= ly1; e += 1) {
    const double v = std::pow(10.0, e);
    s << "<line x1='" << L << "' x2='" << W - R << "' y1='" << Y(v) << "' y2='" << Y(v)
      << "' stroke='#ddd'/><text x='" << L - 45 << "' y='" << Y(v) + 4 << "'>"
      << (e == ly0 ? "&lt;= " : "") << v << "</text>\n";
  }
  // The 8-bit floor and the 2 LSB bar, for reading the chart at a glance.
  for (const auto& [v, label] :
       {std::pair<double, const char*>{0.5, "0.5 LSB: 8-bit floor"}, {2.0, "2 LSB"}}) {
    s << "<line x1='" << L << "' x2='" << W - R << "' y1='" << Y(v) << "' y2='" << Y(v)
      << "' stroke='#888' stroke-dasharray='4 3'/><text x='" << W - R - 120 << "' y='" << Y(v) - 3
      << "' fill='#666'>" << label << "</text>\n";
  }
  s << "<text x='" << (L + W - R) / 2 - 40 << "' y='" << H - 15 << "'>" << axis.name << "</text>\n"
    << "<text transform='translate(18," << H / 2 << ") rotate(-90)'>error (LSB)</text>\n";
  // Each point is numbered; the numbers are placed clear of every marker and of each other
  // (label_placement.h), and the list beside the plot names them. Hovering a point names it too
  // (<title>, and data-label for the report page's tooltip).
  const double dashed_label_w = 120, digit_w = 7, label_h = 12;
  std::vector<Box> markers;
  std::vector<LabelRequest> requests;
  for (const Point& p : points) {
    const double x = X(p.log_ms_sum / p.n);
    markers.push_back({x - 6, Y(p.worst_max) - 6, 12, 12});
    markers.push_back({x - 5, Y(p.mean_sum / p.n) - 5, 10, 10});
    const auto digits = static_cast<double>(std::to_string(requests.size() + 1).size());
    requests.push_back({x, Y(p.worst_max), digits * digit_w + 2, label_h});
  }
  for (double v : {0.5, 2.0})
    markers.push_back({W - R - 120, Y(v) - 14, dashed_label_w, label_h + 2});
  const std::vector<Box> labels = place_labels(requests, markers, {L, T, W - L - R, H - T - B});
  for (size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    const std::string& c = colour[p.path];
    const double x = X(p.log_ms_sum / p.n), mean = p.mean_sum / p.n;
    const std::string number = std::to_string(i + 1);
    const std::string label = number + ": " + p.path + " " + p.variant + ": " +
                              fmt(std::pow(10.0, p.log_ms_sum / p.n) / axis.label_scale) +
                              axis.label_unit + ", worst max " + fmt(p.worst_max) +
                              ", average mean " + fmt(mean, 3) + " LSB";
    const Box& b = labels[i];
    const double cx = b.x + b.w / 2, cy = b.y + b.h / 2;
    s << "<g data-label='" << markup_escape(label) << "'><title>" << markup_escape(label)
      << "</title>";
    // A leader line where the number had to move away from its point.
    if (std::hypot(cx - x, cy - Y(p.worst_max)) > 16) {
      s << "<line x1='" << x << "' y1='" << Y(p.worst_max) << "' x2='" << cx << "' y2='" << cy
        << "' stroke='" << c << "' stroke-width='0.6'/>";
    }
    s << "<circle cx='" << x << "' cy='" << Y(p.worst_max) << "' r='5' fill='" << c << "'/>"
      << "<circle cx='" << x << "' cy='" << Y(mean) << "' r='4' fill='none' stroke='" << c
      << "' stroke-width='1.5'/>"
      << "<text x='" << b.x + 1 << "' y='" << b.y + b.h - 2 << "' fill='" << c << "'>" << number
      << "</text></g>\n";
    s << "<text x='" << W - R + 16 << "' y='" << T + 14 + static_cast<double>(i) * 15 << "' fill='"
      << c << "'>" << number << "  " << markup_escape(p.path + " " + p.variant) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

ChartAxis time_axis(const BenchOptions& o) {
  return {"Speed",
          "ms per frame at " + std::to_string(o.wide_width) + "x" + std::to_string(o.wide_height),
          "ms per frame",
          " ms",
          1.0,
          [](const BenchRow& r) -> std::optional<double> { return r.at_wide.median_ms; }};
}

// The machine-independent twin of the time chart (frame_work.h).
ChartAxis work_axis(const BenchOptions& o) {
  return {"Work",
          "operations per frame at " + std::to_string(o.wide_width) + "x" +
              std::to_string(o.wide_height) + ", counted",
          "operations per frame",
          " M ops",
          1e6,
          [](const BenchRow& r) -> std::optional<double> {
            if (!r.work) return std::nullopt;
            return r.work->total();
          }};
}

// The console's bytes (console_bytes.h), for the rows of a console path: FIFO bytes a frame, what
// the CPU writes to the GP every frame, the figure every way of sending vertices has (docs/bench.md
// says why this one and not MEM1). Counts, not time: the console's time is not modelled.
ChartAxis console_axis() {
  return {"Console bytes",
          // Short enough for the chart's width, as the other two axes' lines are.
          "FIFO bytes a frame, counted; console time not modelled", "FIFO bytes a frame",
          " KB FIFO", 1e3, [](const BenchRow& r) -> std::optional<double> {
            if (!r.console) return std::nullopt;
            return static_cast<double>(r.console->fifo_bytes);
          }};
}

void write_contact_sheet(const BenchOptions& o, const std::vector<BenchRow>& rows) {
  const ContactSheet sheet = bench_contact_sheet(o.out_dir, rows);
  if (sheet.row_labels.empty()) return;
  write_image(o.out_dir / "contact.png", draw_contact_sheet(sheet));
}

// The report page (report_page.h): one card per row, flipping with the scene's reference.
ReportPage bench_page(const BenchOptions& o, const std::vector<BenchRow>& rows) {
  ReportPage page;
  page.title = "ltrender bench";
  page.summary = std::to_string(rows.size()) +
                 " renders; error against the reference over "
                 "covered pixels in LSB of 8 bits; ms = median of the timed frames at " +
                 std::to_string(o.wide_width) + "x" + std::to_string(o.wide_height) +
                 " (at least " + std::to_string(o.frames) + ", in pairs with flat; " + o.pinning +
                 "); " + timing_summary(o);
  page.chart_svg = svg_chart(rows, time_axis(o)) + svg_chart(rows, work_axis(o));
  if (has_console_rows(rows)) page.chart_svg += svg_chart(rows, console_axis());
  for (const BenchRow& r : rows) {
    PageCard c;
    c.scene = r.scene;
    c.path = r.path;
    c.variant = r.variant;
    c.image = r.image;
    if (find_path(r.path).role != PathRole::GroundTruth) {
      c.flip_image = ground_truth_image(r.scene, ".png");
      c.flip_label = ground_truth_label();
    }
    c.heatmap = r.heatmap;
    c.width = r.width;
    c.height = r.height;
    c.figures = {{"ms", fmt(r.at_wide.median_ms)}, {"ratio to flat", fmt(r.ratio_to_flat)}};
    if (r.error) {
      c.error_lsb = r.error->max_lsb;
      c.figures.push_back({"max", fmt(r.error->max_lsb) + " LSB"});
      c.figures.push_back({"mean", fmt(r.error->mean_lsb, 3) + " LSB"});
      c.figures.push_back({"p99", fmt(r.error->p99_lsb) + " LSB"});
      c.figures.push_back({"% > 1 LSB", fmt(r.error->percent_over_1_lsb, 3)});
    }
    if (r.edge_split) {
      c.figures.push_back({"shading max", fmt(r.edge_split->shading_max_lsb) + " LSB"});
      c.figures.push_back(
          {"edge shifts", std::to_string(r.edge_split->edge_shift_pixels) + " px > 1 LSB"});
    }
    if (!r.cost.empty()) c.figures.push_back({"cost", r.cost});
    if (r.console) {
      c.figures.push_back({"FIFO a frame", std::to_string(r.console->fifo_bytes) + " bytes"});
      c.figures.push_back({"MEM1", std::to_string(r.console->mem1_bytes()) + " bytes"});
      c.figures.push_back({"XF vertices", std::to_string(r.console->xf_vertices)});
    }
    if (const std::string notes = stats_note(r); !notes.empty()) c.notes.push_back(notes);
    page.cards.push_back(std::move(c));
  }
  return page;
}

}  // namespace

void write_bench_reports(const BenchOptions& o, const std::vector<BenchRow>& rows) {
  write_text_file(o.out_dir / "report.md", markdown(o, rows));
  write_text_file(o.out_dir / "report.csv", csv(rows));
  // Here, not in bench_report_json, which also writes each bench job's rows: one measurement.
  nlohmann::json json = bench_report_json(o, rows);
  json["tool_versions"] = tool_versions_line();
  write_text_file(o.out_dir / "report.json", json.dump(2) + "\n");
  write_text_file(o.out_dir / "chart.svg", svg_chart(rows, time_axis(o)));
  write_text_file(o.out_dir / "chart_work.svg", svg_chart(rows, work_axis(o)));
  if (has_console_rows(rows))
    write_text_file(o.out_dir / "chart_console.svg", svg_chart(rows, console_axis()));
  write_report_page(o.out_dir, bench_page(o, rows));
  write_contact_sheet(o, rows);
}

}  // namespace lt
