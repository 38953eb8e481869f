// The report page of `advise -o DIR` (DIR/index.html): per material, the candidates as an inline
// SVG chart of cost (the work axis) against error, the Pareto front drawn as a line, the budget
// as a horizontal rule and the pick marked. Self-contained: no script, no external file.
#pragma once

#include <string>

#include "advise/advise.h"

namespace lt::advise {

std::string advise_page(const Advice& a);

}  // namespace lt::advise
