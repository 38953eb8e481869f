#include "report/report_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "core/embedded.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/markup.h"
#include "metrics/heatmap.h"
#include "report/tool_versions.h"

namespace lt {

namespace {

std::string esc(const std::string& s) {
  return markup_escape(s);
}

const std::string& template_file(const std::string& name) {
  const auto& sources = embedded::sources();
  const auto it = sources.find("src/report/page/" + name);
  LT_CHECK(it != sources.end(), "page template not embedded: " + name);
  return it->second;
}

// Replaces each {{key}} of the template in one pass, so that text put in (a scene named
// "{{title}}") is never read as a placeholder. Every key must be known (our bug otherwise).
std::string fill(const std::string& text, const std::map<std::string, std::string>& values) {
  std::string out;
  size_t at = 0;
  for (size_t open; (open = text.find("{{", at)) != std::string::npos;) {
    const size_t close = text.find("}}", open);
    LT_CHECK(close != std::string::npos, "page template has an unclosed {{");
    const auto it = values.find(text.substr(open + 2, close - open - 2));
    LT_CHECK(it != values.end(),
             "page template has an unknown " + text.substr(open, close - open + 2));
    out.append(text, at, open - at).append(it->second);
    at = close + 2;
  }
  return out.append(text, at, std::string::npos);
}

std::string css_colour(const float rgb[3]) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "rgb(%d,%d,%d)", static_cast<int>(std::lround(rgb[0] * 255)),
                static_cast<int>(std::lround(rgb[1] * 255)),
                static_cast<int>(std::lround(rgb[2] * 255)));
  return buf;
}

// The heatmap's scale as the ramp itself (heatmap_colour sampled), with the report's marks.
std::string legend_html() {
  std::string stops;
  for (int i = 0; i <= 16; ++i) {
    float rgb[3];
    heatmap_colour(kHeatmapMaxLsb * i / 16.0, kHeatmapMaxLsb, rgb);
    if (i) stops += ",";
    stops += css_colour(rgb);
  }
  std::ostringstream s;
  s << "<div class=\"legend\" id=\"heatmap-legend\"><span>heatmap, LSB of 8 bits:</span><div>"
    << "<div class=\"ramp\" style=\"background:linear-gradient(to right," << stops
    << ")\"></div><div class=\"ticks\">";
  for (double v : {0.0, 0.5, 1.0, 2.0, 4.0, 8.0}) {
    char label[16];
    std::snprintf(label, sizeof label, "%g", v);
    s << "<span style=\"left:" << 100.0 * v / kHeatmapMaxLsb << "%\">" << label
      << (v == kHeatmapMaxLsb ? "+" : "") << "</span>";
  }
  s << "</div></div><span><span class=\"swatch\" style=\"background:"
    << css_colour(kHeatmapUncovered) << "\"></span> background within 0.5 LSB</span>"
    << "<span><span class=\"swatch\" style=\"background:" << css_colour(kHeatmapNonFinite)
    << "\"></span> NaN/Inf</span></div>";
  return s.str();
}

// Whether a verdict counts as failing (sorted first, shown by the "failing" filter).
bool is_failing_verdict(const std::string& verdict) {
  return verdict == "fail" || verdict == "missing" || verdict == "crashed" ||
         verdict == "timed out";
}

// A verdict as a CSS class name: "timed out" is v-timed-out.
std::string verdict_class(std::string verdict) {
  std::replace(verdict.begin(), verdict.end(), ' ', '-');
  return "v-" + verdict;
}

std::string card_html(const PageCard& c, size_t order) {
  std::ostringstream s;
  const bool failing = is_failing_verdict(c.verdict);
  char error[32] = "";
  if (c.error_lsb) std::snprintf(error, sizeof error, "%.6g", *c.error_lsb);
  s << "<article class=\"card\" tabindex=\"0\" data-case=\""
    << esc(c.scene + "/" + c.path + "/" + c.variant) << "\" data-scene=\"" << esc(c.scene)
    << "\" data-path=\"" << esc(c.path) << "\" data-variant=\"" << esc(c.variant)
    << "\" data-verdict=\"" << esc(c.verdict) << "\" data-failing=\"" << (failing ? "yes" : "no")
    << "\" data-error=\"" << error << "\" data-order=\"" << order << "\" data-width=\"" << c.width
    << "\">\n<h3><span class=\"path\">" << esc(c.path) << "</span> <span "
    << "class=\"variant\">" << esc(c.variant) << "</span>";
  if (!c.verdict.empty())
    s << " <span class=\"verdict " << esc(verdict_class(c.verdict)) << "\">" << esc(c.verdict)
      << "</span>";
  s << "</h3>\n";
  if (c.image.empty()) {
    s << "<div class=\"view no-image\"></div>\n";
  } else {
    s << "<div class=\"view\" style=\"--w:" << c.width << "\" title=\""
      << (c.flip_image.empty() ? "" : "click or f: flip with the " + esc(c.flip_label)) << "\">"
      << "<img class=\"shown-image\" src=\"" << esc(c.image) << "\" alt=\"render\" width=\""
      << c.width << "\" height=\"" << c.height << "\">";
    if (!c.flip_image.empty()) {
      s << "<img class=\"flip-image\" src=\"" << esc(c.flip_image) << "\" alt=\""
        << esc(c.flip_label) << "\" width=\"" << c.width << "\" height=\"" << c.height
        << "\" hidden>";
    }
    if (!c.heatmap.empty()) {
      s << "<img class=\"heat-image\" src=\"" << esc(c.heatmap) << "\" alt=\"heatmap\" width=\""
        << c.width << "\" height=\"" << c.height << "\">";
    }
    s << "</div>\n<p class=\"showing\">showing: <span class=\"showing-what\">render</span>"
      << (c.flip_image.empty() ? "" : " (click or f: flip with the " + esc(c.flip_label) + ")")
      << "</p>\n";
  }
  s << "<dl class=\"figures\">";
  for (const auto& [label, value] : c.figures)
    s << "<dt>" << esc(label) << "</dt><dd>" << esc(value) << "</dd>";
  s << "</dl>\n";
  if (!c.notes.empty()) {
    s << "<ul class=\"notes\">";
    for (const std::string& n : c.notes) s << "<li>" << esc(n) << "</li>";
    s << "</ul>\n";
  }
  s << "</article>\n";
  return s.str();
}

std::string sections_html(const std::vector<PageCard>& cards) {
  std::vector<std::string> scenes;
  std::map<std::string, std::string> body;
  for (size_t i = 0; i < cards.size(); ++i) {
    if (!body.count(cards[i].scene)) scenes.push_back(cards[i].scene);
    body[cards[i].scene] += card_html(cards[i], i);
  }
  std::string out;
  for (const std::string& scene : scenes) {
    out += "<section class=\"scene\" data-scene=\"" + esc(scene) + "\"><h2>" + esc(scene) +
           "</h2>\n<div class=\"cards\">\n" + body[scene] + "</div></section>\n";
  }
  return out;
}

std::string page_html(const ReportPage& page) {
  return fill(
      template_file("page.html"),
      {{"title", esc(page.title)},
       {"summary", esc(page.summary)},
       {"versions", esc(tool_versions_line())},
       {"style", template_file("page.css")},
       {"script", template_file("page.js")},
       {"legend", legend_html()},
       {"chart",
        page.chart_svg.empty() ? "" : "<figure class=\"chart\">" + page.chart_svg + "</figure>"},
       {"sections", sections_html(page.cards)}});
}

}  // namespace

void write_report_page(const fs::path& dir, const ReportPage& page) {
  write_text_file(dir / "index.html", page_html(page));
}

}  // namespace lt
