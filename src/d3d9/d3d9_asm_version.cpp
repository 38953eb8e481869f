#include "d3d9/d3d9_asm_version.h"

#include <map>
#include <vector>

namespace lt::d3d9 {

namespace {

struct VersionName {
  Version version;
  const char* token;
  const char* profile;  // its default profile (arb_profiles.cpp)
};

// ps_2_x's default profile is the ps_2_x minimum (96 slots); vs_2_x's is vs_2_0's, whose limits
// it only raises through caps.
const std::vector<VersionName>& version_names() {
  static const std::vector<VersionName> names = {
      {Version::Vs11, "vs_1_1", "vs_1_1"}, {Version::Vs20, "vs_2_0", "vs_2_0"},
      {Version::Vs2x, "vs_2_x", "vs_2_0"}, {Version::Vs30, "vs_3_0", "vs_3_0"},
      {Version::Ps20, "ps_2_0", "ps_2_0"}, {Version::Ps2x, "ps_2_x", "ps_2_x"},
      {Version::Ps30, "ps_3_0", "ps_3_0"},
  };
  return names;
}

const VersionName& name_of(Version v) {
  for (const VersionName& n : version_names()) {
    if (n.version == v) return n;
  }
  return version_names().front();  // unreachable: every version is listed
}

using RegisterCounts = std::map<std::string, int>;

// Per version, the register types and their counts, from each version's "Registers" page:
// vs_1_1: 12 r, 96+ c (256: the most a device reports in MaxVertexShaderConst), one a0, 16 v,
//   oPos oFog oPts, 2 oD, 8 oT.
// vs_2_0 adds 16 i, 16 b, aL and 16 labels l# (2048 in shader model 3); vs_2_x: up to 32 r and the
// predicate p0. vs_3_0: 32 r, 256 c, 16 i, 16 b, 4 samplers (vertex texture fetch), 12 o# replace
// the named
//   outputs.
// ps_2_0: 12 r, 32 c, 16 s, 8 t, 2 v (colours), 4 oC, oDepth; no i, b, p0 or loops.
// ps_2_x: up to 32 r, 16 i, 16 b, p0.
// ps_3_0: 32 r, 224 c, 16 i, 16 b, 16 s, 10 v (t# are gone), vPos, vFace, aL, p0.
const RegisterCounts& counts_of(Version v) {
  static const std::map<Version, RegisterCounts> counts = {
      {Version::Vs11,
       {{"r", 12},
        {"c", 256},
        {"a", 1},
        {"v", 16},
        {"opos", 1},
        {"ofog", 1},
        {"opts", 1},
        {"od", 2},
        {"ot", 8}}},
      {Version::Vs20,
       {{"r", 12},
        {"c", 256},
        {"i", 16},
        {"b", 16},
        {"a", 1},
        {"al", 1},
        {"l", 16},
        {"v", 16},
        {"opos", 1},
        {"ofog", 1},
        {"opts", 1},
        {"od", 2},
        {"ot", 8}}},
      {Version::Vs2x,
       {{"r", 32},
        {"c", 256},
        {"i", 16},
        {"b", 16},
        {"a", 1},
        {"al", 1},
        {"l", 16},
        {"p", 1},
        {"v", 16},
        {"opos", 1},
        {"ofog", 1},
        {"opts", 1},
        {"od", 2},
        {"ot", 8}}},
      {Version::Vs30,
       {{"r", 32},
        {"c", 256},
        {"i", 16},
        {"b", 16},
        {"a", 1},
        {"al", 1},
        {"l", 2048},
        {"p", 1},
        {"s", 4},
        {"v", 16},
        {"o", 12}}},
      {Version::Ps20,
       {{"r", 12}, {"c", 32}, {"s", 16}, {"t", 8}, {"v", 2}, {"oc", 4}, {"odepth", 1}}},
      {Version::Ps2x,
       {{"r", 32},
        {"c", 32},
        {"i", 16},
        {"b", 16},
        {"l", 16},
        {"p", 1},
        {"s", 16},
        {"t", 8},
        {"v", 2},
        {"oc", 4},
        {"odepth", 1}}},
      {Version::Ps30,
       {{"r", 32},
        {"c", 224},
        {"i", 16},
        {"b", 16},
        {"l", 2048},
        {"p", 1},
        {"al", 1},
        {"s", 16},
        {"v", 10},
        {"vpos", 1},
        {"vface", 1},
        {"oc", 4},
        {"odepth", 1}}},
  };
  return counts.at(v);
}

}  // namespace

std::optional<Version> parse_version(const std::string& token) {
  for (const VersionName& n : version_names()) {
    if (token == n.token) return n.version;
  }
  return std::nullopt;
}

std::string to_string(Version v) {
  return name_of(v).token;
}

std::string version_list() {
  std::string out;
  for (const VersionName& n : version_names())
    out += (out.empty() ? "" : ", ") + std::string(n.token);
  return out;
}

bool is_ps1x(const std::string& token) {
  return token.size() == 6 && token.compare(0, 5, "ps_1_") == 0;
}

budget::ProgramKind kind_of(Version v) {
  return is_pixel(v) ? budget::ProgramKind::Fragment : budget::ProgramKind::Vertex;
}

bool is_pixel(Version v) {
  return v == Version::Ps20 || v == Version::Ps2x || v == Version::Ps30;
}

bool is_model3(Version v) {
  return v == Version::Vs30 || v == Version::Ps30;
}

std::string default_profile(Version v) {
  return name_of(v).profile;
}

int register_count(Version v, const std::string& type) {
  const RegisterCounts& c = counts_of(v);
  const auto it = c.find(type);
  return it == c.end() ? 0 : it->second;
}

}  // namespace lt::d3d9
