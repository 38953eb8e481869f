#include "paths/arbfp/arb_counter.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace lt::budget {

const char* to_string(ProgramKind k) {
  return k == ProgramKind::Vertex ? "vertex" : "fragment";
}

namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

// Splits at commas outside {} and [].
std::vector<std::string> split_operands(const std::string& s) {
  std::vector<std::string> out;
  int depth = 0;
  std::string cur;
  for (char c : s) {
    if (c == '{' || c == '[') ++depth;
    if (c == '}' || c == ']') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!trim(cur).empty()) out.push_back(trim(cur));
  return out;
}

bool is_swizzle(const std::string& s) {
  return !s.empty() && s.size() <= 4 && std::all_of(s.begin(), s.end(), [](char c) {
    return std::string("xyzwrgba").find(c) != std::string::npos;
  });
}

// "-lobe0.xyz" -> "lobe0"; "fragment.texcoord[1].x" -> "fragment.texcoord[1]".
std::string operand_base(std::string op) {
  op = trim(op);
  while (!op.empty() && (op[0] == '-' || op[0] == '+')) op = trim(op.substr(1));
  if (op.empty() || op[0] == '{' || std::isdigit(static_cast<unsigned char>(op[0])) || op[0] == '.')
    return op;
  const size_t dot = op.rfind('.');
  if (dot != std::string::npos && is_swizzle(op.substr(dot + 1)) && op.find('.') != dot) {
    return op.substr(0, dot);  // binding with a swizzle
  }
  if (dot != std::string::npos && is_swizzle(op.substr(dot + 1)) && op.find('.') == dot &&
      op.find('[') == std::string::npos && op.rfind("fragment", 0) != 0 &&
      op.rfind("vertex", 0) != 0 && op.rfind("result", 0) != 0 && op.rfind("state", 0) != 0 &&
      op.rfind("program", 0) != 0) {
    return op.substr(0, dot);  // name.swizzle
  }
  return op;
}

bool is_texture_opcode(const std::string& op) {
  return op == "TEX" || op == "TXP" || op == "TXB" || op == "KIL";
}

}  // namespace

ProgramCounts count_program(const std::string& source) {
  ProgramCounts c;
  // Strip comments, find the header.
  std::string text;
  {
    std::istringstream in(source);
    std::string line;
    while (std::getline(in, line)) text += line.substr(0, line.find('#')) + "\n";
  }
  const size_t bang = text.find("!!ARB");
  if (bang == std::string::npos) throw std::invalid_argument("no !!ARBvp1.0 / !!ARBfp1.0 header");
  if (text.compare(bang, 10, "!!ARBvp1.0") == 0) {
    c.kind = ProgramKind::Vertex;
  } else if (text.compare(bang, 10, "!!ARBfp1.0") == 0) {
    c.kind = ProgramKind::Fragment;
  } else {
    throw std::invalid_argument("unknown program header");
  }
  text = text.substr(bang + 10);

  std::set<std::string> temps, params, inline_params, attributes;
  std::map<std::string, std::string> attrib_aliases;  // ATTRIB name = binding
  // Issue 24: temporaries written since the last indirection (tempsOutput), and temporaries an
  // ALU instruction read or wrote since then (aluTemps).
  std::set<std::string> temps_output, alu_temps;

  std::istringstream statements(text);
  std::string st;
  while (std::getline(statements, st, ';')) {
    st = trim(st);
    if (st.empty()) continue;
    if (st == "END" || st.rfind("END", 0) == 0) break;
    std::istringstream words(st);
    std::string opcode;
    words >> opcode;
    std::string rest;
    std::getline(words, rest);
    rest = trim(rest);
    if (opcode == "OPTION") {
      if (rest == "ARB_position_invariant") c.position_invariant = true;
      continue;
    }
    if (opcode == "TEMP") {
      for (const std::string& n : split_operands(rest)) temps.insert(n);
      continue;
    }
    if (opcode == "ADDRESS" || opcode == "OUTPUT" || opcode == "ALIAS") continue;
    if (opcode == "ATTRIB") {
      const size_t eq = rest.find('=');
      if (eq == std::string::npos) throw std::invalid_argument("ATTRIB without '=': " + st);
      attrib_aliases[trim(rest.substr(0, eq))] = trim(rest.substr(eq + 1));
      continue;
    }
    if (opcode == "PARAM") {
      const size_t eq = rest.find('=');
      if (eq == std::string::npos) throw std::invalid_argument("PARAM without '=': " + st);
      std::string name = trim(rest.substr(0, eq));
      int size = 1;
      const size_t br = name.find('[');
      if (br != std::string::npos) {
        const std::string n = name.substr(br + 1, name.find(']') - br - 1);
        name = trim(name.substr(0, br));
        if (!n.empty()) {
          size = std::stoi(n);
        } else {  // PARAM a[] = { {..}, {..} }: count the top-level entries
          std::string init = trim(rest.substr(eq + 1));
          if (init.size() >= 2 && init.front() == '{') init = init.substr(1, init.size() - 2);
          size = static_cast<int>(split_operands(init).size());
        }
      }
      params.insert(name);
      c.parameters += size;
      continue;
    }
    // An instruction.
    std::string op = opcode;
    if (op.size() > 4 && op.substr(op.size() - 4) == "_SAT") op = op.substr(0, op.size() - 4);
    const std::vector<std::string> operands = split_operands(rest);
    if (operands.empty()) throw std::invalid_argument("instruction without operands: " + st);
    const bool texture = c.kind == ProgramKind::Fragment && is_texture_opcode(op);
    // KIL has only a source; everything else has a destination first.
    const bool has_dst = op != "KIL";
    size_t n_src = operands.size() - (has_dst ? 1 : 0);
    if (texture && op != "KIL") n_src = 1;  // texture[n] and the target are not operands
    std::string dst_temp;
    if (has_dst) {
      const std::string d = operand_base(operands[0]);
      if (temps.count(d)) dst_temp = d;
    }
    std::vector<std::string> src_temps;
    for (size_t k = 0; k < n_src; ++k) {
      const std::string& raw = operands[(has_dst ? 1 : 0) + k];
      std::string b = operand_base(raw);
      if (attrib_aliases.count(b)) b = attrib_aliases[b];
      // An element of a declared PARAM array (c[0]) is part of that declaration.
      const size_t br = b.find('[');
      if (br != std::string::npos && params.count(b.substr(0, br))) b = b.substr(0, br);
      if (temps.count(b)) {
        src_temps.push_back(b);
      } else if (params.count(b)) {
        // a declared PARAM: already counted
      } else if (b.rfind("fragment.", 0) == 0 || b.rfind("vertex.", 0) == 0) {
        attributes.insert(b);
      } else if (!b.empty()) {
        inline_params.insert(b);  // literal or program.*/state.* binding used directly
      }
    }
    if (texture) {
      ++c.tex;
      const bool reads_new = !src_temps.empty() && temps_output.count(src_temps[0]);
      const bool overwrites_alu = !dst_temp.empty() && alu_temps.count(dst_temp);
      if (reads_new || overwrites_alu) {
        ++c.indirections;
        temps_output.clear();
        alu_temps.clear();
      }
    } else {
      ++c.alu;
      for (const std::string& t : src_temps) alu_temps.insert(t);
      if (!dst_temp.empty()) alu_temps.insert(dst_temp);
    }
    if (op != "KIL" && !dst_temp.empty()) temps_output.insert(dst_temp);
  }
  c.temporaries = static_cast<int>(temps.size());
  c.parameters += static_cast<int>(inline_params.size());
  for (const auto& [name, binding] : attrib_aliases) attributes.insert(binding);
  c.attributes = static_cast<int>(attributes.size());
  if (c.kind == ProgramKind::Vertex) {
    c.alu += c.tex;
    c.tex = 0;
    c.indirections = 1;
  }
  return c;
}

}  // namespace lt::budget
