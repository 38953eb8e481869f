// The JSON writer of the budget report: schema ltrender-budget-2 (docs/budget.md), the same keys
// for a scene and for every kind of program file, and a record of its own for an invalid file.
#include <nlohmann/json.hpp>

#include "budget/report.h"

namespace lt::budget {

namespace {

using Json = nlohmann::ordered_json;

Json or_null(const std::string& s) {
  return s.empty() ? Json(nullptr) : Json(s);
}

Json resource_json(const Resource& r) {
  Json j;
  j["key"] = r.key;
  j["label"] = r.label;
  j["used"] = r.used;
  j["limit"] = r.limit ? Json(*r.limit) : Json(nullptr);
  j["over"] = r.over();
  j["rule"] = or_null(r.rule);
  j["check"] =
      r.check ? Json{{"value", r.check->value}, {"agrees", r.check->agrees}} : Json(nullptr);
  return j;
}

std::string dump(const Json& j, int indent) {
  return j.dump(indent < 0 ? -1 : indent);
}

}  // namespace

std::string to_json(const Report& r, int indent) {
  Json j;
  j["schema"] = kSchema;
  j["file"] = r.file;
  j["input"] = r.input;
  j["path"] = r.path;
  j["variant"] = or_null(r.variant);
  j["fits"] = r.fits();
  j["profiles"] = Json::array();
  for (const ProfileUse& p : r.profiles) {
    j["profiles"].push_back(
        {{"name", p.name}, {"applies_to", or_null(p.applies_to)}, {"summary", p.summary}});
  }
  j["over"] = Json::array();
  j["items"] = Json::array();
  for (const Item& item : r.items) {
    Json i;
    i["scope"] = to_string(item.scope);
    i["name"] = item.name;
    i["material"] = or_null(item.material);
    i["program"] = or_null(item.program);
    i["profile"] = or_null(item.profile);
    i["resources"] = Json::array();
    for (const Resource& res : item.resources) {
      i["resources"].push_back(resource_json(res));
      if (res.over()) {
        j["over"].push_back({{"item", item.name},
                             {"key", res.key},
                             {"used", res.used},
                             {"limit", *res.limit},
                             {"profile", or_null(item.profile)},
                             {"line", r.file + ": " + overrun_line(item, res)}});
      }
    }
    i["note"] = or_null(item.note);
    j["items"].push_back(i);
  }
  j["check"] = r.check_name.empty() ? Json(nullptr)
                                    : Json{{"name", r.check_name}, {"source", r.check_source}};
  j["details"] = Json::object();
  for (const Detail& d : r.details) j["details"][d.key] = d.number ? Json(*d.number) : Json(d.text);
  j["notes"] = r.notes;
  return dump(j, indent);
}

std::string error_json(const std::string& file, const InputError& e, int indent) {
  Json j;
  j["schema"] = kSchema;
  j["file"] = file;
  j["fits"] = nullptr;
  j["error"] = {{"file", e.file()},
                {"where", or_null(e.where())},
                {"message", e.what_only()},
                {"line", one_line(e.what())}};
  return dump(j, indent);
}

}  // namespace lt::budget
