#include "paths/arbfp/arb_file_budget.h"

#include <iomanip>
#include <sstream>

#include "core/error.h"
#include "core/fs.h"
#include "gl/context.h"
#include "paths/arbfp/arb_text_parser.h"

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

const budget::Profile& profile_for(ProgramKind kind, const std::string& name) {
  const budget::Profile& chosen = budget::find_profile(
      name.empty() ? (kind == ProgramKind::Vertex ? "vs_2_0" : "ps_2_0") : name);
  return chosen.kind == kind ? chosen : budget::find_profile(chosen.partner);
}

// The rows, ours beside Mesa's native figure, each with the rule that relates them (measured on
// Mesa 22 llvmpipe, see tests/arb_text_test.cpp).
std::vector<BudgetFigure> figures(const FileBudget& b) {
  const budget::ProgramCounts& c = b.counts;
  const budget::Profile& p = *b.profile;
  const MesaFigures& m = b.mesa.native;
  const bool fragment = b.kind == ProgramKind::Fragment;
  const int invariant = c.position_invariant ? 4 : 0;
  std::vector<BudgetFigure> f;
  const bool alu_agrees = fragment ? m.alu == c.alu : m.instructions == c.instructions() + 1;
  f.push_back({"alu", "ALU instructions", c.alu, p.alu, fragment ? m.alu : -1, alu_agrees,
               fragment ? "non-texture instructions; = NATIVE_ALU_INSTRUCTIONS"
                        : "every instruction (GL has no ALU query for vertex programs)"});
  if (fragment) {
    f.push_back({"tex", "TEX instructions", c.tex, p.tex, m.tex, m.tex == c.tex,
                 "TEX, TXP, TXB, KIL (KIL is a texture instruction in ARB_fragment_program); "
                 "= NATIVE_TEX_INSTRUCTIONS"});
  }
  f.push_back({"instruction_slots", "instruction slots", c.instructions() + invariant,
               p.instructions, m.instructions, m.instructions == c.instructions() + 1,
               std::string("ALU + TEX") +
                   (invariant ? " + the 4 DP4 of ARB_position_invariant" : "") +
                   "; Mesa counts END too" + (invariant ? ", not the 4 DP4" : "")});
  f.push_back({"temporaries", "temporaries", c.temporaries, p.temporaries, m.temporaries,
               m.temporaries == c.temporaries, "TEMP declarations; = NATIVE_TEMPORARIES"});
  f.push_back({"parameters", "parameters", c.parameters, p.parameters, m.parameters,
               m.parameters == c.referenced_parameters,
               "declared PARAM slots + distinct inline constants/bindings (checked); Mesa keeps "
               "referenced slots only, equal constants merged, scalars packed (replayed: " +
                   std::to_string(c.referenced_parameters) + ")"});
  f.push_back({"attributes", "attributes", c.attributes, p.attributes, m.attributes,
               m.attributes == c.attributes,
               "distinct inputs read (an unread ATTRIB binds none); = NATIVE_ATTRIBS"});
  if (fragment) {
    f.push_back({"indirections", "texture indirections", c.indirections, p.indirections,
                 m.indirections, m.indirections == 0,
                 "ARB_fragment_program issue 24 (ps_2_0's 4 dependent levels = 5); Mesa reports "
                 "0 (it no longer computes them)"});
  }
  f.push_back({"address_registers", "address registers", c.address_registers, -1,
               m.address_registers, m.address_registers == c.address_registers,
               "ADDRESS declarations; = NATIVE_ADDRESS_REGISTERS"});
  return f;
}

// What Mesa adds at the API level, and how the profile sees it.
std::vector<std::string> notes(const FileBudget& b) {
  std::vector<std::string> out;
  const MesaFigures &n = b.mesa.native, &a = b.mesa.api;
  if (a.instructions != n.instructions || a.temporaries != n.temporaries) {
    std::string why;
    if (b.counts.position_invariant) why = "the 4 DP4 of ARB_position_invariant";
    for (const std::string& o : b.options) {
      if (o.rfind("ARB_fog_", 0) == 0) {
        why = "the fog code of " + o + " (not counted against " + b.profile->name +
              ": D3D9 fogs after the pixel shader, outside its slots)";
      }
    }
    out.push_back("Mesa's API counts (GL_PROGRAM_*) are " + std::to_string(a.instructions) +
                  " instructions and " + std::to_string(a.temporaries) +
                  " temporaries: it appends " + (why.empty() ? "code of its own" : why));
  }
  for (const BudgetFigure& f : b.figures) {
    if (!f.agrees) {
      out.push_back("DIFFERS from Mesa: " + f.label + " " + std::to_string(f.count) + ", Mesa " +
                    std::to_string(f.mesa) + ", which no rule above explains");
    }
  }
  return out;
}

}  // namespace

std::string FileBudget::first_overrun() const {
  if (over.empty()) return "";
  const budget::Overrun& o = over.front();
  return file + ": " + std::to_string(o.count) + " " + o.limit + " > " + std::to_string(o.max) +
         " (" + profile->name + ")";
}

FileBudget budget_arb_file(const std::string& file, const std::string& profile) {
  const std::string source = read_text_file(file);
  text::Program parsed;
  try {
    parsed = text::parse(source);
  } catch (const text::SyntaxError& e) {
    throw InputError(file, std::to_string(e.at().line) + ":" + std::to_string(e.at().column),
                     e.message());
  }
  FileBudget b;
  b.file = file;
  b.header = parsed.header;
  b.kind = parsed.kind;
  b.options = parsed.options;
  b.profile = &profile_for(parsed.kind, profile);
  b.counts = budget::count_parsed(parsed);
  b.over = budget::check(b.counts, *b.profile);
  {
    const gl::Context ctx(8, 8);
    b.mesa = mesa_counts(parsed.kind, source);
  }
  if (!b.mesa.accepted) {
    throw InputError(file, line_column(source, b.mesa.error_offset),
                     "Mesa refuses the program: " + mesa_message(b.mesa.error));
  }
  b.figures = figures(b);
  b.notes = notes(b);
  return b;
}

std::string to_text(const FileBudget& b) {
  std::ostringstream s;
  s << "budget: " << b.file << " (" << b.header << ", " << budget::to_string(b.kind)
    << " program), profile " << b.profile->name << "\n  " << b.profile->source
    << "\n  Mesa: " << b.mesa.renderer << " (NATIVE_* figures)\n\n";
  s << std::left << std::setw(22) << "figure" << std::setw(7) << "count" << std::setw(7) << "limit"
    << std::setw(7) << "Mesa"
    << "rule\n";
  for (const BudgetFigure& f : b.figures) {
    std::string count = std::to_string(f.count) + (f.limit >= 0 && f.count > f.limit ? "!" : "");
    s << std::setw(22) << f.label << std::setw(7) << count << std::setw(7)
      << (f.limit >= 0 ? std::to_string(f.limit) : "-") << std::setw(7)
      << (f.mesa >= 0 ? std::to_string(f.mesa) : "-") << f.rule << "\n";
  }
  for (const std::string& n : b.notes) s << "note: " << n << "\n";
  s << (b.fits() ? "fits " + b.profile->name : "OVER BUDGET: " + b.first_overrun()) << "\n";
  return s.str();
}

nlohmann::json to_json(const FileBudget& b) {
  nlohmann::json counts = nlohmann::json::object(), limits = nlohmann::json::object(),
                 mesa = nlohmann::json::object(), rules = nlohmann::json::object(),
                 agrees = nlohmann::json::object();
  auto or_null = [](int v) { return v >= 0 ? nlohmann::json(v) : nlohmann::json(nullptr); };
  for (const BudgetFigure& f : b.figures) {
    counts[f.key] = f.count;
    limits[f.key] = or_null(f.limit);
    mesa[f.key] = or_null(f.mesa);
    agrees[f.key] = f.agrees;
    rules[f.key] = f.rule;
  }
  nlohmann::json over = nlohmann::json::array();
  for (const budget::Overrun& o : b.over) {
    over.push_back({{"limit", o.limit}, {"count", o.count}, {"max", o.max}});
  }
  return {{"schema", "ltrender-budget-arb-1"},
          {"file", b.file},
          {"path", "arbfp"},
          {"kind", budget::to_string(b.kind)},
          {"header", b.header},
          {"options", b.options},
          {"profile", b.profile->name},
          {"fits", b.fits()},
          {"counts", counts},
          {"limits", limits},
          {"over", over},
          {"mesa",
           {{"renderer", b.mesa.renderer},
            {"native", mesa},
            {"agrees", agrees},
            {"api_instructions", b.mesa.api.instructions},
            {"api_temporaries", b.mesa.api.temporaries}}},
          {"rules", rules},
          {"notes", b.notes}};
}

}  // namespace lt::arbfp
