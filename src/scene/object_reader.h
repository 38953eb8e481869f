// Strict reading of one JSON object of a scene file: every key is either taken or reported as
// unknown, so a typo never silently renders something else (scene-format.md). Every failure is
// an InputError naming the file and the key's path ("materials.marble.translucency.power").
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>

namespace lt {

class ObjectReader {
 public:
  using json = nlohmann::json;

  // `path` is the object's key path ("" for the top level); `file` must outlive the reader.
  ObjectReader(const json& j, std::string path, const std::string& file);

  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  const std::string& file() const { return file_; }
  std::string key_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }
  bool has(const std::string& key) const { return j_.contains(key); }
  const json& get(const std::string& key);

  // A value of the key, `def` when it is absent (no default: a missing required key), refused
  // outside [lo, hi] or not finite.
  double number(const std::string& key, std::optional<double> def = {}, double lo = -INFINITY,
                double hi = INFINITY);
  int integer(const std::string& key, int def, int lo, int hi);
  glm::dvec3 vec3(const std::string& key, std::optional<glm::dvec3> def = {}, double lo = -INFINITY,
                  double hi = INFINITY);
  glm::dvec3 vec3_value(const json& v, const std::string& kp, double lo, double hi) const;
  std::string string(const std::string& key, std::optional<std::string> def = {});
  bool boolean(const std::string& key, bool def);
  ObjectReader object(const std::string& key);

  // Call after reading: any key not taken is a typo or an unsupported feature.
  void finish() const;

 private:
  // True when the object lacks `key`, which is then taken (its default stands in); no default:
  // a missing required key.
  bool absent(const std::string& key, bool has_default);

  const json& j_;
  std::string path_;
  const std::string& file_;
  std::set<std::string> used_;
};

// `text` as JSON, or an InputError naming `file`, the line of a syntax error and nlohmann's
// reason without its "[json.exception...]" prefix. For every JSON input: scenes and glTF alike.
nlohmann::json parse_json_input(const std::string& text, const std::string& file);

// "[lo, hi]" as the range errors write it ("inf" for an infinite bound).
std::string range_text(double lo, double hi);

// JSON may hold "\u0000", the file system cannot: every system call would stop at the NUL (and
// read another file), and so would the printed message. Refuses `file_name` at `key` if it has one.
void refuse_nul(const ObjectReader& r, const std::string& key, const std::string& file_name);

}  // namespace lt
