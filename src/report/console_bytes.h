// A console path's figures on bench's rows (report.json's "console", report.csv's console_
// columns, the page's bytes chart): what `ltrender budget SCENE --path P --variant V` counts for
// the row's scene and variant (for gx, gx_budget.h: the variant's own vertices and the frame's
// textures), read from the budget's report, never counted a second time. Exact counts a frame,
// not time: no public source states how long the console takes (docs/bench.md).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <utility>

#include "budget/report.h"

namespace lt {

struct ConsoleBytes {
  std::size_t vertex_bytes = 0;        // one vertex in the stream
  std::size_t fifo_bytes = 0;          // what the CPU sends through the FIFO a frame
  std::size_t array_bytes = 0;         // MEM1: indexed arrays (0: the vertices are sent direct)
  std::size_t display_list_bytes = 0;  // MEM1: display lists (0: none)
  std::size_t texture_bytes = 0;       // MEM1: the frame's textures
  std::size_t tlut_bytes = 0;          // MEM1: their palettes
  std::size_t xf_vertices = 0;         // vertices the XF transforms and lights a frame
  std::size_t triangles = 0;           // triangles set up a frame
  // What the frame keeps in MEM1: arrays, display lists, textures and palettes.
  std::size_t mem1_bytes() const {
    return array_bytes + display_list_bytes + texture_bytes + tlut_bytes;
  }

  using Field = std::size_t ConsoleBytes::*;
  // The names in report.json, report.csv (with "console_" before them) and the budget's report.
  static constexpr std::array<std::pair<const char*, Field>, 8> kFields = {{
      {"vertex_bytes", &ConsoleBytes::vertex_bytes},
      {"fifo_bytes", &ConsoleBytes::fifo_bytes},
      {"array_bytes", &ConsoleBytes::array_bytes},
      {"display_list_bytes", &ConsoleBytes::display_list_bytes},
      {"texture_bytes", &ConsoleBytes::texture_bytes},
      {"tlut_bytes", &ConsoleBytes::tlut_bytes},
      {"xf_vertices", &ConsoleBytes::xf_vertices},
      {"triangles", &ConsoleBytes::triangles},
  }};
};

// The figures of a path's budget report; none when it counts no FIFO bytes (a path that is not a
// console's, or a storage the scene's mesh does not fit: the report's note says why). A key the
// report lacks is 0 (a direct draw keeps no arrays or lists in MEM1).
std::optional<ConsoleBytes> console_bytes(const budget::Report& report);

}  // namespace lt
