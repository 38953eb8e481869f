#include "budget/report.h"

#include <algorithm>

#include "core/error.h"

namespace lt::budget {

const char* to_string(Scope scope) {
  switch (scope) {
    case Scope::Program:
      return "program";
    case Scope::Pass:
      return "pass";
    case Scope::Material:
      return "material";
  }
  return "program";
}

const Resource* Item::find(const std::string& key) const {
  for (const Resource& r : resources) {
    if (r.key == key) return &r;
  }
  return nullptr;
}

int Item::used(const std::string& key) const {
  const Resource* r = find(key);
  LT_CHECK(r != nullptr, "budget row " + name + " has no " + key);
  return r->used;
}

bool Report::fits() const {
  return first_overrun().empty();
}

int Report::most(const std::string& key) const {
  int m = 0;
  for (const Item& item : items) {
    if (const Resource* r = item.find(key)) m = std::max(m, r->used);
  }
  return m;
}

std::string overrun_line(const Item& item, const Resource& r) {
  return item.name + ": " + r.label + ": " + std::to_string(r.used) + " > " +
         std::to_string(*r.limit) + (item.profile.empty() ? "" : " (" + item.profile + ")");
}

std::string Report::first_overrun() const {
  for (const Item& item : items) {
    for (const Resource& r : item.resources) {
      if (r.over()) return file + ": " + overrun_line(item, r);
    }
  }
  return "";
}

}  // namespace lt::budget
