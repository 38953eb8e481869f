// The Highway target the vector lanes run on in this process ("AVX3", "AVX2", "SSE4", ...): every
// file compiled through hwy/foreach_target.h has the same targets, so HWY_DYNAMIC_DISPATCH picks
// the same one for each of them, the best this CPU runs. `info` names it in the CPU paths' lines.
#pragma once

#include <string>

namespace lt {

std::string simd_target();

}  // namespace lt
