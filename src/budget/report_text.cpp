// The text writer of the budget report. Every line starts with the file it reports on, so the
// output of several files can be grepped (`budget *.comb | grep OVER` names each file over).
#include <set>
#include <sstream>

#include "budget/report.h"

namespace lt::budget {

namespace {

// "24/64", "70/64!" over the limit, "3" with none.
std::string used_of(const Resource& r) {
  std::string s = std::to_string(r.used);
  if (r.limit) s += "/" + std::to_string(*r.limit) + (r.over() ? "!" : "");
  return s;
}

bool has_limits(const Item& item) {
  for (const Resource& r : item.resources) {
    if (r.limit) return true;
  }
  return false;
}

bool has_checks(const Item& item) {
  for (const Resource& r : item.resources) {
    if (r.check) return true;
  }
  return false;
}

// "program material marble: fragment program"; a name that starts with its scope says it once
// ("material marble: translucency term").
std::string head_of(const Item& item) {
  const std::string scope = to_string(item.scope);
  std::string s = item.name.rfind(scope + " ", 0) == 0 ? item.name : scope + " " + item.name;
  if (!item.program.empty()) s += " (" + item.program + ")";
  return s;
}

// The verdict of a row that has limits: "fits ps_2_0" or "OVER ps_2_0".
std::string verdict_of(const Item& item) {
  if (!has_limits(item)) return "";
  bool over = false;
  for (const Resource& r : item.resources) over = over || r.over();
  return std::string(over ? "OVER" : "fits") + (item.profile.empty() ? "" : " " + item.profile);
}

}  // namespace

std::string to_text(const Report& r) {
  std::ostringstream o;
  const std::string at = r.file + ": ";
  o << at << "budget of a " << (r.input == "scene" ? "scene" : "program file") << ", path "
    << r.path << (r.variant.empty() ? "" : ", variant " + r.variant) << "; used/limit, ! = over\n";
  for (const ProfileUse& p : r.profiles) {
    o << at << "profile " << p.name << (p.applies_to.empty() ? "" : " (" + p.applies_to + ")")
      << ": " << p.summary << "\n";
  }
  for (const Detail& d : r.details) {
    o << at << d.key << ": " << (d.number ? std::to_string(*d.number) : d.text) << "\n";
  }
  if (!r.check_name.empty()) o << at << r.check_name << ": " << r.check_source << "\n";
  // A row with a second counter's figures takes a line per resource (figure, Mesa's, the rule
  // that relates them); any other row is one line, its rules said once below.
  std::set<std::string> said;
  std::vector<std::string> rules;
  for (const Item& item : r.items) {
    const std::string verdict = verdict_of(item);
    if (has_checks(item)) {
      o << at << head_of(item) << (verdict.empty() ? "" : ": " + verdict) << "\n";
      for (const Resource& res : item.resources) {
        o << at << "  " << res.label << " " << used_of(res);
        if (res.check) {
          o << ", " << r.check_name << " " << res.check->value
            << (res.check->agrees ? "" : " DIFFERS");
        }
        o << (res.rule.empty() ? "" : ": " + res.rule) << "\n";
      }
    } else {
      o << at << head_of(item) << ":";
      for (size_t i = 0; i < item.resources.size(); ++i) {
        const Resource& res = item.resources[i];
        o << (i == 0 ? " " : ", ") << res.label << " " << used_of(res);
        if (!res.rule.empty() && said.insert(res.label + ": " + res.rule).second)
          rules.push_back(res.label + ": " + res.rule);
      }
      o << (verdict.empty() ? "" : "; " + verdict) << "\n";
    }
    if (!item.note.empty()) o << at << "  " << item.note << "\n";
  }
  for (const std::string& rule : rules) o << at << "rule: " << rule << "\n";
  for (const std::string& n : r.notes) o << at << "note: " << n << "\n";
  size_t over = 0;
  for (const Item& item : r.items) {
    for (const Resource& res : item.resources) {
      if (!res.over()) continue;
      o << at << "OVER " << overrun_line(item, res) << "\n";
      ++over;
    }
  }
  if (over == 0) {
    std::string names;
    for (const ProfileUse& p : r.profiles) names += (names.empty() ? " " : " + ") + p.name;
    o << at << "fits" << names << "\n";
  } else {
    o << at << "OVER BUDGET: " << over << (over == 1 ? " limit" : " limits") << " exceeded\n";
  }
  return o.str();
}

}  // namespace lt::budget
