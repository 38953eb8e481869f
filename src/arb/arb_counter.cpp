#include "arb/arb_counter.h"

#include "arb/arb_ir_counter.h"
#include "arb/arb_text_parser.h"

namespace lt::budget {

const char* to_string(ProgramKind k) {
  return k == ProgramKind::Vertex ? "vertex" : "fragment";
}

ProgramCounts count_program(const std::string& source) {
  return arbfp::ir::count(arbfp::text::parse(source));
}

}  // namespace lt::budget
