#include "paths/arbfp/arb_text_grammar.h"

#include <map>
#include <set>

namespace lt::arbfp::text {

namespace {

const OpcodeInfo kOpcodes[] = {
    {"ABS", Form::Vector, 1, true, true},   {"ADD", Form::Vector, 2, true, true},
    {"ARL", Form::Address, 1, true, false}, {"CMP", Form::Vector, 3, false, true},
    {"COS", Form::Scalar, 1, false, true},  {"DP3", Form::Vector, 2, true, true},
    {"DP4", Form::Vector, 2, true, true},   {"DPH", Form::Vector, 2, true, true},
    {"DST", Form::Vector, 2, true, true},   {"EX2", Form::Scalar, 1, true, true},
    {"EXP", Form::Scalar, 1, true, false},  {"FLR", Form::Vector, 1, true, true},
    {"FRC", Form::Vector, 1, true, true},   {"KIL", Form::Kill, 1, false, true},
    {"LG2", Form::Scalar, 1, true, true},   {"LIT", Form::Vector, 1, true, true},
    {"LOG", Form::Scalar, 1, true, false},  {"LRP", Form::Vector, 3, false, true},
    {"MAD", Form::Vector, 3, true, true},   {"MAX", Form::Vector, 2, true, true},
    {"MIN", Form::Vector, 2, true, true},   {"MOV", Form::Vector, 1, true, true},
    {"MUL", Form::Vector, 2, true, true},   {"POW", Form::Scalar, 2, true, true},
    {"RCP", Form::Scalar, 1, true, true},   {"RSQ", Form::Scalar, 1, true, true},
    {"SCS", Form::Scalar, 1, false, true},  {"SGE", Form::Vector, 2, true, true},
    {"SIN", Form::Scalar, 1, false, true},  {"SLT", Form::Vector, 2, true, true},
    {"SUB", Form::Vector, 2, true, true},   {"SWZ", Form::Swizzle, 1, true, true},
    {"TEX", Form::Texture, 1, false, true}, {"TXB", Form::Texture, 1, false, true},
    {"TXP", Form::Texture, 1, false, true}, {"XPD", Form::Vector, 2, true, true},
};

const char* const kFragmentOptions[] = {"ARB_precision_hint_fastest",
                                        "ARB_precision_hint_nicest",
                                        "ARB_fog_exp",
                                        "ARB_fog_exp2",
                                        "ARB_fog_linear",
                                        "ARB_fragment_program_shadow",
                                        "ARB_draw_buffers"};
const char* const kVertexOptions[] = {"ARB_position_invariant"};

}  // namespace

const OpcodeInfo* find_opcode(const std::string& name) {
  for (const OpcodeInfo& o : kOpcodes) {
    if (name == o.name) return &o;
  }
  return nullptr;
}

// Names the grammar reserves: a program cannot declare them.
bool reserved(const std::string& n) {
  static const std::set<std::string> words = {"ATTRIB", "PARAM",   "TEMP",   "ADDRESS",  "OUTPUT",
                                              "ALIAS",  "OPTION",  "END",    "fragment", "vertex",
                                              "state",  "program", "result", "texture"};
  if (words.count(n)) return true;
  const std::string base =
      n.size() > 4 && n.compare(n.size() - 4, 4, "_SAT") == 0 ? n.substr(0, n.size() - 4) : n;
  return find_opcode(base) != nullptr;
}

bool known_option(const std::string& name, bool vertex) {
  if (vertex) {
    for (const char* o : kVertexOptions) {
      if (name == o) return true;
    }
    return false;
  }
  for (const char* o : kFragmentOptions) {
    if (name == o) return true;
  }
  return false;
}

// Generic vertex attributes that alias a named one (ARB_vertex_program table X.2.1): a program
// may not read both (Mesa: "illegal use of generic attribute and name attribute").
std::string named_alias_of_generic(const std::string& binding) {
  static const std::map<std::string, std::string> alias = {
      {"vertex.attrib[0]", "vertex.position"},      {"vertex.attrib[2]", "vertex.normal"},
      {"vertex.attrib[3]", "vertex.color.primary"}, {"vertex.attrib[4]", "vertex.color.secondary"},
      {"vertex.attrib[5]", "vertex.fogcoord"},      {"vertex.attrib[8]", "vertex.texcoord[0]"},
      {"vertex.attrib[9]", "vertex.texcoord[1]"},   {"vertex.attrib[10]", "vertex.texcoord[2]"},
      {"vertex.attrib[11]", "vertex.texcoord[3]"},  {"vertex.attrib[12]", "vertex.texcoord[4]"},
      {"vertex.attrib[13]", "vertex.texcoord[5]"},  {"vertex.attrib[14]", "vertex.texcoord[6]"},
      {"vertex.attrib[15]", "vertex.texcoord[7]"}};
  const auto it = alias.find(binding);
  return it == alias.end() ? "" : it->second;
}

std::string generic_of_named(const std::string& b) {
  for (int i = 0; i < 16; ++i) {
    const std::string g = "vertex.attrib[" + std::to_string(i) + "]";
    if (named_alias_of_generic(g) == b) return g;
  }
  return "";
}

}  // namespace lt::arbfp::text
