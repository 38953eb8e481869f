#include "report/figure_pairs.h"

#include <cctype>
#include <optional>
#include <sstream>

namespace lt {

namespace {

struct FigureName {
  std::string figure, parameter, value;
  bool left = false;
};

std::vector<std::string> split(const std::string& name) {
  std::vector<std::string> tokens;
  std::stringstream s(name);
  for (std::string t; std::getline(s, t, '_');) tokens.push_back(t);
  return tokens;
}

// "0p2" -> "0.2"; any other token as it is.
std::string value_token(const std::string& t) {
  const std::size_t p = t.find('p');
  const auto digits = [](const std::string& d) {
    if (d.empty()) return false;
    for (char c : d)
      if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
  };
  if (p != std::string::npos && digits(t.substr(0, p)) && digits(t.substr(p + 1)))
    return t.substr(0, p) + "." + t.substr(p + 1);
  return t;
}

std::string joined(const std::vector<std::string>& tokens, std::size_t from, std::size_t to,
                   bool values) {
  std::string out;
  for (std::size_t i = from; i < to; ++i)
    out += (out.empty() ? "" : " ") + (values ? value_token(tokens[i]) : tokens[i]);
  return out;
}

// <figure>_<parameter...>_<a|b>_<value...>: the first "a" or "b" token with a figure and a
// parameter before it and a value after it.
std::optional<FigureName> parse(const std::string& name) {
  const std::vector<std::string> t = split(name);
  for (std::size_t k = 2; k + 1 < t.size(); ++k) {
    if (t[k] != "a" && t[k] != "b") continue;
    return FigureName{t[0], joined(t, 1, k, false), joined(t, k + 1, t.size(), true), t[k] == "a"};
  }
  return std::nullopt;
}

}  // namespace

std::vector<FigureRow> figure_rows(const std::vector<std::string>& names) {
  std::vector<FigureRow> rows;
  bool paired_any = false;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::optional<FigureName> left = parse(names[i]);
    const std::optional<FigureName> right =
        i + 1 < names.size() ? parse(names[i + 1]) : std::nullopt;
    if (left && right && left->left && !right->left && left->parameter == right->parameter) {
      const std::string figures =
          left->figure == right->figure ? left->figure : left->figure + "/" + right->figure;
      rows.push_back(
          {figures + " " + left->parameter,
           {i, i + 1},
           {left->parameter + " " + left->value, right->parameter + " " + right->value}});
      paired_any = true;
      ++i;
      continue;
    }
    rows.push_back({names[i], {i}, {""}});
  }
  if (!paired_any) rows.clear();
  return rows;
}

}  // namespace lt
