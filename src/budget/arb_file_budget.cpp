#include "budget/arb_file_budget.h"

#include <optional>

#include "arb/arb_ir_counter.h"
#include "arb/arb_mesa_counts.h"
#include "arb/arb_text_parser.h"
#include "core/error.h"
#include "core/fs.h"
#include "gl/context.h"

namespace lt::arbfp {

using budget::ProgramKind;

namespace {

// Line and column (1-based) of a byte offset, as the parser names positions.
std::string line_column(const std::string& source, int offset) {
  int line = 1, column = 1;
  for (int i = 0; i < offset && i < static_cast<int>(source.size()); ++i) {
    if (source[static_cast<size_t>(i)] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// Mesa's message without its own "line L, char C: error: " prefix (the position is ours).
std::string mesa_message(const std::string& error) {
  const size_t at = error.find("error: ");
  std::string m = at == std::string::npos ? error : error.substr(at + 7);
  while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
  return m;
}

// The rows of program_resources, each with Mesa's native figure beside ours and the rule that
// relates them (measured on Mesa 22 llvmpipe, see tests/arb_text_test.cpp).
std::vector<budget::Resource> figures(const budget::ProgramCounts& c, const budget::Profile& p,
                                      const MesaFigures& m) {
  const bool fragment = c.kind == ProgramKind::Fragment;
  const bool invariant = c.position_invariant;
  std::vector<budget::Resource> f = budget::program_resources(c, p);
  auto set = [&f](const std::string& key, std::optional<budget::CrossCheck> check,
                  std::string rule) {
    for (budget::Resource& r : f) {
      if (r.key != key) continue;
      r.check = check;
      r.rule = std::move(rule);
    }
  };
  using Check = budget::CrossCheck;
  // GL has no ALU query for vertex programs: the slots row checks their instructions.
  set("alu", fragment ? std::optional<Check>(Check{m.alu, m.alu == c.alu}) : std::nullopt,
      fragment ? "non-texture instructions; = NATIVE_ALU_INSTRUCTIONS"
               : "every instruction (GL has no ALU query for vertex programs)");
  set("tex", Check{m.tex, m.tex == c.tex},
      "TEX, TXP, TXB, KIL (KIL is a texture instruction in ARB_fragment_program); "
      "= NATIVE_TEX_INSTRUCTIONS");
  set("instruction_slots", Check{m.instructions, m.instructions == c.instructions() + 1},
      std::string("ALU + TEX") + (invariant ? " + the 4 DP4 of ARB_position_invariant" : "") +
          "; Mesa counts END too" + (invariant ? ", not the 4 DP4" : ""));
  set("temporaries", Check{m.temporaries, m.temporaries == c.temporaries},
      "TEMP declarations; = NATIVE_TEMPORARIES");
  set("parameters", Check{m.parameters, m.parameters == c.referenced_parameters},
      "declared PARAM slots + distinct inline constants/bindings (checked); Mesa keeps "
      "referenced slots only, equal constants merged, scalars packed (replayed: " +
          std::to_string(c.referenced_parameters) + ")");
  set("attributes", Check{m.attributes, m.attributes == c.attributes},
      "distinct inputs read (an unread ATTRIB binds none); = NATIVE_ATTRIBS");
  set("indirections", Check{m.indirections, m.indirections == 0},
      "ARB_fragment_program issue 24 (ps_2_0's 4 dependent levels = 5); Mesa reports "
      "0 (it no longer computes them)");
  set("address_registers", Check{m.address_registers, m.address_registers == c.address_registers},
      "ADDRESS declarations; = NATIVE_ADDRESS_REGISTERS");
  return f;
}

// What Mesa adds at the API level, and how the profile sees it; and any figure that differs
// from Mesa's by no rule.
std::vector<std::string> notes(const budget::ProgramCounts& c,
                               const std::vector<std::string>& options,
                               const budget::Profile& profile, const MesaCounts& mesa,
                               const std::vector<budget::Resource>& figures) {
  std::vector<std::string> out;
  const MesaFigures &n = mesa.native, &a = mesa.api;
  if (a.instructions != n.instructions || a.temporaries != n.temporaries) {
    std::string why;
    if (c.position_invariant) why = "the 4 DP4 of ARB_position_invariant";
    for (const std::string& o : options) {
      if (o.rfind("ARB_fog_", 0) == 0) {
        why = "the fog code of " + o + " (not counted against " + profile.name +
              ": D3D9 fogs after the pixel shader, outside its slots)";
      }
    }
    out.push_back("Mesa's API counts (GL_PROGRAM_*) are " + std::to_string(a.instructions) +
                  " instructions and " + std::to_string(a.temporaries) +
                  " temporaries: it appends " + (why.empty() ? "code of its own" : why));
  }
  for (const budget::Resource& f : figures) {
    if (f.check && !f.check->agrees) {
      out.push_back("DIFFERS from Mesa: " + f.label + " " + std::to_string(f.used) + ", Mesa " +
                    std::to_string(f.check->value) + ", which no rule above explains");
    }
  }
  return out;
}

}  // namespace

budget::Report budget_arb_file(const std::string& file, const std::string& profile) {
  const std::string source = read_text_file(file);
  ir::Program parsed;
  try {
    parsed = text::parse(source);
  } catch (const text::SyntaxError& e) {
    throw InputError(file, std::to_string(e.at().line) + ":" + std::to_string(e.at().column),
                     e.message());
  }
  const budget::Profile& checked = budget::profile_for(
      parsed.kind(), profile, parsed.kind() == ProgramKind::Vertex ? "vs_2_0" : "ps_2_0");
  const budget::ProgramCounts counts = ir::count(parsed);
  MesaCounts mesa;
  {
    const gl::Context ctx(8, 8);
    mesa = mesa_counts(parsed.kind(), source);
  }
  if (!mesa.accepted) {
    throw InputError(file, line_column(source, mesa.error_offset),
                     "Mesa refuses the program: " + mesa_message(mesa.error));
  }
  budget::Report r;
  r.file = file;
  r.input = "program";
  r.path = "arbfp";
  r.profiles = {
      {checked.name, std::string(budget::to_string(parsed.kind())) + " programs", checked.source}};
  r.check_name = "Mesa";
  r.check_source = mesa.renderer + " (GL_PROGRAM_NATIVE_* figures)";
  std::string options;
  for (const std::string& o : parsed.options()) options += (options.empty() ? "" : " ") + o;
  r.details = {{"header", ir::header(parsed.kind()), {}},
               {"kind", budget::to_string(parsed.kind()), {}},
               {"options", options, {}},
               {"mesa_api_instructions", "", mesa.api.instructions},
               {"mesa_api_temporaries", "", mesa.api.temporaries}};
  budget::Item item;
  item.scope = budget::Scope::Program;
  item.name = std::string(budget::to_string(parsed.kind())) + " program";
  item.program = file;
  item.profile = checked.name;
  item.resources = figures(counts, checked, mesa.native);
  r.notes = notes(counts, parsed.options(), checked, mesa, item.resources);
  r.items.push_back(std::move(item));
  return r;
}

}  // namespace lt::arbfp
