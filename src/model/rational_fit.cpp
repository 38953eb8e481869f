#include "model/rational_fit.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lt::model {

double Rational22::operator()(double x) const {
  return (a[0] + a[1] * x + a[2] * x * x) / (k[0] + k[1] * x + k[2] * x * x);
}

namespace {

// Solves the n x n system m * x = b in place (Gaussian elimination, partial pivoting); false if
// singular.
template <size_t N>
bool solve(std::array<std::array<double, N>, N> m, std::array<double, N>& b) {
  for (size_t c = 0; c < N; ++c) {
    size_t p = c;
    for (size_t r = c + 1; r < N; ++r) {
      if (std::abs(m[r][c]) > std::abs(m[p][c])) p = r;
    }
    if (std::abs(m[p][c]) < 1e-300) return false;
    std::swap(m[p], m[c]);
    std::swap(b[p], b[c]);
    for (size_t r = c + 1; r < N; ++r) {
      const double f = m[r][c] / m[c][c];
      for (size_t k = c; k < N; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (size_t c = N; c-- > 0;) {
    for (size_t k = c + 1; k < N; ++k) b[c] -= m[c][k] * b[k];
    b[c] /= m[c][c];
  }
  return true;
}

double max_error(const Rational22& r, const std::vector<double>& xs,
                 const std::vector<double>& fs) {
  double e = 0;
  for (size_t i = 0; i < xs.size(); ++i) e = std::max(e, std::abs(r(xs[i]) - fs[i]));
  return e;
}

double min_denominator(const Rational22& r, const std::vector<double>& xs) {
  double m = 1e300;
  for (double x : xs) m = std::min(m, r.k[0] + r.k[1] * x + r.k[2] * x * x);
  return m;
}

}  // namespace

RationalFit fit_rational22(const std::function<double(double)>& f, double x_max, int samples) {
  RationalFit best;
  if (!(x_max > 0)) {
    best.r.a = {f(0), 0, 0};
    return best;
  }
  std::vector<double> xs, fs;
  for (int i = 0; i < samples; ++i) {
    xs.push_back(x_max * i / (samples - 1));
    fs.push_back(f(xs.back()));
  }
  // Unknowns u = (a0, a1, a2, k1, k2): residual P(x) - f(x) (1 + k1 x + k2 x^2), each sample
  // weighted by 1 / Q_prev(x)^2 so the iteration converges to the true rational least squares.
  Rational22 current;             // k = (1, 0, 0): the first solve is the polynomial fit
  best.r.a = {fs.front(), 0, 0};  // the constant, should every solve fail
  best.max_error = max_error(best.r, xs, fs);
  for (int iter = 0; iter < 30; ++iter) {
    std::array<std::array<double, 5>, 5> m{};
    std::array<double, 5> rhs{};
    for (size_t i = 0; i < xs.size(); ++i) {
      const double x = xs[i], q = current.k[0] + current.k[1] * x + current.k[2] * x * x;
      const double w = 1.0 / (q * q);
      const std::array<double, 5> row = {1, x, x * x, -fs[i] * x, -fs[i] * x * x};
      for (size_t r = 0; r < 5; ++r) {
        for (size_t c = 0; c < 5; ++c) m[r][c] += w * row[r] * row[c];
        rhs[r] += w * row[r] * fs[i];
      }
    }
    // A tiny ridge keeps the system solvable for flat curves (k1 = k2 = 0 is then the answer).
    for (size_t r = 0; r < 5; ++r) m[r][r] += 1e-12 * (1 + m[r][r]);
    if (!solve(m, rhs)) break;
    Rational22 next;
    next.a = {rhs[0], rhs[1], rhs[2]};
    next.k = {1, rhs[3], rhs[4]};
    if (min_denominator(next, xs) < 1e-3) break;
    const double e = max_error(next, xs, fs);
    if (e < best.max_error) {
      best.r = next;
      best.max_error = e;
    }
    current = next;
  }
  return best;
}

}  // namespace lt::model
