// The questions of "C-spaces in 3-D" (volume_questions): each verdict against facts written again
// here from the handout (SE(2) = R^2 x S^1 has one angle, T^3 three; the short way between two
// angles crosses +-pi when the plain difference is more than pi), right and wrong answers, and
// unreadable ones that are not attempts.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/teaching/volume_questions.hpp"

namespace {

csl::Scene polygon_scene() {
  csl::Scene s;
  s.robot = csl::make_polygon_robot({{-0.1, -0.05}, {0.1, -0.05}, {0.1, 0.05}, {-0.1, 0.05}});
  s.start = csl::config({0.2, 0.3, 0.0});
  s.goal = csl::config({0.8, 0.7, 1.0});
  return s;
}

csl::Scene arm_scene() {
  csl::Scene s;
  s.robot = csl::ArmRobot({0.5, 0.5}, {0.2, 0.15, 0.1});
  s.start = csl::config({0.1, -0.4, 0.7});
  s.goal = csl::config({1.0, 0.5, -0.2});
  return s;
}

bool right(const csl::Scene& s, const char* id, const std::string& answer, double free = 0.5) {
  return csl::check_volume_question(id, s, free, answer).correct;
}

}  // namespace

TEST_CASE("volume questions: the space's name and dimension") {
  const csl::Scene p = polygon_scene(), a = arm_scene();
  CHECK(right(p, "name", "SE(2)"));
  CHECK(right(p, "name", "R^2 x S^1"));
  CHECK_FALSE(right(p, "name", "R^3"));
  CHECK_FALSE(right(p, "name", "T^3"));
  CHECK(right(a, "name", "T^3"));
  CHECK(right(a, "name", "S^1 x S^1 x S^1"));
  CHECK_FALSE(right(a, "name", "R^3"));
  // A wrong name is an attempt; text that names no space is not.
  CHECK(csl::check_volume_question("name", a, 0.5, "R^3").readable);
  const csl::ExerciseCheck garbled = csl::check_volume_question("name", a, 0.5, "((");
  CHECK_FALSE(garbled.correct);
  CHECK_FALSE(garbled.readable);
  CHECK(garbled.explanation.find("could not read") == std::string::npos);  // the lesson says "not an answer: "
  CHECK(!garbled.explanation.empty());
  CHECK(right(p, "dimension", "3"));
  CHECK(right(a, "dimension", " 3 "));
  CHECK_FALSE(right(a, "dimension", "2"));
  const csl::ExerciseCheck bad = csl::check_volume_question("dimension", a, 0.5, "three");
  CHECK_FALSE(bad.correct);
  CHECK_FALSE(bad.readable);
}

TEST_CASE("volume questions: glued faces, one pair per angle") {
  const csl::Scene p = polygon_scene(), a = arm_scene();
  CHECK(right(p, "glued", "top-bottom"));
  CHECK_FALSE(right(p, "glued", "all"));
  CHECK(right(a, "glued", "all"));
  CHECK_FALSE(right(a, "glued", "top-bottom"));
  CHECK_FALSE(right(a, "glued", "none"));
  CHECK_FALSE(csl::check_volume_question("glued", a, 0.5, "every face").readable);
  // Every choice the question offers is a key the checker reads.
  for (const auto& c : csl::volume_question("glued", a).choices)
    CHECK(csl::check_volume_question("glued", a, 0.5, c.first).readable);
}

TEST_CASE("volume questions: which pair crosses a seam, from the angles themselves") {
  for (const csl::Scene& s : {polygon_scene(), arm_scene()}) {
    const std::vector<csl::Config> c = csl::seam_question_configs(s);
    REQUIRE(c.size() == 3);
    const int axis = std::holds_alternative<csl::ArmRobot>(s.robot) ? 0 : 2;
    // The short way crosses +-pi exactly when the plain difference is longer than pi.
    const bool b = std::fabs(c[1][axis] - c[0][axis]) > csl::kPi;
    const bool cc = std::fabs(c[2][axis] - c[0][axis]) > csl::kPi;
    const std::string want = b && cc ? "both" : b ? "B" : cc ? "C" : "neither";
    CHECK(want == "B");  // the question is built so that one of the two crosses
    CHECK(right(s, "seam", want));
    for (const char* other : {"B", "C", "both", "neither"})
      if (want != other) CHECK_FALSE(right(s, "seam", other));
    // The other coordinates are the start's.
    for (int i = 0; i < 3; ++i)
      if (i != axis) CHECK(c[1][i] == s.start[i]);
  }
}

TEST_CASE("volume questions: the free percentage within half a point") {
  const csl::Scene p = polygon_scene();
  CHECK(right(p, "free", "63.2", 0.6321));
  CHECK(right(p, "free", "63.6 %", 0.6321));
  CHECK_FALSE(right(p, "free", "62.7", 0.6321));
  const csl::ExerciseCheck fraction = csl::check_volume_question("free", p, 0.6321, "0.632");
  CHECK_FALSE(fraction.correct);
  CHECK(fraction.readable);
  CHECK(fraction.explanation.find("fraction") != std::string::npos);
  CHECK_FALSE(csl::check_volume_question("free", p, 0.6321, "").readable);
  CHECK_THROWS_AS(csl::check_volume_question("colour", p, 0.5, "red"), std::invalid_argument);
  csl::Scene point = p;
  point.robot = csl::PointRobot{};
  CHECK_THROWS_AS(csl::volume_question("name", point), std::invalid_argument);
}
