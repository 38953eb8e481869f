// `ltrender export gx`: the generated programs as C for a libogc project (gx.md §2): one
// function per material and pass, the LUTs as 32-byte aligned u8 arrays in I8 tile order, the
// vertex format each pass expects (the variant's storage and indices, declared: plan_emitter.cpp
// vertex_format), and a comment block with the stage/unit counts and the
// error measured against the reference. `render --program` reads the file back to the same
// image, bit for bit.
#pragma once

#include <string>

#include "metrics/compare.h"
#include "paths/gx/gx_path.h"

namespace lt::gx {

struct ExportFigures {
  std::string scene, variant;
  int width = 0, height = 0;
  ErrorStats error;    // covered pixels, gx against the reference
  std::string budget;  // the budget table (gx_budget.h to_text)
};

std::string export_c(const ScenePrograms& programs, const ExportFigures& figures);

}  // namespace lt::gx
