#include "budget/arb_profiles.h"

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
       "D3D9 ps_2_0: 64 ALU, 32 TEX, 12 temps, 32 constants, 8 texcoords, 4 dependent-read levels",
       4},
      // ps_2_x guarantees at least 96 instruction slots (ALU and TEX together); the other minimums
      // are those of ps_2_0.
      {"ps_2_x", ProgramKind::Fragment, "vs_2_0", -1, -1, 96, 12, 32, 8, 5,
       "D3D9 ps_2_x minimum: 96 instruction slots, otherwise as ps_2_0", 4},
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
      // fxc's ps_2_a target (GeForce FX): ps_2_x with D3DPS20CAPS_NODEPENDENTREADLIMIT and
      // NOTEXINSTRUCTIONLIMIT, 512 slots, 22 temporaries (fxc's profile caps, "ps_2_x").
      {"ps_2_a", ProgramKind::Fragment, "vs_2_0", -1, -1, 512, 22, 32, 8, -1,
       "fxc ps_2_a: 512 instruction slots, 22 temps, 32 constants, 8 texcoords, no dependent-read "
       "limit"},
      // fxc's ps_2_b target (Radeon X800): 512 slots and 32 temporaries, but neither cap: at most
      // 32 texture instructions and 4 dependent-read levels, as ps_2_0.
      {"ps_2_b", ProgramKind::Fragment, "vs_2_0", -1, 32, 512, 32, 32, 8, 5,
       "fxc ps_2_b: 512 instruction slots (32 TEX), 32 temps, 32 constants, 8 texcoords, "
       "4 dependent-read levels",
       4},
      // ps_3_0: 512 slots at least, 32 temporaries, 224 constants, 10 inputs (v#), no
      // dependent-read limit ("Registers - ps_3_0", "Pixel Shader Differences").
      {"ps_3_0", ProgramKind::Fragment, "vs_3_0", -1, -1, 512, 32, 224, 10, -1,
       "D3D9 ps_3_0: 512 instruction slots, 32 temps, 224 constants, 10 inputs"},
      // vs_1_1: 128 slots, 12 temporaries, 96 constants at least, 16 inputs ("Registers -
      // vs_1_1", "Vertex Shader Differences").
      {"vs_1_1", ProgramKind::Vertex, "ps_2_0", -1, -1, 128, 12, 96, 16, -1,
       "D3D9 vs_1_1: 128 instruction slots, 12 temps, 96 constants, 16 inputs"},
      // vs_3_0: 512 slots at least, 32 temporaries, 256 constants, 16 inputs.
      {"vs_3_0", ProgramKind::Vertex, "ps_3_0", -1, -1, 512, 32, 256, 16, -1,
       "D3D9 vs_3_0: 512 instruction slots, 32 temps, 256 constants, 16 inputs"},
  };
  return profiles;
}

const Profile& find_profile(const std::string& name) {
  return find_named(all_profiles(), name, "--profile", "profile");
}

const Profile& profile_for(ProgramKind kind, const std::string& name, const std::string& fallback) {
  const Profile& chosen = find_profile(name.empty() ? fallback : name);
  return chosen.kind == kind ? chosen : find_profile(chosen.partner);
}

std::optional<int> limit_of(int max) {
  return max >= 0 ? std::optional<int>(max) : std::nullopt;
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
  std::vector<Resource> out;
  out.push_back({"alu", "ALU instructions", c.alu, limit_of(p.alu), "", {}});
  if (fragment) out.push_back({"tex", "TEX instructions", c.tex, limit_of(p.tex), "", {}});
  // As check(): the 4 DP4 the driver appends for ARB_position_invariant take slots too.
  out.push_back({"instruction_slots",
                 "instruction slots",
                 c.instructions() + (c.position_invariant ? 4 : 0),
                 limit_of(p.instructions),
                 c.position_invariant ? "ALU + TEX + the 4 DP4 of ARB_position_invariant" : "",
                 {}});
  out.push_back({"temporaries", "temporaries", c.temporaries, limit_of(p.temporaries), "", {}});
  out.push_back({"parameters", "parameters", c.parameters, limit_of(p.parameters), "", {}});
  out.push_back({"attributes", "attributes", c.attributes, limit_of(p.attributes), "", {}});
  if (fragment) {
    out.push_back(
        {"indirections", "texture indirections", c.indirections, limit_of(p.indirections), "", {}});
  }
  out.push_back({"address_registers", "address registers", c.address_registers, {}, "", {}});
  return out;
}

}  // namespace lt::budget
