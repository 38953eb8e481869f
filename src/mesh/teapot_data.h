// The Utah teapot as its published data: 32 bicubic Bezier patches (Newell's 306 control points
// and the 32 x 16 indices into them). mesh/teapot.cpp tessellates it; nothing else reads it.
#pragma once

#include <array>

namespace lt::meshgen {

inline constexpr int kTeapotPatches = 32;
inline constexpr int kTeapotControlPoints = 306;

// Patch p's control point (row i, column j) is kTeapotControlPointData[indices[p][4 * i + j]].
extern const std::array<std::array<int, 16>, kTeapotPatches> kTeapotPatchIndices;
// x, y, z with z up, as the dataset has them.
extern const std::array<std::array<double, 3>, kTeapotControlPoints> kTeapotControlPointData;

}  // namespace lt::meshgen
