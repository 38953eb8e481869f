// What a path reports of its last frame, typed: a path sets the figures it has, the rest stay
// empty. The bench takes each figure's median over the timed frames and words the ones that are
// set in its notes; report.json lists them by these names. A new figure is one field here, one
// row in FrameStats::kFields, and its words in the bench's notes.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace lt {

struct FrameStats {
  std::optional<double> shading_seconds;       // CPU per-pixel shading (reference, half)
  std::optional<double> covered_pixels;        // pixels that CPU shading ran on
  std::optional<double> threads;               // CPU shading threads
  std::optional<double> nonfinite_pixels;      // NaN/Inf results drawn as a marker (half)
  std::optional<double> cpu_vertex_seconds;    // per-vertex work on the CPU (combiners, gx XF)
  std::optional<double> passes;                // passes drawn
  std::optional<double> cube_rebuild_seconds;  // combiners lobe=cube: building the cube maps
  std::optional<double> tev_seconds;           // gx: texture unit, TEV and EFB on the CPU
  std::optional<double> tev_stage_pixels;      // gx: TEV stages run, over all pixels and passes
  std::optional<double> xf_light_vertices;     // gx: lights evaluated, over all vertices and passes

  using Field = std::optional<double> FrameStats::*;
  static constexpr std::array<std::pair<const char*, Field>, 10> kFields = {{
      {"shading_seconds", &FrameStats::shading_seconds},
      {"covered_pixels", &FrameStats::covered_pixels},
      {"threads", &FrameStats::threads},
      {"nonfinite_pixels", &FrameStats::nonfinite_pixels},
      {"cpu_vertex_seconds", &FrameStats::cpu_vertex_seconds},
      {"passes", &FrameStats::passes},
      {"cube_rebuild_seconds", &FrameStats::cube_rebuild_seconds},
      {"tev_seconds", &FrameStats::tev_seconds},
      {"tev_stage_pixels", &FrameStats::tev_stage_pixels},
      {"xf_light_vertices", &FrameStats::xf_light_vertices},
  }};

  // The figures that are set, by name, in kFields order.
  std::vector<std::pair<const char*, double>> set_fields() const {
    std::vector<std::pair<const char*, double>> out;
    for (const auto& [name, field] : kFields) {
      if (this->*field) out.emplace_back(name, *(this->*field));
    }
    return out;
  }
};

}  // namespace lt
