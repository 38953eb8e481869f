#include "budget/shader_model_file_budget.h"

#include "budget/arb_file_budget.h"
#include "budget/d3d9_file_budget.h"
#include "core/fs.h"
#include "d3d9/d3d9_asm_parser.h"

namespace lt::budget {

namespace {

// The header after optional leading white space, as Mesa accepts it (arb_text_lexer.h).
bool starts_with_arb_header(const std::string& text) {
  const size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string::npos) return false;
  return text.compare(start, 10, "!!ARBfp1.0") == 0 || text.compare(start, 10, "!!ARBvp1.0") == 0;
}

bool is_d3d9_file(const std::string& file) {
  const std::string text = read_text_file(file);
  if (starts_with_arb_header(text)) return false;
  const std::string ext = fs::path(file).extension().string();
  return ext == ".asm" || ext == ".vsh" || ext == ".psh" || d3d9::starts_with_version(text);
}

}  // namespace

bool is_shader_model_program_text(const std::string& text) {
  return starts_with_arb_header(text) || d3d9::starts_with_version(text);
}

Report budget_shader_model_file(const std::string& file, const std::string& profile) {
  if (is_d3d9_file(file)) return d3d9::budget_d3d9_file(file, profile);
  return arbfp::budget_arb_file(file, profile);
}

}  // namespace lt::budget
