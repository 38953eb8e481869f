// model::lobe_power for arrays and for one value: lobe_power-inl.h on the best Highway target the
// CPU runs. Compiled once per target (hwy/foreach_target.h re-includes this file), outside the
// unity build (CMakeLists.txt).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "model/lobe_power_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "model/lobe_power-inl.h"
#include "model/lobe_power.h"

HWY_BEFORE_NAMESPACE();
namespace lt::model::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

size_t LobePowerArray(const double* x, double p, double* out, size_t n) {
  const hn::ScalableTag<double> d;
  size_t calls = 0;
  size_t i = 0;
  for (; i + hn::Lanes(d) <= n; i += hn::Lanes(d))
    hn::StoreU(LobePower(d, hn::LoadU(d, x + i), p, hn::FirstN(d, hn::Lanes(d)), &calls), d,
               out + i);
  const hn::CappedTag<double, 1> d1;
  for (; i < n; ++i)
    hn::StoreU(LobePower(d1, hn::LoadU(d1, x + i), p, hn::FirstN(d1, 1), &calls), d1, out + i);
  return calls;
}

}  // namespace lt::model::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lt::model {

HWY_EXPORT(LobePowerArray);

size_t lobe_power(const double* x, double p, double* out, size_t n) {
  return HWY_DYNAMIC_DISPATCH(LobePowerArray)(x, p, out, n);
}

double lobe_power(double x, double p) {
  double out;
  lobe_power(&x, p, &out, 1);
  return out;
}

}  // namespace lt::model
#endif  // HWY_ONCE
