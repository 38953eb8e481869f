#include "advise/advise_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/markup.h"

namespace lt::advise {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

// Chart geometry, in SVG units.
constexpr double kW = 640, kH = 320, kLeft = 70, kRight = 20, kTop = 20, kBottom = 50;

// One material's chart. Error on a log scale from 0.1 LSB (a floor: 0 LSB would be -inf), so
// a 1-LSB budget and a 40-LSB curve fit one chart.
std::string chart(const Advice& a, const MaterialAdvice& ma) {
  const size_t m = ma.index;
  const Stat stat = a.options.stat;
  std::vector<size_t> shown;
  for (size_t i = 0; i < a.candidates.size(); ++i) {
    if (a.candidates[i].rendered && a.candidates[i].non_finite[m] == 0) shown.push_back(i);
  }
  if (shown.empty()) return "<p>No candidate was rendered without a non-finite pixel.</p>\n";
  double xmax = 0, emax = a.options.max_lsb;
  for (size_t i : shown) {
    xmax = std::max(xmax, a.candidates[i].cost[m].ops);
    emax = std::max(emax, stat_of(a.candidates[i].error[m], stat));
  }
  xmax = xmax > 0 ? xmax * 1.05 : 1;
  const double lo = std::log10(0.1), hi = std::log10(std::max(emax * 1.5, 1.0));
  auto x = [&](double ops) { return kLeft + ops / xmax * (kW - kLeft - kRight); };
  auto y = [&](double e) {
    const double l = std::log10(std::max(e, 0.1));
    return kTop + (hi - l) / (hi - lo) * (kH - kTop - kBottom);
  };
  std::ostringstream s;
  s << "<svg class=\"front\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kW << "\" height=\""
    << kH << "\" viewBox=\"0 0 " << kW << " " << kH << "\" role=\"img\" aria-label=\"cost against "
    << to_string(stat) << " error, material " << markup_escape(ma.name) << "\">\n";
  s << "<line x1=\"" << kLeft << "\" y1=\"" << kH - kBottom << "\" x2=\"" << kW - kRight
    << "\" y2=\"" << kH - kBottom << "\" stroke=\"#444\"/>\n";
  s << "<line x1=\"" << kLeft << "\" y1=\"" << kTop << "\" x2=\"" << kLeft << "\" y2=\""
    << kH - kBottom << "\" stroke=\"#444\"/>\n";
  s << "<text x=\"" << (kLeft + kW - kRight) / 2 << "\" y=\"" << kH - 12
    << "\" text-anchor=\"middle\">operations a frame (0 to " << num(xmax) << ")</text>\n";
  s << "<text x=\"14\" y=\"" << (kTop + kH - kBottom) / 2 << "\" transform=\"rotate(-90 14 "
    << (kTop + kH - kBottom) / 2 << ")\" text-anchor=\"middle\">" << to_string(stat)
    << " error, LSB (log)</text>\n";
  for (double e : {0.1, 1.0, 10.0, 100.0}) {
    if (std::log10(e) > hi) break;
    s << "<text class=\"tick\" x=\"" << kLeft - 6 << "\" y=\"" << y(e) + 4
      << "\" text-anchor=\"end\">" << e << "</text>\n";
  }
  s << "<line class=\"budget\" x1=\"" << kLeft << "\" y1=\"" << y(a.options.max_lsb) << "\" x2=\""
    << kW - kRight << "\" y2=\"" << y(a.options.max_lsb)
    << "\" stroke=\"#c60\" stroke-dasharray=\"6 4\"><title>budget " << a.options.max_lsb
    << " LSB</title></line>\n";
  std::string points;
  for (size_t i : ma.front) {
    const CandidateResult& c = a.candidates[i];
    points += num(x(c.cost[m].ops)) + "," + num(y(stat_of(c.error[m], stat))) + " ";
  }
  s << "<polyline class=\"front-line\" fill=\"none\" stroke=\"#26a\" points=\"" << points
    << "\"/>\n";
  for (size_t i : shown) {
    const CandidateResult& c = a.candidates[i];
    const bool on_front = std::find(ma.front.begin(), ma.front.end(), i) != ma.front.end();
    const bool pick = ma.pick && *ma.pick == i;
    const double e = stat_of(c.error[m], stat);
    s << "<circle class=\""
      << (pick       ? "pick"
          : on_front ? "on-front"
                     : "candidate")
      << "\" cx=\"" << num(x(c.cost[m].ops)) << "\" cy=\"" << num(y(e)) << "\" r=\""
      << (pick ? 7 : 4) << "\" fill=\""
      << (pick       ? "#d22"
          : on_front ? "#26a"
                     : "#aaa")
      << "\"><title>" << markup_escape(c.candidate.variant) << ": " << num(c.cost[m].ops)
      << " ops, " << num(c.cost[m].texture_bytes) << " texture bytes, " << to_string(stat) << " "
      << num(e) << " LSB</title></circle>\n";
    if (pick) {
      s << "<text class=\"pick-label\" x=\"" << num(x(c.cost[m].ops) + 10) << "\" y=\""
        << num(y(e) - 10) << "\">" << markup_escape(c.candidate.variant) << "</text>\n";
    }
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace

std::string advise_page(const Advice& a) {
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>advise: "
    << markup_escape(a.options.scene_file.filename().string()) << " on "
    << markup_escape(a.options.profile) << "</title>\n"
    << "<style>body{font:14px sans-serif;margin:2em;max-width:60em}"
       "svg text{font:12px sans-serif}table{border-collapse:collapse}"
       "td,th{padding:2px 8px;text-align:left}</style>\n</head>\n<body>\n";
  s << "<h1>advise: " << markup_escape(a.options.scene_file.string()) << " on "
    << markup_escape(a.options.profile) << " (path " << markup_escape(a.path) << ")</h1>\n";
  s << "<p>Budget " << a.options.max_lsb << " LSB " << to_string(a.options.stat) << " at "
    << a.width << "x" << a.height << "; " << a.rendered() << " of " << a.candidates.size()
    << " candidates rendered. Grey: a rendered candidate; blue: the Pareto front; red: the "
       "pick; dashed: the budget.</p>\n";
  for (const MaterialAdvice& ma : a.materials) {
    s << "<section class=\"material\">\n<h2>material " << markup_escape(ma.name) << "</h2>\n";
    s << "<p>"
      << (ma.pick ? "pick: <b>" + markup_escape(a.candidates[*ma.pick].candidate.variant) + "</b>"
                  : std::string("no candidate within the budget"))
      << "</p>\n";
    s << chart(a, ma) << "</section>\n";
  }
  s << "</body>\n</html>\n";
  return s.str();
}

}  // namespace lt::advise
