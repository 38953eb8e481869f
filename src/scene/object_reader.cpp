#include "scene/object_reader.h"

#include "core/error.h"

namespace lt {

namespace {

// JSON syntax errors carry a byte offset; users want a line.
int line_of_offset(const std::string& text, size_t offset) {
  int line = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

}  // namespace

nlohmann::json parse_json_input(const std::string& text, const std::string& file) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string msg = e.what();
    // nlohmann's message is "[json.exception.parse_error.101] parse error at line L, column C: ..."
    const auto pos = msg.find("parse error");
    throw InputError(file, std::to_string(line_of_offset(text, e.byte)),
                     "invalid JSON: " + (pos == std::string::npos ? msg : msg.substr(pos)));
  } catch (const nlohmann::json::exception& e) {
    // e.g. "[json.exception.out_of_range.406] number overflow parsing '1e400'": no position.
    std::string msg = e.what();
    const auto pos = msg.find("] ");
    throw InputError(file, "",
                     "invalid JSON: " + (pos == std::string::npos ? msg : msg.substr(pos + 2)));
  }
}

ObjectReader::ObjectReader(const json& j, std::string path, const std::string& file)
    : j_(j), path_(std::move(path)), file_(file) {
  if (!j_.is_object()) fail(path_, "expected an object");
}

void ObjectReader::fail(const std::string& key, const std::string& what) const {
  throw InputError(file_, key.empty() ? "(top level)" : key, what);
}

const ObjectReader::json& ObjectReader::get(const std::string& key) {
  used_.insert(key);
  if (!j_.contains(key)) fail(key_path(key), "missing required key");
  return j_.at(key);
}

bool ObjectReader::absent(const std::string& key, bool has_default) {
  if (has(key)) return false;
  if (!has_default) fail(key_path(key), "missing required key");
  used_.insert(key);
  return true;
}

double ObjectReader::number(const std::string& key, std::optional<double> def, double lo,
                            double hi) {
  if (absent(key, def.has_value())) return *def;
  const json& v = get(key);
  if (!v.is_number()) fail(key_path(key), "expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(key_path(key), "must be finite");
  if (d < lo || d > hi) {
    fail(key_path(key), "out of range: " + v.dump() + " (allowed " + range_text(lo, hi) + ")");
  }
  return d;
}

int ObjectReader::integer(const std::string& key, int def, int lo, int hi) {
  if (absent(key, true)) return def;
  const json& v = get(key);
  if (!v.is_number_integer()) fail(key_path(key), "expected an integer");
  const auto i = v.get<long long>();
  if (i < lo || i > hi) {
    fail(key_path(key), "out of range: " + v.dump() + " (allowed " + range_text(lo, hi) + ")");
  }
  return static_cast<int>(i);
}

glm::dvec3 ObjectReader::vec3(const std::string& key, std::optional<glm::dvec3> def, double lo,
                              double hi) {
  if (absent(key, def.has_value())) return *def;
  return vec3_value(get(key), key_path(key), lo, hi);
}

glm::dvec3 ObjectReader::vec3_value(const json& v, const std::string& kp, double lo,
                                    double hi) const {
  if (!v.is_array() || v.size() != 3) fail(kp, "expected an array of 3 numbers");
  glm::dvec3 r;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number()) fail(kp, "expected an array of 3 numbers");
    r[i] = v[i].get<double>();
    if (!std::isfinite(r[i])) fail(kp, "must be finite");
    if (r[i] < lo || r[i] > hi) {
      fail(kp, "component out of range: " + v[i].dump() + " (allowed " + range_text(lo, hi) + ")");
    }
  }
  return r;
}

std::string ObjectReader::string(const std::string& key, std::optional<std::string> def) {
  if (absent(key, def.has_value())) return *def;
  const json& v = get(key);
  if (!v.is_string()) fail(key_path(key), "expected a string");
  return v.get<std::string>();
}

bool ObjectReader::boolean(const std::string& key, bool def) {
  if (absent(key, true)) return def;
  const json& v = get(key);
  if (!v.is_boolean()) fail(key_path(key), "expected true or false");
  return v.get<bool>();
}

ObjectReader ObjectReader::object(const std::string& key) {
  return ObjectReader(get(key), key_path(key), file_);
}

void ObjectReader::finish() const {
  for (auto it = j_.begin(); it != j_.end(); ++it) {
    if (!used_.count(it.key())) fail(key_path(it.key()), "unknown key");
  }
}

std::string range_text(double lo, double hi) {
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on chained operator+ here.
  auto s = [](double v) {
    if (v == INFINITY) return std::string("inf");
    if (v == -INFINITY) return std::string("-inf");
    return nlohmann::json(v).dump();
  };
  std::string r = "[";
  r.append(s(lo)).append(", ").append(s(hi)).append("]");
  return r;
}

void refuse_nul(const ObjectReader& r, const std::string& key, const std::string& file_name) {
  if (file_name.find('\0') == std::string::npos) return;
  std::string shown;
  for (char c : file_name) shown += c == '\0' ? std::string("\\u0000") : std::string(1, c);
  r.fail(r.key_path(key), "a path cannot contain a NUL byte: \"" + shown + "\"");
}

}  // namespace lt
