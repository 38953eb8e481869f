// simd_target (core/simd_target.h): HWY_TARGET read through Highway's own dispatch. Compiled once
// per target (hwy/foreach_target.h re-includes this file), outside the unity build.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/simd_target_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/targets.h>

#include <cstdint>

#include "core/simd_target.h"

HWY_BEFORE_NAMESPACE();
namespace lt::HWY_NAMESPACE {

std::int64_t Target() {
  return HWY_TARGET;
}

}  // namespace lt::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lt {

HWY_EXPORT(Target);

std::string simd_target() {
  return hwy::TargetName(HWY_DYNAMIC_DISPATCH(Target)());
}

}  // namespace lt
#endif  // HWY_ONCE
