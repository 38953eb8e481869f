// The reference's shading of a run of covered pixels (paths/common/pixel_run.h) in double vector
// lanes (Highway): model::shade (model/translucency.h) operation for operation, one pixel a lane,
// so every lane's result is model::shade's to the bit (tests/reference_lanes_test.cpp holds the
// two equal). What has no vector form that is the scalar one to the bit stays per lane: a lobe
// ramp's sample (model::sample_ramp) and std::pow for the lobe where model::lobe_power takes it
// (a fractional power; model/lobe_power-inl.h is the whole power's lanes). A map's sample is in
// the lanes, its texels gathered (bilinear_lanes-inl.h).
//
// One binary for every x86-64 machine: each Highway target is compiled and the best the CPU runs
// is chosen at the first call (HWY_DYNAMIC_DISPATCH). The lanes use + - * / sqrt and compares
// only, each IEEE-rounded in double on every target, and nothing is fused (-ffp-contract=off).
#pragma once

#include "model/texture_sampling.h"
#include "paths/common/pixel_run.h"
#include "scene/scene.h"

namespace lt::reference {

// Fills out.rgb[c][i] for every i < run.count (and the padding lanes, which the caller drops)
// with model::shade(scene, material, point) narrowed to float, the point being pixel i's
// G-buffer values widened to double and V = model::view_vector(scene.camera, P). `scene`'s
// light positions are camera-relative, as the G-buffer's.
void shade_run(const Scene& scene, const Material& material, const PixelRun& run, ShadedRun& out);

// model::sample_bilinear(texture, (u[i], v[i])) for i < n through the maps' lanes
// (bilinear_lanes-inl.h): channel c of sample i in rgb[c * n + i].
void sample_bilinear(const model::Texture& texture, const double* u, const double* v, double* rgb,
                     size_t n);

}  // namespace lt::reference
