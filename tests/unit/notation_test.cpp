// C-space notation: the homework's robots (P1-P7 kinds), the description format and its
// errors, and the answer checker on right answers in many spellings and on typical mistakes.
#include "core/teaching/notation.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

using csl::check_answer;
using csl::configuration_space;
using csl::NotationError;
using csl::parse_robot_description;
using csl::parse_space_expression;
using csl::SpaceSignature;
using Base = csl::RobotDescription::Base;

namespace {

csl::ConfigSpaceInfo q_of(const std::string& description) {
  return configuration_space(parse_robot_description(description));
}

std::vector<std::string> factor_names(const csl::ConfigSpaceInfo& info) {
  std::vector<std::string> out;
  for (const auto& f : info.factors) out.push_back(f.notation);
  return out;
}

std::string description_error(const std::string& text) {
  try {
    parse_robot_description(text);
  } catch (const NotationError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("the description format: defaults, keys in any order, spaces or commas") {
  const csl::RobotDescription none = parse_robot_description("");
  CHECK(none.base == Base::Fixed);
  CHECK(none.joints.empty());
  CHECK_FALSE(none.spherical_wrist);

  const csl::RobotDescription r =
      parse_robot_description("  wrist=spherical,joints=RRP ,  base = planar ");
  CHECK(r.base == Base::PlanarMobile);
  CHECK(r.joints == "RRP");
  CHECK(r.spherical_wrist);

  CHECK(parse_robot_description("base=fixed").base == Base::Fixed);
  CHECK(parse_robot_description("base=planar-translating").base == Base::PlanarTranslating);
  CHECK(parse_robot_description("base=spatial-translating").base == Base::SpatialTranslating);
  CHECK(parse_robot_description("base=spatial").base == Base::SpatialMobile);
  CHECK_FALSE(parse_robot_description("wrist=none").spherical_wrist);
}

TEST_CASE("bad descriptions are NotationErrors that name the problem") {
  CHECK(description_error("base=planer") ==
        "base: unknown value 'planer' (fixed, planar-translating, planar, spatial-translating "
        "or spatial)");
  CHECK(description_error("joints=RRX") ==
        "joints: 'X' in 'RRX' is not a joint letter (R revolute, P prismatic)");
  CHECK(contains(description_error("joints=rr"), "'r' in 'rr' is not a joint letter"));
  CHECK(description_error("joint=RR") == "unknown key 'joint' (keys: base, joints, wrist)");
  CHECK(description_error("wrist=yes") == "wrist: unknown value 'yes' (spherical or none)");
  CHECK(description_error("RRR") == "'RRR' is not key=value (keys: base, joints, wrist)");
  CHECK(description_error("joints=R joints=P") == "joints given twice");
  CHECK(description_error("base=") == "base: missing value");
  CHECK(description_error("joints=R,R") == "'R' is not key=value (keys: base, joints, wrist)");
  // A robot built in code is held to the same letters.
  csl::RobotDescription bad;
  bad.joints = "RQ";
  CHECK_THROWS_AS(configuration_space(bad), NotationError);
}

TEST_CASE("P1: a mobile robot that translates and rotates in the plane is SE(2)") {
  const auto q = q_of("base=planar");
  CHECK(q.notation == "SE(2)");
  CHECK(q.dimension == 3);
  REQUIRE(q.factors.size() == 1);
  CHECK(q.factors[0].dimension == 3);
  CHECK(contains(q.factors[0].reason, "turns"));
  CHECK(q.equivalent.front() == "R^2 x S^1");
}

TEST_CASE("arms with n revolute joints are T^n, and one joint is S^1") {
  CHECK(q_of("joints=R").notation == "S^1");
  CHECK(q_of("joints=R").dimension == 1);
  CHECK(q_of("joints=RR").notation == "T^2");
  CHECK(q_of("joints=RRR").notation == "T^3");
  CHECK(q_of("joints=RRR").dimension == 3);
  CHECK(q_of("joints=RRRRRRR").notation == "T^7");
  const auto e = q_of("joints=RR").equivalent;
  CHECK(std::find(e.begin(), e.end(), "S^1 x S^1") != e.end());
  CHECK(std::find(e.begin(), e.end(), "(SO(2))^2") != e.end());
}

TEST_CASE("prismatic joints are R; revolute joints come first whatever the joint order") {
  CHECK(q_of("joints=P").notation == "R");
  CHECK(q_of("joints=PP").notation == "R^2");
  const auto rrp = q_of("joints=RRP");
  CHECK(rrp.notation == "T^2 x R");
  CHECK(rrp.dimension == 3);
  CHECK(factor_names(rrp) == std::vector<std::string>{"T^2", "R"});
  CHECK(q_of("joints=PRP").notation == "S^1 x R^2");
  CHECK(q_of("joints=RPR").notation == "T^2 x R");
}

TEST_CASE("P6: a six-link arm whose last three links form a spherical wrist is T^6") {
  const auto q = q_of("joints=RRR wrist=spherical");
  CHECK(q.notation == "T^6");
  CHECK(q.dimension == 6);
  REQUIRE(q.factors.size() == 1);
  CHECK(contains(q.factors[0].reason, "spherical wrist"));
  // Writing all six joints out is the same robot.
  CHECK(q_of("joints=RRRRRR").notation == "T^6");
  CHECK(q_of("wrist=spherical").notation == "T^3");
}

TEST_CASE("P7: the same arm on a base that translates and rotates in the plane is SE(2) x T^6") {
  const auto q = q_of("base=planar joints=RRR wrist=spherical");
  CHECK(q.notation == "SE(2) x T^6");
  CHECK(q.dimension == 9);
  CHECK(factor_names(q) == std::vector<std::string>{"SE(2)", "T^6"});
  CHECK(q.factors[0].dimension + q.factors[1].dimension == 9);
  CHECK(q.equivalent == std::vector<std::string>{"R^2 x S^1 x T^6", "R^2 x T^7", "SE(2) x (S^1)^6",
                                                 "SE(2) x (SO(2))^6"});
}

TEST_CASE("the other bases: R^2, R^3, SE(3); base factor always first") {
  CHECK(q_of("base=planar-translating").notation == "R^2");
  CHECK(q_of("base=spatial-translating joints=P").notation == "R^3 x R");
  const auto spatial = q_of("base=spatial joints=RRP");
  CHECK(spatial.notation == "SE(3) x T^2 x R");
  CHECK(spatial.dimension == 9);
  CHECK(spatial.equivalent.front() == "R^3 x SO(3) x T^2 x R");
  CHECK(q_of("base=planar joints=R").notation == "SE(2) x S^1");
}

TEST_CASE("a fixed robot without joints is a single point") {
  const auto q = q_of("base=fixed");
  CHECK(q.notation == "a single point");
  CHECK(q.dimension == 0);
  REQUIRE(q.factors.size() == 1);
  CHECK_FALSE(q.factors[0].reason.empty());
}

TEST_CASE("every listed spelling, and the canonical one, checks as correct") {
  for (const char* d : {"base=planar", "joints=R", "joints=RRP", "joints=PP", "base=fixed",
                        "joints=RRR wrist=spherical", "base=planar joints=RRR wrist=spherical",
                        "base=spatial joints=RPR", "base=planar-translating joints=P"}) {
    CAPTURE(d);
    const auto robot = parse_robot_description(d);
    const auto q = configuration_space(robot);
    CHECK(parse_space_expression(q.notation).dimension() == q.dimension);
    CHECK(check_answer(q.notation, robot).correct);
    CHECK_FALSE(q.equivalent.empty());
    for (const std::string& e : q.equivalent) {
      CAPTURE(e);
      CHECK(check_answer(e, robot).correct);
    }
  }
}

TEST_CASE("the expression reader: signs, superscripts, powers, spacing, Q =") {
  const SpaceSignature p7{2, 7, 0, 0};
  for (const char* s :
       {"SE(2) x T^6", "Q = SE(2) x T^6", "R^2 x S^1 x T^6", "R^2 x T^7", "SE(2)xT^6",
        "se(2) * t^6", "R² × S¹ × T⁶", "ℝ^2 x T^7", "R x R x (S^1)^7", "SE ( 2 ) x T ^ 6",
        "R^{2} \\times T^{7}", "(SO(2))^6 x SE(2)", "SO(2)^7 x R^2", "(R x S^1)^2 x T^5"}) {
    CAPTURE(s);
    CHECK(parse_space_expression(s) == p7);
  }
  CHECK(parse_space_expression("SE(3)") == SpaceSignature{3, 0, 0, 1});
  CHECK(parse_space_expression("R^3 x SO(3)") == SpaceSignature{3, 0, 0, 1});
  CHECK(parse_space_expression("S^2 x S^2") == SpaceSignature{0, 0, 2, 0});
  CHECK(parse_space_expression("T¹²") == SpaceSignature{0, 12, 0, 0});
  CHECK(parse_space_expression("a point") == SpaceSignature{});
  CHECK(parse_space_expression("R^0") == SpaceSignature{});
  CHECK(parse_space_expression("SE(2) x T^6").dimension() == 9);
  CHECK(parse_space_expression("SE(3) x S^2").dimension() == 8);
}

TEST_CASE("the expression reader says what it could not read") {
  const auto error = [](const std::string& s) {
    try {
      parse_space_expression(s);
    } catch (const NotationError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(error("") == "the answer is empty");
  CHECK(error("Q = ") == "the answer is empty");
  CHECK(error("Z^2") == "expected a factor such as R^2, S^1, T^3, SO(3) or SE(2) (at 'Z^2')");
  CHECK(error("R^2 S^1") == "expected a product sign x, × or * (at 'S^1')");
  CHECK(error("SE(2) x") == "expected a factor such as R^2, S^1, T^3, SO(3) or SE(2) (at the end)");
  CHECK(error("S^3") == "only S^1 (the circle) and S^2 (the sphere) are known (at 'S^3')");
  CHECK(error("SO(4)") == "only SO(2), SO(3), SE(2) and SE(3) are known (at 'SO(4)')");
  CHECK(error("T x T") == "T needs an exponent, as in T^3 (at 'x T')");
  CHECK(error("(S^1 x S^1") == "expected ')' (at the end)");
  CHECK(error("S^1)") == "')' without a matching '(' (at ')')");
  CHECK(error("S^1^3") == "a power of S^n or T^n needs parentheses, as in (S^1)^3 (at '^3')");
  CHECK(error("R^x") == "expected a whole number (at 'x')");
  CHECK(error("((T^1000)^1000)^1000") == "space too large (at the end)");
  // Issue 27: 65000 '(' (10000 on the browser's stack) overflowed the stack, one call each.
  CHECK(error(std::string(33, '(') + "R" + std::string(33, ')')) == "too many nested parentheses (at most 32) (at '(R))))))))))))))...')");
  CHECK(error(std::string(32, '(') + "R" + std::string(32, ')')) == "");
  CHECK(error(std::string(1001, '(')) == "the answer is longer than 1000 characters");
  CHECK(error(std::string(999, '(')) == "too many nested parentheses (at most 32) (at '((((((((((((((((...')");
  // Control characters are escaped where a message quotes the answer.
  CHECK(error("R^2 \x1b[2J") == "expected a product sign x, × or * (at '\\x1b[2J')");
}

TEST_CASE("right answers are confirmed with an equality") {
  const auto p7 = parse_robot_description("base=planar joints=RRR wrist=spherical");
  auto c = check_answer("Q = SE(2) x T^6", p7);
  CHECK(c.correct);
  CHECK(c.explanation == "correct: SE(2) x T^6 = R^2 x S^1 x T^6 (dimension 9)");
  c = check_answer("T^6 x R^2 x S^1", p7);  // order does not matter in a product
  CHECK(c.correct);
  CHECK(c.explanation == "correct: SE(2) x T^6 = T^6 x R^2 x S^1 (dimension 9)");
  CHECK(check_answer("R² × T⁷", p7).correct);

  const auto p6 = parse_robot_description("joints=RRR wrist=spherical");
  CHECK(check_answer("T^6", p6).correct);
  CHECK(check_answer("(S^1)^6", p6).correct);
  CHECK(check_answer("SO(2) x SO(2) x SO(2) x SO(2) x SO(2) x SO(2)", p6).correct);
  CHECK(check_answer("T^3 x T^3", p6).correct);

  const auto p1 = parse_robot_description("base=planar");
  CHECK(check_answer("R^2 x SO(2)", p1).correct);
  CHECK(check_answer("point", parse_robot_description("")).correct);
}

TEST_CASE("wrong answers: the sphere for the torus, SO(3) for T^3, R for S^1") {
  const auto rr = parse_robot_description("joints=RR");
  auto c = check_answer("S^2", rr);
  CHECK_FALSE(c.correct);
  CHECK(contains(c.explanation, "S^2 is the sphere: S^1 x S^1 is the torus T^2"));
  CHECK_FALSE(contains(c.explanation, "dimension"));  // same dimension: that is the trap

  const auto p6 = parse_robot_description("joints=RRR wrist=spherical");
  c = check_answer("T^3 x SO(3)", p6);
  CHECK_FALSE(c.correct);
  CHECK(contains(c.explanation, "SO(3) is not T^3"));
  CHECK_FALSE(contains(c.explanation, "missing"));
  // After a known confusion, the counts say how the answer was read.
  c = check_answer("SO(3)", p6);
  CHECK(contains(c.explanation, "SO(3) is not T^3"));
  CHECK(contains(c.explanation,
                 "; reading SO(3) as T^3: 3 revolute joints are missing: expected 6 "
                 "circle factors, got 3; dimension: expected 6, got 3"));

  const auto rrp = parse_robot_description("joints=RRP");
  c = check_answer("T^3", rrp);
  CHECK_FALSE(c.correct);
  CHECK(c.explanation == "a prismatic joint slides along a line: R, not S^1");
  c = check_answer("S^1 x R^2", rrp);
  CHECK_FALSE(c.correct);
  CHECK(c.explanation ==
        "a revolute joint turns: its angle goes around the circle S^1, not along the line R");
  c = check_answer("R^3", parse_robot_description("base=planar"));
  CHECK(contains(c.explanation, "the base's turning is an angle"));
  // With the wrong number of degrees of freedom an extra R is not read as a swapped S^1.
  c = check_answer("R^3 x S^1", parse_robot_description("joints=RR"));
  CHECK_FALSE(contains(c.explanation, "not along the line R"));
  CHECK(contains(c.explanation, "3 R dimensions too many"));

  // A spatial base turns in SO(3): neither the sphere nor three angles.
  const auto spatial = parse_robot_description("base=spatial");
  CHECK(contains(check_answer("R^3 x S^2", spatial).explanation, "S^2 is not SO(3)"));
  CHECK(contains(check_answer("R^3 x T^3", spatial).explanation, "T^3 is not SO(3)"));
}

TEST_CASE("wrong answers: missing or extra factors are counted") {
  const auto p7 = parse_robot_description("base=planar joints=RRR wrist=spherical");
  auto c = check_answer("R^2 x T^6", p7);  // forgot that the base turns
  CHECK_FALSE(c.correct);
  CHECK(c.explanation ==
        "one circle factor is missing: expected 7 circle factors (6 revolute joints and the "
        "base turning in the plane), got 6; dimension: expected 9, got 8");
  c = check_answer("T^6", p7);  // forgot the base
  CHECK(contains(
      c.explanation,
      "2 R dimensions are missing: expected R^2 (the base's position (x, y)), got no R factor"));

  const auto t7 = parse_robot_description("joints=RRRRRRR");
  CHECK(check_answer("T^6", t7).explanation ==
        "one revolute joint is missing: expected 7 circle factors, got 6; dimension: expected 7, "
        "got 6");

  c = check_answer("SE(2)", parse_robot_description("base=planar-translating"));
  CHECK(contains(c.explanation,
                 "one circle factor too many: expected no circle factor (nothing on this robot "
                 "turns), got 1"));

  c = check_answer("SE(3) x T^6", parse_robot_description("joints=RRRRRR"));
  CHECK(contains(c.explanation, "SO(3) does not belong here"));
  CHECK(contains(c.explanation, "3 R dimensions too many"));

  c = check_answer("SE(2) x T^6", parse_robot_description("base=spatial joints=RRRRRR"));
  CHECK(contains(c.explanation, "SO(3) is missing"));
}

TEST_CASE("unreadable answers are incorrect with a reason, never an exception") {
  const auto p6 = parse_robot_description("joints=RRR wrist=spherical");
  for (const char* s : {"", "T^", "the six-torus", "T^6 +", "\xff\xfe", "((((", "S^1^6"}) {
    CAPTURE(s);
    csl::AnswerCheck c;
    CHECK_NOTHROW(c = check_answer(s, p6));
    CHECK_FALSE(c.correct);
    CHECK(contains(c.explanation, "could not read the answer: "));
  }
}
