#include "paths/arbfp/arb_profiles.h"

#include "core/error.h"
#include "core/find_named.h"

namespace lt::budget {

const std::vector<Profile>& all_profiles() {
  static const std::vector<Profile> profiles = {
      // D3D9 pixel shader 2.0: 64 arithmetic + 32 texture instructions, 12 temporaries (r#),
      // 32 constants (c#), 8 texture coordinate inputs (t#), and 4 levels of dependent reads.
      // ARB counts the first, non-dependent, node as an indirection too, so 4 dependent levels
      // are 5 texture indirections.
      {"ps_2_0", ProgramKind::Fragment, "vs_2_0", 64, 32, -1, 12, 32, 8, 5,
       "D3D9 ps_2_0: 64 ALU, 32 TEX, 12 temps, 32 constants, 8 texcoords, 4 dependent-read levels"},
      // ps_2_x guarantees at least 96 instruction slots (ALU and TEX together); the other minimums
      // are those of ps_2_0.
      {"ps_2_x", ProgramKind::Fragment, "vs_2_0", -1, -1, 96, 12, 32, 8, 5,
       "D3D9 ps_2_x minimum: 96 instruction slots, otherwise as ps_2_0"},
      // ARB_fragment_program's minimum maximums (MAX_PROGRAM_NATIVE_*): what every implementation
      // must accept.
      {"arbfp1-min", ProgramKind::Fragment, "arbvp1-min", 48, 24, 72, 16, 24, 10, 4,
       "ARB_fragment_program minimums: 48 ALU, 24 TEX, 72 instructions, 16 temps, 24 params, "
       "10 attribs, 4 indirections"},
      // D3D9 vs_2_0: 256 instruction slots, 12 temporaries, 256 constants (c#), 16 inputs (v#).
      {"vs_2_0", ProgramKind::Vertex, "ps_2_0", -1, -1, 256, 12, 256, 16, -1,
       "D3D9 vs_2_0: 256 instruction slots, 12 temps, 256 constants, 16 inputs"},
      // ARB_vertex_program's minimum maximums.
      {"arbvp1-min", ProgramKind::Vertex, "arbfp1-min", -1, -1, 128, 12, 96, 16, -1,
       "ARB_vertex_program minimums: 128 instructions, 12 temps, 96 params, 16 attribs"},
  };
  return profiles;
}

const Profile& find_profile(const std::string& name) {
  return find_named(all_profiles(), name, "--profile", "profile");
}

std::vector<Overrun> check(const ProgramCounts& c, const Profile& p) {
  std::vector<Overrun> out;
  auto over = [&out](const char* limit, int count, int max) {
    if (max >= 0 && count > max) out.push_back({limit, count, max});
  };
  over("ALU instructions", c.alu, p.alu);
  over("TEX instructions", c.tex, p.tex);
  // position_invariant makes the driver append the 4 DP4 of the transform: they use slots too.
  over("instruction slots", c.instructions() + (c.position_invariant ? 4 : 0), p.instructions);
  over("temporaries", c.temporaries, p.temporaries);
  over("parameters", c.parameters, p.parameters);
  over("attributes", c.attributes, p.attributes);
  over("texture indirections", c.indirections, p.indirections);
  return out;
}

std::vector<Resource> program_resources(const ProgramCounts& c, const Profile& p) {
  const bool fragment = c.kind == ProgramKind::Fragment;
  auto limit = [](int max) { return max >= 0 ? std::optional<int>(max) : std::nullopt; };
  std::vector<Resource> out;
  out.push_back({"alu", "ALU instructions", c.alu, limit(p.alu), "", {}});
  if (fragment) out.push_back({"tex", "TEX instructions", c.tex, limit(p.tex), "", {}});
  // As check(): the 4 DP4 the driver appends for ARB_position_invariant take slots too.
  out.push_back({"instruction_slots",
                 "instruction slots",
                 c.instructions() + (c.position_invariant ? 4 : 0),
                 limit(p.instructions),
                 c.position_invariant ? "ALU + TEX + the 4 DP4 of ARB_position_invariant" : "",
                 {}});
  out.push_back({"temporaries", "temporaries", c.temporaries, limit(p.temporaries), "", {}});
  out.push_back({"parameters", "parameters", c.parameters, limit(p.parameters), "", {}});
  out.push_back({"attributes", "attributes", c.attributes, limit(p.attributes), "", {}});
  if (fragment) {
    out.push_back(
        {"indirections", "texture indirections", c.indirections, limit(p.indirections), "", {}});
  }
  out.push_back({"address_registers", "address registers", c.address_registers, {}, "", {}});
  return out;
}

}  // namespace lt::budget
