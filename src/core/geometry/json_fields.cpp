#include "core/geometry/json_fields.hpp"

#include <cmath>
#include <cstdio>

#include "core/base/text.hpp"

namespace csl {
namespace {

using json = nlohmann::json;

std::string join(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }

}  // namespace

namespace json_fields {

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw SceneError(path + ": " + what);
}

std::string value_text(const json& v) {
  if (v.is_string()) return '"' + printable(v.get_ref<const std::string&>(), 40) + '"';
  if (v.is_number()) return shortest(v.get<double>());
  return std::string("a JSON ") + v.type_name();
}

const json& field(const json& obj, const char* key, const std::string& path) {
  auto it = obj.find(key);
  if (it == obj.end()) fail(join(path, key), "missing");
  return *it;
}

void expect_object(const json& j, const std::string& path, std::initializer_list<const char*> keys) {
  if (!j.is_object()) fail(path.empty() ? "scene" : path, "must be a JSON object");
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) fail(join(path, printable(it.key(), 40).c_str()), "unknown field");
  }
}

double number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, "must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "must be finite");
  if (std::fabs(v) > kMaxCoordinate) fail(path, "must be within +-1e6");
  return v;
}

Vec2 point(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 2) fail(path, "must be an array of 2 numbers");
  return {number(j[0], path + "[0]"), number(j[1], path + "[1]")};
}

Polygon polygon(const json& j, const std::string& path, std::size_t max_vertices) {
  if (!j.is_array()) fail(path, "must be an array of [x, y] points");
  if (j.size() > max_vertices) fail(path, "has more than " + std::to_string(max_vertices) + " vertices");
  Polygon p;
  for (std::size_t i = 0; i < j.size(); ++i) p.push_back(point(j[i], path + "[" + std::to_string(i) + "]"));
  if (const char* problem = polygon_problem(p); *problem) fail(path, problem);
  return p;
}

json point_json(const Vec2& p) { return json::array({p.x(), p.y()}); }

json polygon_json(const Polygon& poly) {
  json out = json::array();
  for (const Vec2& v : poly) out.push_back(point_json(v));
  return out;
}

}  // namespace json_fields
}  // namespace csl
