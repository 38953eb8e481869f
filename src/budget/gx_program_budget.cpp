#include "budget/gx_program_budget.h"

#include <bitset>
#include <set>

#include "core/error.h"
#include "core/find_named.h"
#include "gx/program/parser.h"

namespace lt::gx {

namespace {

// A colour operand that reads a TEV register (CPREV/APREV/C0/A0/..: 0..7) names register
// sel / 2; the alpha operands APREV/A0/A1/A2 (0..3) name register sel.
void count_registers(const TevStage& s, std::set<int>& regs) {
  for (u8 sel : {s.color.a, s.color.b, s.color.c, s.color.d}) {
    if (sel < 8) regs.insert(sel / 2);
  }
  for (u8 sel : {s.alpha.a, s.alpha.b, s.alpha.c, s.alpha.d}) {
    if (sel < 4) regs.insert(sel);
  }
  regs.insert(s.color.dest);
  regs.insert(s.alpha.dest);
}

// A konst selector 12..31 reads K0..K3 (the low two bits); 0..7 are fixed fractions
// [HWT gxtest/tev.cpp KonstTest].
void count_konst(const TevStage& s, std::set<int>& konst) {
  const bool colour_reads =
      s.color.a == 14 || s.color.b == 14 || s.color.c == 14 || s.color.d == 14;
  const bool alpha_reads = s.alpha.a == 6 || s.alpha.b == 6 || s.alpha.c == 6 || s.alpha.d == 6;
  if (colour_reads && s.konst_color_sel >= 12) konst.insert(s.konst_color_sel & 3);
  if (alpha_reads && s.konst_alpha_sel >= 12) konst.insert(s.konst_alpha_sel & 3);
}

std::vector<budget::Resource> resources(const GxCounts& c, const GxCounts& lim) {
  // A limit below 0 is none.
  auto row = [&](const char* key, const char* label, int GxCounts::*n) {
    return budget::Resource{
        key, label, c.*n, lim.*n >= 0 ? std::optional<int>(lim.*n) : std::nullopt, "", {}};
  };
  return {row("tev_stages", "TEV stages", &GxCounts::tev_stages),
          row("texgens", "texgens", &GxCounts::texgens),
          row("texture_maps", "texture maps", &GxCounts::texture_maps),
          row("channels", "colour channels", &GxCounts::channels),
          row("lights_per_channel", "lights per channel", &GxCounts::lights_per_channel),
          row("konst_colors", "konst colours", &GxCounts::konst_colors),
          row("tev_registers", "TEV registers", &GxCounts::tev_registers),
          row("vertex_attributes", "vertex attributes", &GxCounts::vertex_attributes)};
}

// Throws InputError("--profile", ...) naming the valid profiles.
const GxProfile& find_gx_profile(const std::string& name) {
  return find_named(gx_profiles(), name, "--profile", "gx profile");
}

}  // namespace

GxCounts count_program(const GxState& st) {
  GxCounts c;
  c.tev_stages = st.tev.num_stages;
  c.texgens = st.texgen.num_texgens;
  c.channels = st.lighting.num_channels;
  std::set<int> maps, regs, konst;
  // Counts beyond the hardware's are reported as they are; only the 16 stages that exist and
  // the 2 channels hold state to look at.
  for (int i = 0; i < std::min(st.tev.num_stages, kMaxTevStages); ++i) {
    const TevStage& s = st.tev.stages[static_cast<size_t>(i)];
    if (s.texmap != kTexMapNull) maps.insert(s.texmap);
    count_registers(s, regs);
    count_konst(s, konst);
  }
  c.texture_maps = static_cast<int>(maps.size());
  c.tev_registers = static_cast<int>(regs.size());
  c.konst_colors = static_cast<int>(konst.size());
  for (int ch = 0; ch < std::min(st.lighting.num_channels, kMaxChannels); ++ch) {
    for (int part : {ch, ch + 2}) {
      const ChannelControl& ctl = st.lighting.control[static_cast<size_t>(part)];
      if (ctl.lighting)
        c.lights_per_channel = std::max(c.lights_per_channel,
                                        static_cast<int>(std::bitset<8>(ctl.light_mask).count()));
    }
  }
  c.vertex_attributes = st.vertex.count();
  return c;
}

const std::vector<GxProfile>& gx_profiles() {
  GxCounts wii;
  wii.tev_stages = 16;         // [OGC gx.h L569, L3070]
  wii.texgens = 8;             // [OGC gx.h L279, L2692]
  wii.texture_maps = 8;        // [OGC gx.h L673]
  wii.channels = 2;            // COLOR0A0, COLOR1A1 [OGC gx.h L3003-3011]
  wii.lights_per_channel = 8;  // GX_LIGHT0..7 [OGC gx.h L178-187]
  wii.konst_colors = 4;        // GX_KCOLOR0..3 [OGC gx.h L692-696]
  wii.tev_registers = 4;       // PREV, REG0..2 [OGC gx.h L637-641]
  wii.vertex_attributes = 12;  // GX_VA_POS .. GX_VA_TEX7 that carry data per vertex
  static const std::vector<GxProfile> profiles = {
      {"wii-tev",
       "Wii / GameCube GX: 16 TEV stages, 8 texgens, 8 texture maps, 2 colour "
       "channels, 8 lights, 4 konst colours, PREV + 3 TEV registers",
       wii, "devkitPro/libogc gc/ogc/gx.h; docs/spec/gx-hardware.md section 4"}};
  return profiles;
}

budget::Report gx_programs_report(const std::vector<std::vector<PassProgram>>& by_material,
                                  const std::vector<std::string>& material_names,
                                  const std::string& profile) {
  const GxProfile& prof = find_gx_profile(profile.empty() ? "wii-tev" : profile);
  budget::Report r;
  r.path = "gx";
  r.profiles = {{prof.name, "", prof.summary + " (" + prof.source + ")"}};
  std::vector<budget::Item> materials;
  for (size_t m = 0; m < by_material.size(); ++m) {
    std::string material;
    for (const PassProgram& p : by_material[m]) {
      budget::Item b;
      b.scope = budget::Scope::Pass;
      b.material = m < material_names.size() ? material_names[m] : p.material;
      material = b.material;
      b.name = b.material.empty() ? p.name
                                  : "material " + b.material + " pass " + std::to_string(p.pass) +
                                        " (" + p.name + ")";
      b.profile = prof.name;
      b.resources = resources(count_program(p.state), prof.limits);
      r.items.push_back(std::move(b));
    }
    if (by_material[m].empty()) continue;
    budget::Item passes;
    passes.scope = budget::Scope::Material;
    passes.name = (material.empty() ? "(whole file)" : "material " + material) + ": passes";
    passes.material = material;
    passes.resources = {{"passes", "passes", static_cast<int>(by_material[m].size()), {}, "", {}}};
    passes.note = "passes: additive EFB blending, no hardware limit";
    materials.push_back(std::move(passes));
  }
  r.items.insert(r.items.end(), materials.begin(), materials.end());
  return r;
}

budget::Report gx_budget_file(const std::string& program_file, const std::string& profile) {
  const ProgramFile file = load_program(program_file);
  std::vector<std::vector<PassProgram>> groups;
  std::map<std::string, size_t> index;
  for (PassProgram& p : file_programs(file)) {
    if (!index.count(p.material)) {
      index[p.material] = groups.size();
      groups.emplace_back();
    }
    groups[index[p.material]].push_back(std::move(p));
  }
  budget::Report r = gx_programs_report(groups, {}, profile);
  r.file = program_file;
  r.input = "program";
  return r;
}

}  // namespace lt::gx
