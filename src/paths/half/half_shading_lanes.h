// The half path's shading of a run of covered pixels (paths/common/pixel_run.h), vectorised with
// Highway: one pixel a lane, every operation of the seed's half3 code done in float and rounded
// to binary16 in the lanes (half_rounding-inl.h), in the order and with the guards of the
// conventions in half_shading.cpp's file comment. exp2 and log2 stay per lane (std:: in float, as
// before), and so do the texture units' addressing (model::bilinear_taps) and texel fetches;
// their blend is in the lanes (sample_half, half_shading.h, is the same code on one texel).
//
// One binary for every x86-64 machine: each Highway target is compiled and the best the CPU runs
// is chosen at the first call (HWY_DYNAMIC_DISPATCH). Every target gives the same bits: the
// rounding is IEEE's on each, and nothing is fused (-ffp-contract=off for the core).
#pragma once

#include <string>

#include "paths/common/pixel_run.h"
#include "paths/half/half_shading.h"

namespace lt::fp16 {

// Fills out.rgb[c][i] for every i < run.count (and the padding lanes, which the caller drops)
// with the pixel's half result widened to float. With PowMode::Unguarded a result may be NaN or
// Inf; the guarded modes are finite by construction.
void shade_run(const SceneH& scene, const MaterialH& material, PowMode mode, const PixelRun& run,
               ShadedRun& out);

// round_to_half over n floats, on the target dynamic dispatch chose: what tests check bit for
// bit against Imath's half, and what bench/ times.
void round_to_half(const float* in, float* out, std::size_t n);

}  // namespace lt::fp16
