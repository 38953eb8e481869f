// The talk's parameter figures as pairs (scenes/figures/): each figure of the GDC 2011 talk shows
// one parameter at two values, left and right ("Fig. 16 - Power (4/Left, 12/Right) Term"). A
// scene named <figure>_<parameter>_a_<value>, followed in name order by
// <figure>_<parameter>_b_<value> of the same parameter, is such a figure's left and right image
// (fig16_power_a_4, fig16_power_b_12; fig20_thickness_a_grey, fig21_thickness_b_red). In a
// value, digits around a "p" are a decimal number ("0p2" is 0.2).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace lt {

struct FigureRow {
  std::string label;                  // "fig16 power", "fig20/fig21 thickness", or a lone name
  std::vector<std::size_t> scenes;    // indices into the names: the pair, left first, or one
  std::vector<std::string> captions;  // one a scene: "power 4", "power 12"; "" for a lone scene
};

// One row per pair and one per scene that pairs with none, in the names' order; empty when no
// two names pair (the bench's ordinary sheet, a row a scene, is the one to draw then).
std::vector<FigureRow> figure_rows(const std::vector<std::string>& scene_names);

}  // namespace lt
