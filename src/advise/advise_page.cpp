#include "advise/advise_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/fixed.h"
#include "core/markup.h"

namespace lt::advise {

namespace {

std::string num(double v) {
  return fixed(v, 1);
}

// Chart geometry, in SVG units.
constexpr double kW = 640, kH = 320, kLeft = 70, kRight = 20, kTop = 20, kBottom = 50;

// The cost axis, fitted to the costs drawn: candidates of one path often differ by a few percent
// of their cost, so an axis from 0 would crowd them at its right edge. Costs over more than a
// decade (a refined mesh's vertices beside a LUT's bytes, say) are drawn on a log scale.
struct CostAxis {
  double lo = 0, hi = 1;
  bool log = false;
  // 0 at lo to 1 at hi.
  double fraction(double v) const {
    return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
               : (v - lo) / (hi - lo);
  }
};

CostAxis cost_axis(double min_cost, double max_cost) {
  CostAxis a;
  a.log = min_cost > 0 && max_cost / min_cost > 10;
  if (a.log) {
    a.lo = min_cost / 1.25;  // a margin of a tenth of a decade each side
    a.hi = max_cost * 1.25;
    return a;
  }
  // 5% of the span each side; a single cost (or all equal) gets 5% of itself.
  const double pad =
      max_cost > min_cost ? (max_cost - min_cost) * 0.05 : std::max(std::abs(max_cost) * 0.05, 1.0);
  a.lo = std::max(0.0, min_cost - pad);
  a.hi = max_cost + pad;
  return a;
}

// Tick values inside the axis: powers of ten on a log axis (with 2 and 5 times them when it spans
// under two decades), else multiples of the 1-2-5 step that gives 4 to 10 ticks.
std::vector<double> cost_ticks(const CostAxis& a) {
  std::vector<double> ticks;
  if (a.log) {
    const bool fine = a.hi / a.lo < 100;
    for (double p = std::pow(10.0, std::floor(std::log10(a.lo))); p <= a.hi; p *= 10) {
      for (double k : {1.0, 2.0, 5.0}) {
        if ((k == 1.0 || fine) && p * k >= a.lo && p * k <= a.hi) ticks.push_back(p * k);
      }
    }
    return ticks;
  }
  const double raw = (a.hi - a.lo) / 5;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (double k : {1.0, 2.0, 5.0, 10.0}) {
    step = k * decade;
    if (step >= raw) break;
  }
  for (double t = std::ceil(a.lo / step) * step; t <= a.hi; t += step) ticks.push_back(t);
  return ticks;
}

// A tick's label: 12500 as "12.5k", 3e6 as "3M".
std::string tick_label(double v) {
  char buf[32];
  const double a = std::abs(v);
  if (a >= 1e6)
    std::snprintf(buf, sizeof buf, "%gM", v / 1e6);
  else if (a >= 1e3)
    std::snprintf(buf, sizeof buf, "%gk", v / 1e3);
  else
    std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

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
  double xmin = std::numeric_limits<double>::infinity(), xmax = 0, emax = a.options.max_lsb;
  for (size_t i : shown) {
    xmin = std::min(xmin, a.candidates[i].cost[m].ops);
    xmax = std::max(xmax, a.candidates[i].cost[m].ops);
    emax = std::max(emax, stat_of(a.candidates[i].error[m], stat));
  }
  const CostAxis axis = cost_axis(xmin, xmax);
  const double lo = std::log10(0.1), hi = std::log10(std::max(emax * 1.5, 1.0));
  auto x = [&](double ops) { return kLeft + axis.fraction(ops) * (kW - kLeft - kRight); };
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
    << "\" text-anchor=\"middle\">operations a frame" << (axis.log ? " (log)" : "") << "</text>\n";
  for (double t : cost_ticks(axis)) {
    s << "<line x1=\"" << num(x(t)) << "\" y1=\"" << kH - kBottom << "\" x2=\"" << num(x(t))
      << "\" y2=\"" << kH - kBottom + 5 << "\" stroke=\"#444\"/>\n";
    s << "<text class=\"tick\" x=\"" << num(x(t)) << "\" y=\"" << kH - kBottom + 18
      << "\" text-anchor=\"middle\">" << tick_label(t) << "</text>\n";
  }
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
  // Drawn in layers, the pick last: candidates of the same cost and error (LUT widths often
  // are) would otherwise cover the front and the pick.
  std::stable_sort(shown.begin(), shown.end(), [&](size_t p, size_t q) {
    auto layer = [&](size_t i) {
      if (ma.pick && *ma.pick == i) return 2;
      return std::find(ma.front.begin(), ma.front.end(), i) != ma.front.end() ? 1 : 0;
    };
    return layer(p) < layer(q);
  });
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

// The material's pick in words: a variant, or (with --max-vertices) a variant on a refined mesh,
// which the chart does not show (its points are the variants on the scene's own mesh).
std::string pick_words(const Advice& a, const MaterialAdvice& ma) {
  if (ma.pick)
    return "pick: <b>" + markup_escape(a.candidates[*ma.pick].candidate.variant) + "</b>";
  if (ma.refinement && ma.refinement->holds_at) {
    const Refinement& r = *ma.refinement;
    return "pick: <b>" + markup_escape(a.candidates[r.candidate].candidate.variant) +
           "</b> on a refined mesh, +" + std::to_string(r.vertices_added()) + " vertices, max " +
           num(r.pick_step().error.max_lsb) +
           " LSB (the chart shows the variants on the scene's own mesh)";
  }
  return "no candidate within the budget";
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
    s << "<p>" << pick_words(a, ma) << "</p>\n";
    s << chart(a, ma) << "</section>\n";
  }
  s << "</body>\n</html>\n";
  return s.str();
}

}  // namespace lt::advise
