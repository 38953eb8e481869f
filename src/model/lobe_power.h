// The lobe's power x^p (model.md: lobe = t^p) as the reference defines it. For a whole p from 1
// to 64 -- every demo scene's power is 3 to 8, and an artist's power is most often whole -- x^p
// is computed by binary powering in double-double arithmetic and rounded to the nearest double:
// every product exact by Dekker's split (no fused multiply-add), at most 12 products for p <= 64,
// so the double-double's relative error is below 2^-97 and its rounding is the correctly rounded
// x^p except where x^p lies within 2^-44 ULP of the midpoint between two doubles (there it is one
// of the two). Every other case is std::pow: a fractional p, x outside (0, 1] (NaN included; the
// lobe's t is in [0, 1]), and results below 2^-800, where the double-double's small parts would
// leave the normal range.
//
// Why not std::pow everywhere. std::pow is the C library's: glibc documents its pow as within
// 0.54 ULP (sysdeps/ieee754/dbl-64/e_pow.c), and glibc 2.36 rounds x^p the other way for about one
// t in 1,250 (tests/lobe_power_test.cpp counts them); other C libraries round differently again.
// A ground truth built on it would change in the last bit with the C library, and vector lanes
// could match it only by calling it (about half of the reference's shading; issue 39). The
// double-double power is correctly rounded, the same on every machine and every Highway target,
// and runs in vector lanes (lobe_power-inl.h). tests/lobe_power_test.cpp holds it to x^p
// computed in binary128 (GCC's __float128).
#pragma once

#include <cmath>
#include <cstddef>

namespace lt::model {

// The exponents raised by the double-double powering: whole numbers 1..64 (beyond, more products
// than the error bound above counts).
inline bool is_whole_power(double p) {
  return p >= 1 && p <= 64 && p == std::floor(p);
}

// x^p as the lobe takes it (the header says how).
double lobe_power(double x, double p);

// out[i] = lobe_power(x[i], p) for i < n, in vector lanes on the best target the CPU runs;
// returns how many of the n went through std::pow.
std::size_t lobe_power(const double* x, double p, double* out, std::size_t n);

}  // namespace lt::model
