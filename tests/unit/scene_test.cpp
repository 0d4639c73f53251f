// Scenes: parsing every robot and obstacle type, validation messages that name the field,
// limits, and the exact JSON round trip.
#include <doctest/doctest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/base/angles.hpp"
#include "core/scene/scene.hpp"

using csl::Scene;
using csl::SceneError;
using nlohmann::json;

namespace {
json p12() {
  return json::parse(R"({"version": 1,
    "workspace": {"min": [0, 0], "max": [1, 1]},
    "robot": {"type": "point"},
    "obstacles": [{"type": "disk", "center": [0.2, 0.05], "radius": 0.1}],
    "start": [0, 0], "goal": [1, 0]})");
}

std::string error_of(const json& j) {
  try {
    csl::scene_from_json(j);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("the homework's P12 scene parses with its values") {
  Scene s = csl::scene_from_json(p12());
  REQUIRE(s.obstacles.size() == 1);
  const auto& d = std::get<csl::Disk>(s.obstacles[0]);
  CHECK(d.center.x() == 0.2);
  CHECK(d.center.y() == 0.05);
  CHECK(d.radius == 0.1);
  CHECK(s.start == csl::config({0, 0}));
  CHECK(s.goal == csl::config({1, 0}));
  CHECK(std::holds_alternative<csl::PointRobot>(s.robot));
}

TEST_CASE("every obstacle and robot type round-trips exactly") {
  const json j = json::parse(R"({"version": 1, "name": "all kinds",
    "workspace": {"min": [-1, -1], "max": [2, 2]},
    "robot": {"type": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]]},
    "obstacles": [{"type": "disk", "center": [0.5, 0.5], "radius": 0.25},
                  {"type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0.5, 0.2], [0, 1]]},
                  {"type": "segment", "a": [0.5, -1], "b": [0.5, 0.3]}],
    "start": [0, 0, 0.5], "goal": [1.5, 1.5, -3]})");
  const Scene s = csl::scene_from_json(j);
  CHECK(s.name == "all kinds");
  CHECK(std::get<csl::PolygonRobot>(s.robot).radius == doctest::Approx(std::sqrt(0.0125)));
  CHECK(csl::scene_to_json(s) == j);
  const Scene t = csl::scene_from_json(csl::scene_to_json(s));
  CHECK(csl::scene_to_json(t) == csl::scene_to_json(s));

  const json arm = json::parse(R"({"version": 1, "robot": {"type": "arm2", "base": [0.5, 0.5], "lengths": [0.3, 0.2]},
    "start": [0.25, 7.0]})");
  const Scene a = csl::scene_from_json(arm);
  CHECK(a.start[1] == doctest::Approx(7.0 - csl::kTwoPi));  // angles are stored wrapped
  CHECK(a.goal == csl::config({csl::kPi / 2, 0.0}));        // the arm's default goal
  CHECK(csl::scene_to_json(csl::scene_from_json(csl::scene_to_json(a))) == csl::scene_to_json(a));
}

TEST_CASE("invalid scenes are refused with the offending field named") {
  json j = p12();
  j["obstacles"][0]["radius"] = -0.5;
  CHECK(error_of(j) == "obstacles[0].radius: must be >= 0");

  j = p12();
  j["obstacles"][0]["center"] = json::array({0.1});
  CHECK(error_of(j) == "obstacles[0].center: must be an array of 2 numbers");

  j = p12();
  j["obstacles"][0]["type"] = "blob";
  CHECK(error_of(j) == "obstacles[0].type: unknown obstacle type \"blob\" (disk, polygon or segment)");

  j = p12();
  j["obstacles"][0] = json::parse(R"({"type": "polygon", "vertices": [[0, 0], [1, 0]]})");
  CHECK(error_of(j) == "obstacles[0].vertices: a polygon needs at least 3 vertices");

  j = p12();
  j["obstacles"][0] = json::parse(R"({"type": "polygon", "vertices": [[0, 0], [1, 1], [1, 0], [0, 1]]})");
  CHECK(error_of(j) == "obstacles[0].vertices: the polygon's edges cross (it is self-intersecting)");

  j = p12();
  j["version"] = 2;
  CHECK(error_of(j) == "version: must be 1");

  j = p12();
  j.erase("version");
  CHECK(error_of(j) == "version: missing");

  j = p12();
  j["start"] = json::array({"a", 0});
  CHECK(error_of(j) == "start[0]: must be a number");

  j = p12();
  j["start"] = json::array({0, 0, 0});
  CHECK(error_of(j) == "start: must be an array of 2 numbers for robot type 'point'");

  j = p12();
  j["goal"] = json::array({2, 0});
  CHECK(error_of(j) == "goal: must lie inside the workspace");

  j = p12();
  j["workspace"]["max"] = json::array({0, 1});
  CHECK(error_of(j) == "workspace: min must be below max in both coordinates");

  j = p12();
  j["robot"] = json::parse(R"({"type": "arm2", "base": [0, 0], "lengths": [0.5, -1]})");
  CHECK(error_of(j) == "robot.lengths: link lengths must be > 0");

  j = p12();
  j["colour"] = "red";
  CHECK(error_of(j) == "colour: unknown field");

  j = p12();
  j["obstacles"][0]["center"][0] = 1e300;
  CHECK(error_of(j) == "obstacles[0].center[0]: must be within +-1e6");
}

TEST_CASE("scene limits are enforced") {
  json j = p12();
  j["obstacles"] = json::array();
  for (std::size_t i = 0; i <= csl::kMaxObstacles; ++i)
    j["obstacles"].push_back({{"type", "disk"}, {"center", {0.5, 0.5}}, {"radius", 0.01}});
  CHECK(error_of(j) == "obstacles: more than 1000 obstacles");
}

// Issue 27: {"workspace": {"min": [0, 0], "max": [1e-15, 1e-15]}} was valid, and the app's
// views crashed on it (and every later start, from the autosave). Sides below 0.001 and slivers
// more than 100 times longer than wide are refused, by the core: CLI, links, import and API alike.
TEST_CASE("the workspace has a least side and a greatest aspect ratio") {
  json j = p12();
  const auto with = [&](double w, double h) {
    j["workspace"] = {{"min", {0, 0}}, {"max", {w, h}}};
    j["start"] = {0, 0};
    j["goal"] = {w, h};
    return error_of(j);
  };
  CHECK(with(1e-15, 1e-15) == "workspace: each side must be at least 0.001 long (it is 1e-15 by 1e-15)");
  CHECK(with(5e-324, 1) == "workspace: each side must be at least 0.001 long (it is 4.94066e-324 by 1)");
  CHECK(with(0.001, 0.001) == "");
  CHECK(with(0.0009999, 0.05) == "workspace: each side must be at least 0.001 long (it is 0.0009999 by 0.05)");
  CHECK(with(100, 1) == "");
  CHECK(with(100.01, 1) == "workspace: one side may be at most 100 times the other (it is 100.01 by 1)");
  CHECK(with(1, 1e6) == "workspace: one side may be at most 100 times the other (it is 1 by 1e+06)");
  CHECK(with(2e6 - 1, 2e6 - 1) == "workspace.max[0]: must be within +-1e6");
}

TEST_CASE("scene text is JSON, all of it: a NUL byte and what follows are refused") {
  // nlohmann's parser stops at a NUL as at the end, so this passed as {"version": 1}.
  const std::string text = std::string("{\"version\": 1}") + '\0' + "garbage";
  CHECK_THROWS_WITH(csl::scene_from_string(text), "scene: not valid JSON (a NUL byte at byte 14)");
  CHECK_THROWS_WITH(csl::scene_from_string("{\"version\": 1} x"), "scene: not valid JSON");
  CHECK_NOTHROW(csl::scene_from_string("{\"version\": 1}\n"));
}

TEST_CASE("messages quote untrusted keys and values on one line, and never dump a deep value") {
  json j = p12();
  j["na\nme\x1b[31m"] = 1;
  CHECK(error_of(j) == "na\\nme\\x1b[31m: unknown field");
  j = p12();
  j["obstacles"][0]["type"] = json::parse(std::string(60, '[') + std::string(60, ']'));
  CHECK(error_of(j) == "obstacles[0].type: unknown obstacle type a JSON array (disk, polygon or segment)");
}

TEST_CASE("JSON text nested past 64 levels is refused while it is read") {
  // Copying a value nested 200000 deep recurses once a level (a crash), and the page's API
  // copies its arguments: the parser stops at the limit, before anything deep exists.
  const std::string deep = "{\"version\": 1, \"name\": " + std::string(200000, '[') + std::string(200000, ']') + "}";
  CHECK_THROWS_WITH(csl::scene_from_string(deep), "scene: nested more than 64 levels deep");
  CHECK_NOTHROW(csl::parse_json_text(std::string(64, '[') + std::string(64, ']')));
  CHECK_THROWS_WITH(csl::parse_json_text(std::string(65, '[') + std::string(65, ']')), "nested more than 64 levels deep");
}

TEST_CASE("malformed JSON text is a SceneError, not a crash") {
  CHECK_THROWS_AS(csl::scene_from_string("{\"version\": 1, "), SceneError);
  CHECK_THROWS_WITH(csl::scene_from_string("[1, 2"), "scene: not valid JSON");
  CHECK_THROWS_WITH(csl::scene_from_string("[1, 2]"), "scene: must be a JSON object");
  CHECK_THROWS_WITH(csl::scene_from_string("{\"version\": 1, \"start\": [NaN, 0]}"), "scene: not valid JSON");
}

TEST_CASE("obstacle_problem checks one obstacle for editors") {
  CHECK(csl::obstacle_problem(csl::Disk{{0, 0}, 0.1}, "new") == "");
  CHECK(csl::obstacle_problem(csl::Disk{{0, 0}, -1}, "new") == "new.radius: must be >= 0");
  CHECK(csl::obstacle_problem(csl::PolygonObstacle{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}, "new") ==
        "new.vertices: the polygon's edges cross (it is self-intersecting)");
}

TEST_CASE("same_scene: every field counts") {
  csl::Scene a = csl::scene_from_string(
      R"({"version": 1, "obstacles": [{"type": "disk", "center": [0.5, 0.5], "radius": 0.1}]})");
  csl::Scene b = a;
  CHECK(csl::same_scene(a, b));
  std::get<csl::Disk>(b.obstacles[0]).center.x() = std::nextafter(0.5, 1.0);
  CHECK_FALSE(csl::same_scene(a, b));
  b = a;
  b.goal[1] = 0.9;
  CHECK_FALSE(csl::same_scene(a, b));
  b = a;
  b.name = "renamed";
  CHECK_FALSE(csl::same_scene(a, b));
}

TEST_CASE("same_content: every field but the name") {
  csl::Scene a = csl::scene_from_string(
      R"({"version": 1, "name": "P12", "obstacles": [{"type": "disk", "center": [0.5, 0.5], "radius": 0.1}]})");
  csl::Scene b = a;
  b.name = "P12 (edited)";
  CHECK(csl::same_content(a, b));
  b.name.clear();
  CHECK(csl::same_content(a, b));
  std::get<csl::Disk>(b.obstacles[0]).radius = std::nextafter(0.1, 1.0);
  CHECK_FALSE(csl::same_content(a, b));
  b = a;
  b.start[0] = 0.25;
  CHECK_FALSE(csl::same_content(a, b));
}

TEST_CASE("an arm of N links: 'arm' with 1 to 6 lengths, 'arm2' with two, each written back as read") {
  const json three = json::parse(R"({"version": 1, "robot": {"type": "arm", "base": [0.5, 0.5], "lengths": [0.3, 0.2, 0.1]},
                                     "start": [0.1, 0.2, 7.0], "goal": [1, 2, 3]})");
  const Scene s = csl::scene_from_json(three);
  const auto& arm = std::get<csl::ArmRobot>(s.robot);
  CHECK(arm.lengths == std::vector<double>{0.3, 0.2, 0.1});
  CHECK(s.start.size() == 3);
  CHECK(s.start[2] == doctest::Approx(7.0 - csl::kTwoPi));  // angles wrap, all of them
  const json back = csl::scene_to_json(s);
  CHECK(back["robot"] == three["robot"]);
  CHECK(csl::scene_from_json(back).start == s.start);
  // The defaults for an arm: every joint at 0, the goal with the first turned a quarter.
  const Scene d = csl::scene_from_json(json::parse(R"({"version": 1, "robot": {"type": "arm", "base": [0, 0], "lengths": [1, 1, 1, 1]}})"));
  CHECK(d.start == csl::config({0, 0, 0, 0}));
  CHECK(d.goal == csl::config({csl::kPi / 2, 0, 0, 0}));
  // A 2-link "arm" is the arm2.
  const json two = json::parse(R"({"version": 1, "robot": {"type": "arm", "base": [0, 0], "lengths": [0.3, 0.2]}})");
  CHECK(csl::scene_to_json(csl::scene_from_json(two))["robot"]["type"] == "arm2");
  // Refused, naming the field: no links, too many, an arm2 of three, a configuration of the wrong size.
  json j = three;
  j["robot"]["lengths"] = json::array();
  CHECK(error_of(j) == "robot.lengths: must be an array of 1 to 6 numbers");
  j["robot"]["lengths"] = json::array({0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1});
  CHECK(error_of(j) == "robot.lengths: must be an array of 1 to 6 numbers");
  j = three;
  j["robot"]["type"] = "arm2";
  CHECK(error_of(j) == "robot.lengths: must be an array of 2 numbers");
  j = three;
  j["start"] = json::array({0.1, 0.2});
  CHECK(error_of(j).rfind("start: must be an array of 3 numbers for robot type 'arm'", 0) == 0);
  j = three;
  j["robot"]["lengths"][1] = 0;
  CHECK(error_of(j) == "robot.lengths: link lengths must be > 0");
}
