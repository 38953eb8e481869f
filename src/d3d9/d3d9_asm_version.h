// The version token that opens a Direct3D 9 shader assembly program (vs_2_0, ps_3_0, ...) and
// what it allows: which registers exist and how many of each. The register files are the
// documentation's ("Registers - vs_1_1" ... "Registers - ps_3_0", learn.microsoft.com
// direct3dhlsl/dx9-graphics-reference-asm-*-registers-*); a count a device's caps can raise
// (ps_2_x temporaries, vs constants) is the largest the version allows, and the profile
// (arb_profiles.h) holds the program to what a given card guarantees.
#pragma once

#include <optional>
#include <string>

#include "arb/arb_counter.h"

namespace lt::d3d9 {

enum class Version { Vs11, Vs20, Vs2x, Vs30, Ps20, Ps2x, Ps30 };

// "vs_2_0" -> Vs20; nullopt for any other text. ps_2_a and ps_2_b are fxc's target names, not
// version tokens: fxc writes ps_2_x for both.
std::optional<Version> parse_version(const std::string& token);
std::string to_string(Version v);
// Every version token the reader takes, for messages: "vs_1_1, vs_2_0, ...".
std::string version_list();
// The pixel shader versions of 1.x are another machine (texture stages, co-issue): named so
// the refusal says so rather than "unknown version".
bool is_ps1x(const std::string& token);

budget::ProgramKind kind_of(Version v);
bool is_pixel(Version v);
// 3_0 and above (vs_3_0, ps_3_0): the shader model 3 rules (_abs, output registers o#).
bool is_model3(Version v);
// The profile a program of this version is checked against when --profile is not given.
std::string default_profile(Version v);

// How many registers of a type the version has (0: the type does not exist in the version);
// `type` is the register's name without its index, lower case ("r", "c", "oc", "opos").
int register_count(Version v, const std::string& type);

}  // namespace lt::d3d9
