// The curves that replace pow(t, p) in the ports, in double, once: what the generators turn into
// instructions and constants, what the fp16 path evaluates in half, and what the tests hold
// them to. The exact lobe itself is model::lobe (translucency.h); the power LUT is power_lut.h.
#pragma once

namespace lt::model {

// The seed's literal for log2(e) in the SG post ("n = n * 1.4427f + 1.4427f"): the fp16 path
// keeps it as the seed's code has it.
inline constexpr double kSeedLog2e = 1.4427;

// The spherical-Gaussian exponent of the seed, n' = p / ln 2 + 1 / ln 2 (1.4427 = 1 / ln 2).
double sg_exponent(double p);
// n' of exp2(n' (t - 1)) minimising the max over t in [0, 1] of |exp2(n' (t - 1)) - t^p|.
double fit_sg_exponent(double p);
// The spherical-Gaussian curve exp2(n (t - 1)) at a saturated t: with n = sg_exponent(p) the
// seed's `sg`, with fit_sg_exponent(p) `sg-fitted`, with n = p the "simplified" form (a
// different curve, ~35-40 LSB off for any p: model.md).
double sg_curve(double t, double n);

}  // namespace lt::model
