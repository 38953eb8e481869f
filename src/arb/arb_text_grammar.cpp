#include "arb/arb_text_grammar.h"

#include <map>
#include <set>

namespace lt::arbfp::text {

namespace {

using ir::Op;

const OpcodeInfo kOpcodes[] = {
    {Op::ABS, Form::Vector},  {Op::ADD, Form::Vector},  {Op::ARL, Form::Address},
    {Op::CMP, Form::Vector},  {Op::COS, Form::Scalar},  {Op::DP3, Form::Vector},
    {Op::DP4, Form::Vector},  {Op::DPH, Form::Vector},  {Op::DST, Form::Vector},
    {Op::EX2, Form::Scalar},  {Op::EXP, Form::Scalar},  {Op::FLR, Form::Vector},
    {Op::FRC, Form::Vector},  {Op::KIL, Form::Kill},    {Op::LG2, Form::Scalar},
    {Op::LIT, Form::Vector},  {Op::LOG, Form::Scalar},  {Op::LRP, Form::Vector},
    {Op::MAD, Form::Vector},  {Op::MAX, Form::Vector},  {Op::MIN, Form::Vector},
    {Op::MOV, Form::Vector},  {Op::MUL, Form::Vector},  {Op::POW, Form::Scalar},
    {Op::RCP, Form::Scalar},  {Op::RSQ, Form::Scalar},  {Op::SCS, Form::Scalar},
    {Op::SGE, Form::Vector},  {Op::SIN, Form::Scalar},  {Op::SLT, Form::Vector},
    {Op::SUB, Form::Vector},  {Op::SWZ, Form::Swizzle}, {Op::TEX, Form::Texture},
    {Op::TXB, Form::Texture}, {Op::TXP, Form::Texture}, {Op::XPD, Form::Vector},
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
    if (name == ir::info(o.op).name) return &o;
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
