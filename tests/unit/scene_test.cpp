// Scenes: parsing, validation messages that name the field, and the JSON round trip.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "core/scene.hpp"

using csl::Scene;
using csl::SceneError;
using nlohmann::json;

namespace {
json minimal() {
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

TEST_CASE("a valid scene parses with its values") {
  Scene s = csl::scene_from_json(minimal());
  REQUIRE(s.disks.size() == 1);
  CHECK(s.disks[0].center.x() == 0.2);
  CHECK(s.disks[0].center.y() == 0.05);
  CHECK(s.disks[0].radius == 0.1);
  CHECK(s.goal.x() == 1.0);
  CHECK(s.goal.y() == 0.0);
}

TEST_CASE("scene JSON round-trips exactly") {
  Scene s = csl::scene_from_json(minimal());
  Scene t = csl::scene_from_json(csl::scene_to_json(s));
  CHECK(csl::scene_to_json(t) == csl::scene_to_json(s));
  CHECK(csl::scene_to_json(s)["obstacles"][0]["radius"] == 0.1);
}

TEST_CASE("invalid scenes are refused with the offending field named") {
  json j = minimal();
  j["obstacles"][0]["radius"] = -0.5;
  CHECK(error_of(j) == "obstacles[0].radius: must be >= 0");

  j = minimal();
  j["obstacles"][0]["center"] = json::array({0.1});
  CHECK(error_of(j) == "obstacles[0].center: must be an array of 2 numbers");

  j = minimal();
  j["version"] = 2;
  CHECK(error_of(j) == "version: must be 1");

  j = minimal();
  j.erase("version");
  CHECK(error_of(j) == "version: missing");

  j = minimal();
  j["start"] = json::array({"a", 0});
  CHECK(error_of(j) == "start[0]: must be a number");

  j = minimal();
  j["workspace"]["max"] = json::array({0, 1});
  CHECK(error_of(j) == "workspace: min must be below max in both coordinates");
}

TEST_CASE("malformed JSON text is a SceneError, not a crash") {
  CHECK_THROWS_AS(csl::scene_from_string("{\"version\": 1, "), SceneError);
  CHECK_THROWS_WITH(csl::scene_from_string("[1, 2"), "scene: not valid JSON");
}
