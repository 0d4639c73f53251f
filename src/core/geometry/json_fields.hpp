#pragma once
// Reading and writing the scene format's pieces (numbers, points, polygons, objects with known
// fields), with errors that name the offending field ("robot.lengths[1]: must be > 0"). Here,
// below the robots and the scene, so that each robot type reads and writes its own JSON
// (core/robots/*_robot.cpp) with the scene's rules and messages.
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <stdexcept>
#include <string>

#include "core/geometry/geometry.hpp"

namespace csl {

/// |any coordinate or length| in a scene.
inline constexpr double kMaxCoordinate = 1e6;

/// Thrown for invalid scene JSON; what() names the offending field, e.g. "obstacles[2].radius: ...".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace json_fields {

/// Throws SceneError("path: what").
[[noreturn]] void fail(const std::string& path, const std::string& what);
/// A number in few digits for a message ("1e-15", "0.25").
std::string shortest(double v);
/// A field's value in a message: a string quoted (escaped, cut), anything else by its kind.
/// Never dump(): it recurses, and a value nested 100000 deep overflows the stack.
std::string value_text(const nlohmann::json& v);
/// The member `key` of `obj` (SceneError "path.key: missing" if absent).
const nlohmann::json& field(const nlohmann::json& obj, const char* key, const std::string& path);
/// `j` is an object with no member but `keys`.
void expect_object(const nlohmann::json& j, const std::string& path, std::initializer_list<const char*> keys);
/// A finite number within +-kMaxCoordinate.
double number(const nlohmann::json& j, const std::string& path);
/// [x, y].
Vec2 point(const nlohmann::json& j, const std::string& path);
/// [[x, y], ...]: a simple polygon of at most `max_vertices` (polygon_problem() says why not).
Polygon polygon(const nlohmann::json& j, const std::string& path, std::size_t max_vertices);

nlohmann::json point_json(const Vec2& p);
nlohmann::json polygon_json(const Polygon& poly);

}  // namespace json_fields
}  // namespace csl
