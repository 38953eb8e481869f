#include "load/gltf/gltf_notes.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/object_reader.h"

namespace lt::gltf {

namespace {
using json = nlohmann::json;

double checked(const json& v, double lo, double hi, const std::string& file,
               const std::string& where) {
  if (!v.is_number()) throw InputError(file, where, "expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d) || d < lo || d > hi) {
    throw InputError(file, where,
                     "out of range: " + v.dump() + " (allowed " + range_text(lo, hi) + ")");
  }
  return d;
}
}  // namespace

void note_unmapped_keys(const json& object, const std::string& pointer,
                        std::initializer_list<const char*> mapped, const std::string& why,
                        Notes& notes) {
  if (!object.is_object()) return;
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string& key = it.key();
    if (key == "name" || key == "extras") continue;
    if (std::any_of(mapped.begin(), mapped.end(), [&](const char* m) { return key == m; }))
      continue;
    if (key == "extensions" && it.value().is_object()) {
      for (auto e = it.value().begin(); e != it.value().end(); ++e) {
        if (std::any_of(mapped.begin(), mapped.end(), [&](const char* m) { return e.key() == m; }))
          continue;
        notes.push_back("ignored " + pointer + "/extensions/" + e.key() +
                        ": extension not implemented");
      }
      continue;
    }
    notes.push_back("ignored " + pointer + "/" + key + ": " + why);
  }
}

const json& at_pointer(const json& doc, const std::string& pointer) {
  static const json null_value;
  try {
    const json::json_pointer p(pointer);
    return doc.contains(p) ? doc.at(p) : null_value;
  } catch (const json::exception&) {
    return null_value;
  }
}

double bounded_number(const json& object, const char* key, double def, double lo, double hi,
                      const std::string& file, const std::string& pointer) {
  if (!object.is_object() || !object.contains(key)) return def;
  return checked(object[key], lo, hi, file, pointer + "/" + key);
}

std::vector<double> bounded_numbers(const json& object, const char* key, std::size_t n,
                                    std::vector<double> def, double lo, double hi,
                                    const std::string& file, const std::string& pointer) {
  if (!object.is_object() || !object.contains(key)) return def;
  const json& v = object[key];
  const std::string where = pointer + "/" + key;
  if (!v.is_array() || v.size() != n) {
    throw InputError(file, where, "expected an array of " + std::to_string(n) + " numbers");
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(checked(v[i], lo, hi, file, where + "/" + std::to_string(i)));
  return out;
}

}  // namespace lt::gltf
