#include "budget/d3d9_file_budget.h"

#include "budget/arb_profiles.h"
#include "core/error.h"
#include "core/fs.h"
#include "d3d9/d3d9_asm_counter.h"
#include "d3d9/d3d9_asm_parser.h"
#include "d3d9/d3d9_fxc_comment.h"

namespace lt::d3d9 {

namespace {

// The rows of one program: fxc's figures as the cross-checks of the slots it states.
std::vector<budget::Resource> d3d9_figures(const Counts& c, Version version,
                                           const budget::Profile& p,
                                           const std::optional<FxcCount>& fxc) {
  const bool pixel = is_pixel(version), model3 = is_model3(version);
  using budget::CrossCheck;
  auto check = [](std::optional<int> theirs, int ours) {
    return theirs ? std::optional<CrossCheck>(CrossCheck{*theirs, *theirs == ours}) : std::nullopt;
  };
  using budget::limit_of;
  std::vector<budget::Resource> out;
  if (pixel) {
    out.push_back({"alu", "ALU instructions", c.arithmetic, limit_of(p.alu),
                   "arithmetic slots by the version's instruction table (macros take several); "
                   "= fxc's ALU",
                   check(fxc ? std::optional<int>(fxc->arithmetic) : std::nullopt, c.arithmetic)});
    out.push_back({"tex", "TEX instructions", c.texture, limit_of(p.tex),
                   "texld, texldp, texldb, texkill, ...: one slot each (texldd 3, texldl 2); "
                   "= fxc's TEX",
                   check(fxc ? fxc->texture : std::nullopt, c.texture)});
  } else {
    out.push_back({"alu",
                   "ALU instructions",
                   c.arithmetic,
                   {},
                   "arithmetic slots by the version's instruction table; = fxc's ALU",
                   check(fxc ? std::optional<int>(fxc->arithmetic) : std::nullopt, c.arithmetic)});
  }
  out.push_back({"instruction_slots", "instruction slots", c.slots(), limit_of(p.instructions),
                 "arithmetic + texture + flow-control slots",
                 check(fxc ? fxc->slots : std::nullopt, c.slots())});
  out.push_back({"temporaries",
                 "temporaries",
                 c.temporaries,
                 limit_of(p.temporaries),
                 "r0..rN used: N + 1",
                 {}});
  out.push_back({"parameters",
                 "constants",
                 c.constants,
                 limit_of(p.parameters),
                 std::string("c0..cN read or defined: N + 1") +
                     (c.relative_constants ? " (relatively addressed: from the base index)" : ""),
                 {}});
  out.push_back({"attributes",
                 pixel && !model3 ? "texture coordinates (t#)" : "inputs (v#)",
                 c.inputs,
                 limit_of(p.attributes),
                 "distinct input registers declared or read",
                 {}});
  out.push_back({"samplers", "samplers", c.samplers, {}, "distinct s# declared or sampled", {}});
  if (pixel) {
    out.push_back({"dependent_reads",
                   "dependent-read levels",
                   c.dependent_levels,
                   limit_of(p.dependent_levels),
                   "1 + the highest dependent order of a texture read (texld - ps_2_0: first "
                   "order reads an r# or rewrites its destination, n-th depends on an (n-1)-th)",
                   {}});
  }
  return out;
}

}  // namespace

budget::Report budget_d3d9_file(const std::string& file, const std::string& profile) {
  const std::string source = read_text_file(file);
  Program program;
  try {
    program = parse(source);
  } catch (const arbfp::text::SyntaxError& e) {
    throw InputError(file, std::to_string(e.at().line) + ":" + std::to_string(e.at().column),
                     e.message());
  }
  const budget::Profile& checked =
      budget::profile_for(kind_of(program.version), profile, default_profile(program.version));
  const Counts counts = count(program);
  const std::optional<FxcCount> fxc = fxc_count(source);
  const std::string kind = budget::to_string(kind_of(program.version));

  budget::Report r;
  r.file = file;
  r.input = "program";
  r.path = "arbfp";
  r.profiles = {{checked.name, kind + " programs", checked.source}};
  if (fxc) {
    r.check_name = "fxc";
    r.check_source = "fxc's count in the listing's comment (" + fxc->form + ")";
  }
  r.details = {{"header", to_string(program.version), {}},
               {"kind", kind, {}},
               {"language", "D3D9 shader assembly", {}}};
  budget::Item item;
  item.scope = budget::Scope::Program;
  item.name = kind + " program";
  item.program = file;
  item.profile = checked.name;
  item.resources = d3d9_figures(counts, program.version, checked, fxc);
  for (const budget::Resource& f : item.resources) {
    if (f.check && !f.check->agrees) {
      r.notes.push_back("DIFFERS from fxc: " + f.label + " " + std::to_string(f.used) + ", fxc " +
                        std::to_string(f.check->value));
    }
  }
  r.items.push_back(std::move(item));
  return r;
}

}  // namespace lt::d3d9
