// A rational function of degree 2 over degree 2, R(x) = (a0 + a1 x + a2 x^2) / (k0 + k1 x + k2
// x^2), fitted in double to a curve on [0, x_max]. It is the shape of the Wii's XF attenuation
// (GX_AF_SPEC: numerator from GX_InitLightAttnA, denominator from GX_InitLightAttnK), so a
// fitted lobe can be evaluated per vertex by the lighting hardware with no texture at all.
#pragma once

#include <array>
#include <functional>

namespace lt::model {

struct Rational22 {
  std::array<double, 3> a{0, 0, 0}, k{1, 0, 0};
  double operator()(double x) const;
};

struct RationalFit {
  Rational22 r;
  double max_error = 0;  // max |R - f| over the fitting samples
};

// Sanathanan-Koerner iterations of the linearised least-squares problem (k0 = 1), keeping the
// best iterate by max error among those whose denominator stays above 1e-3 on [0, x_max] (so
// the hardware never divides by zero); the polynomial fit (k = 1, 0, 0) is a candidate too.
// x_max <= 0 gives the constant f(0).
RationalFit fit_rational22(const std::function<double(double)>& f, double x_max, int samples = 513);

}  // namespace lt::model
