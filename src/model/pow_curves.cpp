#include "model/pow_curves.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "model/translucency.h"

namespace lt::model {

double sg_exponent(double p) {
  return p / std::log(2.0) + 1 / std::log(2.0);
}

namespace {

double fit_sg_exponent_uncached(double p) {
  // Max error over a dense t grid; the fitted curve is smooth, 4097 samples resolve its peak.
  auto max_error = [p](double n) {
    double e = 0;
    for (int i = 0; i <= 4096; ++i) {
      const double t = i / 4096.0;
      e = std::max(e, std::abs(std::exp2(n * (t - 1)) - lobe(t, p)));
    }
    return e;
  };
  // Coarse scan over [0, 2 n'_sg + 8], then golden-section refinement around the best sample
  // (the max error is unimodal near its minimum, not necessarily globally).
  const double hi = 2 * sg_exponent(p) + 8;
  const int steps = 200;
  int best = 0;
  double best_e = max_error(0);
  for (int i = 1; i <= steps; ++i) {
    const double e = max_error(hi * i / steps);
    if (e < best_e) best_e = e, best = i;
  }
  double a = hi * std::max(best - 1, 0) / steps, b = hi * std::min(best + 1, steps) / steps;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 60; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (max_error(c) < max_error(d))
      b = d;
    else
      a = c;
  }
  return (a + b) / 2;
}

}  // namespace

// Memoised: the fit is a pure function of p and costs ~250k exp2/pow calls, and every build of a
// pow=sg-fitted program (a budget, a render, each candidate `advise` costs) asks for it again.
double fit_sg_exponent(double p) {
  static std::mutex mutex;
  static std::map<double, double> fitted;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto it = fitted.find(p); it != fitted.end()) return it->second;
  }
  const double n = fit_sg_exponent_uncached(p);
  const std::lock_guard<std::mutex> lock(mutex);
  return fitted.emplace(p, n).first->second;
}

double sg_curve(double t, double n) {
  return std::exp2(n * (std::clamp(t, 0.0, 1.0) - 1));
}

}  // namespace lt::model
