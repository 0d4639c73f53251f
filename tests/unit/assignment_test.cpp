// Assignment files (core/teaching/assignment.hpp, assignment_grade.hpp, state_condition.hpp):
// every kind of error named by item and field, all errors at once, per-learner seeds, and
// grades checked against answers computed here from the exercises' given numbers (never from
// the exercise's own answer field).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "core/teaching/assignment.hpp"
#include "core/teaching/assignment_grade.hpp"
#include "core/teaching/state_condition.hpp"

namespace {

using json = nlohmann::json;
using namespace csl;

const json kScene = json::parse(R"({"version": 1, "workspace": {"min": [0, 0], "max": [1, 1]}, "robot": {"type": "point"},
  "obstacles": [{"type": "disk", "center": [0.5, 0.5], "radius": 0.1}], "start": [0.1, 0.1], "goal": [0.9, 0.9]})");

// One item of each kind, valid.
json base() {
  return {{"format", "cspacelab-assignment"},
          {"version", 1},
          {"title", "Week 3"},
          {"items",
           {{{"kind", "exercise"}, {"problem", "P10"}, {"points", 2}},
            {{"kind", "explore"}, {"title", "Look"}, {"prompt", "Step it."}, {"lesson", "step-prm"}, {"scene", kScene},
             {"params", {{"samples", 100}}}},
            {{"kind", "task"},
             {"title", "Find a path"},
             {"prompt", "With at most 50 samples."},
             {"lesson", "step-prm"},
             {"points", 3},
             {"check", {{"all", {{{"pointer", "/solved"}, {"equals", true}}, {{"pointer", "/params/samples"}, {"max", 50}}}}}}}}}};
}

std::vector<std::string> errors_of(const json& j) { return parse_assignment(j).errors; }

// Exactly one error, containing every one of `parts`.
void one_error(const std::function<void(json&)>& edit, std::initializer_list<std::string> parts) {
  json j = base();
  edit(j);
  const std::vector<std::string> errors = errors_of(j);
  INFO(j.dump());
  REQUIRE(errors.size() == 1);
  for (const std::string& p : parts) {
    INFO(errors[0], " should contain ", p);
    CHECK(errors[0].find(p) != std::string::npos);
  }
}

Assignment parsed(const json& j) {
  AssignmentParse p = parse_assignment(j);
  INFO((p.errors.empty() ? std::string() : p.errors[0]));
  REQUIRE(p.assignment);
  return *p.assignment;
}

AssignmentGrade grade(const Assignment& a, const json& answers, const std::string& learner = "") {
  AnswerSheetParse s = parse_answer_sheet(answers, a);
  INFO((s.errors.empty() ? std::string() : s.errors[0]));
  REQUIRE(s.sheet);
  return grade_assignment(a, *s.sheet, learner);
}

// S^1 distance written again: the least |q2 - q1 + 2 pi k|.
double s1(double q1, double q2) {
  double best = 1e300;
  for (int k = -4; k <= 4; ++k) best = std::min(best, std::fabs(q2 - q1 + 2 * 3.14159265358979323846 * k));
  return best;
}

std::string text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  return buf;
}

}  // namespace

TEST_CASE("assignment: a valid file, its defaults and its normal form") {
  const Assignment a = parsed(base());
  REQUIRE(a.items.size() == 3);
  CHECK(a.pass == kDefaultPass);
  CHECK(a.seed_key == "Week 3");  // default: the title
  CHECK(a.items[0].title.rfind("P10: ", 0) == 0);
  CHECK(!a.items[0].seed);  // default: per learner
  CHECK(a.items[1].points == 0);  // explore: credit for visiting, none by default
  CHECK(a.max_points() == 5);
  // The normal form reads back to itself.
  const json normal = assignment_to_json(a);
  CHECK(assignment_to_json(parsed(normal)) == normal);
  CHECK(normal["items"][0]["seed"] == "learner");
}

TEST_CASE("assignment: top-level errors name the field") {
  one_error([](json& j) { j["format"] = "cspacelab-scene"; }, {"format: ", "\"cspacelab-scene\""});
  one_error([](json& j) { j["version"] = 2; }, {"version: 2 is not one this lab reads (1)"});
  one_error([](json& j) { j.erase("version"); }, {"version: required"});
  one_error([](json& j) { j.erase("title"); }, {"title: required"});
  one_error([](json& j) { j["title"] = std::string(201, 'x'); }, {"title: a text of 1 to 200 characters, got 201"});
  one_error([](json& j) { j["titel"] = "x"; }, {"\"titel\": unknown field"});
  one_error([](json& j) { j["pass"] = 1.5; }, {"pass: ", "[0, 1]", "1.5"});
  one_error([](json& j) { j["seed_key"] = ""; }, {"seed_key: a text of 1 to 200"});
  one_error([](json& j) { j["description"] = std::string(4001, 'd'); }, {"description: a text of 1 to 4000 characters"});
  one_error([](json& j) { j["items"] = json::array(); }, {"items: a list of 1 to 100 items, got 0"});
  one_error([](json& j) { j["items"] = json::array(); for (int i = 0; i < 101; ++i) j["items"].push_back(base()["items"][0]); },
            {"items: a list of 1 to 100 items, got 101"});
  CHECK(parse_assignment_text("{\"format\": ").errors.size() == 1);
  CHECK(parse_assignment(json::array()).errors.size() == 1);
}

TEST_CASE("assignment: exercise errors name the item and the field") {
  one_error([](json& j) { j["items"][0]["points"] = -1; }, {"items[0] (P10): points: a number in [0, 1000], got -1"});
  one_error([](json& j) { j["items"][0]["points"] = 1001; }, {"items[0] (P10): points: ", "1001"});
  one_error([](json& j) { j["items"][0]["problem"] = "P14"; }, {"items[0] (P14): problem: P1 to P13, got \"P14\""});
  one_error([](json& j) { j["items"][0].erase("problem"); }, {"items[0]: problem: required"});
  one_error([](json& j) { j["items"][0]["seed"] = -1; }, {"items[0] (P10): seed: an integer in [0, 2^53 - 1] or \"learner\", got -1"});
  one_error([](json& j) { j["items"][0]["seed"] = 9007199254740992ULL; }, {"seed: ", "9007199254740992"});
  one_error([](json& j) { j["items"][0]["seed"] = 1.5; }, {"seed: ", "1.5"});
  one_error([](json& j) { j["items"][0]["seed"] = "student"; }, {"seed: ", "\"student\""});
  one_error([](json& j) { j["items"][0]["tolerance"] = -0.1; }, {"items[0] (P10): tolerance: a finite number >= 0, got -0.1"});
  one_error([](json& j) { j["items"][0]["tolerance"] = "0.1"; }, {"tolerance: a finite number >= 0"});
  one_error([](json& j) { j["items"][0]["problem"] = "P3", j["items"][0]["tolerance"] = 0.1; }, {"items[0] (P3): tolerance: P3's answer", "notation"});
  one_error([](json& j) { j["items"][0]["tolerence"] = 0.1; }, {"items[0] (P10): \"tolerence\": unknown field"});
  one_error([](json& j) { j["items"][0]["title"] = ""; }, {"items[0] (P10): title: a text of 1 to 200 characters, got 0"});
  one_error([](json& j) { j["items"][0]["kind"] = "quiz"; }, {"items[0] (P10): kind: exercise, explore or task, got \"quiz\""});
  one_error([](json& j) { j["items"][0] = 3; }, {"items[0]: an item is an object"});
  one_error([](json& j) { j["items"][0]["tries"] = 0; }, {"items[0] (P10): tries: how many checks", "[1, 100], got 0"});
  one_error([](json& j) { j["items"][0]["tries"] = 101; }, {"items[0] (P10): tries: ", "got 101"});
  one_error([](json& j) { j["items"][0]["tries"] = 2.5; }, {"tries: ", "got 2.5"});
  one_error([](json& j) { j["items"][0]["tries"] = "3"; }, {"tries: ", "got \"3\""});
  one_error([](json& j) { j["items"][0]["tries"] = 18446744073709551615ULL; }, {"tries: ", "got 18446744073709551615"});
}

TEST_CASE("assignment: explore and task errors name the item (with its title) and the field") {
  one_error([](json& j) { j["items"][1]["lesson"] = "step_prm"; }, {"items[1] (\"Look\"): lesson: one of torus", "got \"step_prm\""});
  one_error([](json& j) { j["items"][1].erase("lesson"); }, {"items[1] (\"Look\"): lesson: required"});
  one_error([](json& j) { j["items"][1]["params"] = {{"sample", 10}}; }, {"items[1] (\"Look\"): params: ", "\"sample\" is not a parameter of step-prm"});
  one_error([](json& j) { j["items"][1]["params"] = {{"samples", -1}}; }, {"items[1] (\"Look\"): params: samples"});
  one_error([](json& j) { j["items"][1]["params"] = json::array(); }, {"params: an object"});
  one_error([](json& j) { j["items"][1]["scene"]["robot"]["type"] = "blimp"; }, {"items[1] (\"Look\"): scene: "});
  one_error([](json& j) { j["items"][1]["scene"] = "wall-gap"; }, {"items[1] (\"Look\"): scene: a scene (a JSON object"});
  one_error([](json& j) { j["items"][1]["scene"]["robot"] = {{"type", "arm"}, {"base", {0.5, 0.5}}, {"lengths", {0.3, 0.3}}};
                          j["items"][1]["scene"]["start"] = {0, 0}; j["items"][1]["scene"]["goal"] = {1, 1}; },
            {"items[1] (\"Look\"): scene: the step-prm lesson takes scenes with robot point"});
  one_error([](json& j) { j["items"][1].erase("prompt"); }, {"items[1] (\"Look\"): prompt: required"});
  one_error([](json& j) { j["items"][1]["prompt"] = std::string(2001, 'p'); }, {"prompt: a text of 1 to 2000 characters, got 2001"});
  one_error([](json& j) { j["items"][1].erase("title"); }, {"items[1]: title: required"});
  one_error([](json& j) { j["items"][1]["check"] = {{"pointer", "/solved"}, {"equals", true}}; }, {"items[1] (\"Look\"): \"check\": unknown field"});
  one_error([](json& j) { j["items"][2]["points"] = -1; }, {"items[2] (\"Find a path\"): points: a number in [0, 1000], got -1"});
  one_error([](json& j) { j["items"][2].erase("check"); }, {"items[2] (\"Find a path\"): check: required"});
  one_error([](json& j) { j["items"][2]["tries"] = -1; }, {"items[2] (\"Find a path\"): tries: ", "got -1"});
  // A visit is no check: an explore item has no tries.
  one_error([](json& j) { j["items"][1]["tries"] = 2; }, {"items[1] (\"Look\"): \"tries\": unknown field"});
}

TEST_CASE("assignment: tries: kept in the normal form and the student's view; answers say theirs") {
  json j = base();
  j["items"][0]["tries"] = 3;
  j["items"][2]["tries"] = 1;
  const Assignment a = parsed(j);
  CHECK(a.items[0].tries == 3u);
  CHECK(a.items[2].tries == 1u);
  CHECK(!parsed(base()).items[0].tries);  // default: any number
  const json normal = assignment_to_json(a);
  CHECK(normal["items"][0]["tries"] == 3);
  CHECK(!normal["items"][1].contains("tries"));
  CHECK(assignment_to_json(parsed(normal)) == normal);
  const json view = assignment_student_view(a, "s");
  CHECK(view["items"][0]["tries"] == 3);
  CHECK(view["items"][2]["tries"] == 1);
  CHECK(!view["items"][1].contains("tries"));

  // An answer's tries: reported beside the item's limit, not graded; more than it allows is the
  // instructor's to read, not a file refused.
  const auto errors = [&](const json& answers) { return parse_answer_sheet(answers, a).errors; };
  CHECK(errors({{"answers", {{{"item", 0}, {"answer", "1"}, {"tries", 3}}}}}).empty());
  CHECK(errors({{"answers", {{{"item", 2}, {"state", json::object()}, {"tries", 2}}}}}).empty());
  CHECK(errors({{"answers", {{{"item", 0}, {"answer", "1"}, {"tries", 0}}}}})[0] ==
        "answers[0]: tries: how many times it was checked, an integer in [1, 2147483648], got 0");
  CHECK(errors({{"answers", {{{"item", 0}, {"answer", "1"}, {"tries", "2"}}}}})[0].find("tries: ") != std::string::npos);
  CHECK(errors({{"answers", {{{"item", 1}, {"visited", true}, {"tries", 1}}}}})[0] ==
        "answers[0]: \"tries\": item 1 (explore) is answered with \"visited\"");
  const Assignment any = parsed(base());
  CHECK(parse_answer_sheet({{"answers", {{{"item", 0}, {"answer", "1"}, {"tries", 40}}}}}, any).errors.empty());

  const AssignmentGrade g = grade(a, {{"answers", {{{"item", 0}, {"answer", "1"}, {"tries", 5}}}}});
  CHECK(g.items[0].tries == 5);
  const json out = assignment_grade_to_json(a, g);
  CHECK(out["items"][0]["tries"] == 5);
  CHECK(out["items"][0]["tries_allowed"] == 3);
  CHECK(!out["items"][1].contains("tries"));
  CHECK(!out["items"][1].contains("tries_allowed"));
  CHECK(out["items"][2]["tries_allowed"] == 1);
  // The same answer without its count grades the same.
  CHECK(grade(a, {{"answers", {{{"item", 0}, {"answer", "1"}}}}}).raw == g.raw);
}

TEST_CASE("assignment: a task's condition: pointers and operands checked, each error where it is") {
  const auto check = [](const json& c, std::initializer_list<std::string> parts) {
    one_error([&](json& j) { j["items"][2]["check"] = c; }, parts);
  };
  check({{"pointer", "solved"}, {"equals", true}}, {"items[2] (\"Find a path\"): check: pointer: a JSON pointer starts with '/'"});
  check({{"pointer", "/a~2b"}, {"equals", true}}, {"check: pointer: '~' is written ~0"});
  check({{"pointer", "/" + std::string(200, 'x')}, {"equals", 1}}, {"check: pointer: at most 200 characters"});
  check({{"pointer", 3}, {"equals", 1}}, {"check: pointer: a JSON pointer"});
  check({{"pointer", "/nodes"}}, {"check: a comparison: equals, min or max"});
  check({{"pointer", "/nodes"}, {"equals", 3}, {"max", 4}}, {"check: equals, or min and max: not both"});
  check({{"pointer", "/nodes"}, {"min", 5}, {"max", 4}}, {"check: min 5 is more than max 4"});
  check({{"pointer", "/nodes"}, {"min", "5"}}, {"check: min: a finite number, got \"5\""});
  check({{"pointer", "/path"}, {"equals", {1, 2}}}, {"check: equals: a string, a number, true, false or null"});
  check({{"pointer", "/nodes"}, {"equals", 3}, {"note", "x"}}, {"check: unknown field \"note\""});
  check({{"all", json::array()}}, {"check: all: a list of 1 to 20 conditions"});
  check({{"all", {{{"pointer", "/a"}, {"equals", 1}}}}, {"any", {{{"pointer", "/a"}, {"equals", 1}}}}}, {"check: \"all\" or \"any\", not both"});
  check({{"any", {{{"pointer", "/a"}, {"equals", 1}}, {{"pointer", "/b"}, {"max", "x"}}}}}, {"check.any[1]: max: a finite number"});
  json deep = {{"pointer", "/a"}, {"equals", 1}};
  for (int i = 0; i < 5; ++i) deep = {{"all", json::array({deep})}};
  check(deep, {"at most 4 levels of all/any"});
  check(42, {"check: a condition is an object"});
}

TEST_CASE("assignment: every error at once, each naming its item") {
  json j = base();
  j["pass"] = -1;
  j["items"][0]["points"] = -1;
  j["items"][0]["seed"] = "x";
  j["items"][1]["lesson"] = "nope";
  j["items"][2]["check"]["all"][1]["max"] = "fifty";
  const std::vector<std::string> errors = errors_of(j);
  REQUIRE(errors.size() == 5);
  CHECK(errors[0].rfind("pass: ", 0) == 0);
  CHECK(errors[1].rfind("items[0] (P10): points: ", 0) == 0);
  CHECK(errors[2].rfind("items[0] (P10): seed: ", 0) == 0);
  CHECK(errors[3].rfind("items[1] (\"Look\"): lesson: ", 0) == 0);
  CHECK(errors[4].rfind("items[2] (\"Find a path\"): check.all[1]: max: ", 0) == 0);
  CHECK(!parse_assignment(j).assignment);
}

TEST_CASE("assignment: per-learner seeds: the same on reload, different between learners, fixed seeds kept") {
  const Assignment a = parsed(base());
  std::set<std::uint64_t> seeds;
  for (int i = 0; i < 1000; ++i) {
    const std::string id = "learner-" + std::to_string(i);
    const std::uint64_t s = learner_seed(a, 0, id);
    CHECK(s <= kMaxExerciseSeed);
    CHECK(learner_seed(a, 0, id) == s);  // a reload
    seeds.insert(s);
  }
  CHECK(seeds.size() == 1000);
  // The exercise follows the seed; another item, another seed.
  CHECK(assignment_exercise(a, 0, "ann").seed == learner_seed(a, 0, "ann"));
  CHECK(assignment_exercise(a, 0, "ann").prompt != assignment_exercise(a, 0, "bob").prompt);
  CHECK(learner_seed(a, 0, "ann") != learner_seed(a, 1, "ann"));
  // No learner id: the id "", the same for everyone.
  CHECK(assignment_exercise(a, 0, "").seed == learner_seed(a, 0, ""));
  // A fixed seed ignores the learner.
  json fixed = base();
  fixed["items"][0]["seed"] = 17;
  const Assignment f = parsed(fixed);
  CHECK(assignment_exercise(f, 0, "ann").seed == 17);
  CHECK(assignment_exercise(f, 0, "bob").seed == 17);
  // The seed key: a new title changes everyone's numbers unless the key is kept.
  json retitled = base();
  retitled["title"] = "Week 3 (fixed typo)";
  CHECK(learner_seed(parsed(retitled), 0, "ann") != learner_seed(a, 0, "ann"));
  retitled["seed_key"] = "Week 3";
  CHECK(learner_seed(parsed(retitled), 0, "ann") == learner_seed(a, 0, "ann"));
}

TEST_CASE("assignment: P10 graded against the S^1 distance computed here from the given numbers") {
  const Assignment a = parsed(base());
  for (const std::string learner : {"ann", "bob", "chen", ""}) {
    const Exercise e = assignment_exercise(a, 0, learner);
    const double want = s1(e.given["q1"].get<double>(), e.given["q2"].get<double>());
    const AssignmentGrade right = grade(a, {{"answers", {{{"item", 0}, {"answer", text(want)}}}}}, learner);
    CHECK(right.items[0].correct);
    CHECK(right.items[0].points == 2);
    CHECK(right.items[0].expected.get<double>() == doctest::Approx(want).epsilon(1e-9));
    CHECK(*right.items[0].seed == e.seed);
    const AssignmentGrade wrong = grade(a, {{"answers", {{{"item", 0}, {"answer", text(want + 0.05)}}}}}, learner);
    CHECK(!wrong.items[0].correct);
    CHECK(wrong.items[0].points == 0);
    CHECK(wrong.items[0].attempted);
  }
}

TEST_CASE("assignment: P12 graded against N found here by brute force; the tolerance override") {
  json j = base();
  j["items"][0] = {{"kind", "exercise"}, {"problem", "P12"}, {"seed", 4}};
  const Assignment a = parsed(j);
  const Exercise e = assignment_exercise(a, 0, "");
  const double cx = e.given["center"][0].get<double>(), cy = e.given["center"][1].get<double>();
  const double r = e.given["radius"].get<double>();
  int n = 0;
  for (int k = 2; k < 100000 && !n; ++k)
    for (int i = 0; i < k && !n; ++i)
      if (std::hypot(static_cast<double>(i) / (k - 1) - cx, cy) <= r) n = k;
  REQUIRE(n > 0);
  CHECK(grade(a, {{"answers", {{{"item", 0}, {"answer", std::to_string(n)}}}}}).items[0].correct);
  CHECK(!grade(a, {{"answers", {{{"item", 0}, {"answer", std::to_string(n + 1)}}}}}).items[0].correct);

  // P10 within 0.008: wrong with the exercise's 0.005, right with an override of 0.01.
  json k = base();
  k["items"][0]["seed"] = 5;
  const Assignment own = parsed(k);
  k["items"][0]["tolerance"] = 0.01;
  const Assignment wide = parsed(k);
  const Exercise p10 = assignment_exercise(own, 0, "");
  const std::string off = text(s1(p10.given["q1"].get<double>(), p10.given["q2"].get<double>()) + 0.008);
  CHECK(!grade(own, {{"answers", {{{"item", 0}, {"answer", off}}}}}).items[0].correct);
  CHECK(grade(wide, {{"answers", {{{"item", 0}, {"answer", off}}}}}).items[0].correct);
  // One tolerance in the hint, the one that counts: the problem's own 0.005 is replaced.
  CHECK(p10.format_hint == "radians, e.g. 1.57 or pi/2 (within 0.005)");
  CHECK(assignment_exercise(wide, 0, "").format_hint == "radians, e.g. 1.57 or pi/2 (within 0.01 in this assignment)");
  // P12's hint states no tolerance: the assignment's comes first in its brackets.
  j["items"][0]["tolerance"] = 1;
  CHECK(assignment_exercise(parsed(j), 0, "").format_hint ==
        "a whole number N >= 2 (within 1 in this assignment; both ends counted)");
  // P13's relative tolerance ("within 1%") gives way to the assignment's absolute one.
  j["items"][0] = {{"kind", "exercise"}, {"problem", "P13"}, {"seed", 2}, {"tolerance", 0.05}};
  CHECK(assignment_exercise(parsed(j), 0, "").format_hint == "a number (within 0.05 in this assignment; 0 if no force acts)");
}

TEST_CASE("assignment: a task is checked from the lesson's state") {
  const Assignment a = parsed(base());
  const auto task = [&](const json& state) { return grade(a, {{"answers", {{{"item", 2}, {"state", state}}}}}).items[2]; };
  const ItemGrade done = task({{"solved", true}, {"params", {{"samples", 40}}}, {"nodes", 42}});
  CHECK(done.correct);
  CHECK(done.points == 3);
  const ItemGrade too_many = task({{"solved", true}, {"params", {{"samples", 80}}}});
  CHECK(!too_many.correct);
  CHECK(too_many.attempted);
  CHECK(too_many.explanation.find("the parameter samples is 80 (wanted: the parameter samples is at most 50)") != std::string::npos);
  const ItemGrade missing = task({{"params", {{"samples", 40}}}});
  CHECK(!missing.correct);
  CHECK(missing.explanation.find("no: solved is not in the state") != std::string::npos);
  CHECK(!task({{"solved", "true"}, {"params", {{"samples", 40}}}}).correct);  // a string is not true
  CHECK(!task({{"solved", true}, {"params", {{"samples", "40"}}}}).correct);  // nor a number
  // In words for the student: the pointers' segments, "params" read as "the parameter".
  CHECK(done.expected == "solved is true and the parameter samples is at most 50");
  // A pointer with an empty name has no words: it is shown as written.
  std::vector<std::string> errors;
  const auto odd = csl::parse_state_condition({{"pointer", "/params/"}, {"max", 1}}, "check", errors);
  REQUIRE(odd);
  CHECK(csl::state_condition_text(*odd) == "/params/ is at most 1");
}

TEST_CASE("assignment: conditions: any, bounds inclusive, numbers by value, escaped pointers") {
  std::vector<std::string> errors;
  const auto cond = [&](const json& j) {
    auto c = parse_state_condition(j, "check", errors);
    REQUIRE(c);
    return *c;
  };
  const StateCondition any = cond({{"any", {{{"pointer", "/a"}, {"min", 1}, {"max", 2}}, {{"pointer", "/b"}, {"equals", "x"}}}}});
  CHECK(evaluate_state_condition(any, {{"a", 1}}).met);
  CHECK(evaluate_state_condition(any, {{"a", 2.0}}).met);
  CHECK(!evaluate_state_condition(any, {{"a", 2.5}}).met);
  CHECK(evaluate_state_condition(any, {{"a", 7}, {"b", "x"}}).met);
  CHECK(evaluate_state_condition(any, {{"a", 7}, {"b", "x"}}).lines.size() == 2);  // each term explained
  CHECK(evaluate_state_condition(cond({{"pointer", "/n"}, {"equals", 4}}), {{"n", 4.0}}).met);
  CHECK(evaluate_state_condition(cond({{"pointer", "/a~1b/0"}, {"equals", nullptr}}), {{"a/b", {nullptr}}}).met);
  CHECK(!evaluate_state_condition(cond({{"pointer", "/list/5"}, {"min", 0}}), {{"list", {1, 2}}}).met);
  CHECK(!evaluate_state_condition(cond({{"pointer", "/list/x"}, {"min", 0}}), {{"list", {1, 2}}}).met);
  CHECK(!evaluate_state_condition(cond({{"pointer", "/n"}, {"min", 0}}), json::array()).met);
  CHECK(errors.empty());
  CHECK(state_condition_to_json(any) == json({{"any", {{{"pointer", "/a"}, {"min", 1}, {"max", 2}}, {{"pointer", "/b"}, {"equals", "x"}}}}}));
}

TEST_CASE("assignment: totals, scaled score, completion and the pass mark") {
  json j = base();
  j["pass"] = 0.4;
  j["items"][0]["seed"] = 3;
  j["items"][1]["points"] = 1;  // 2 + 1 + 3 = 6
  const Assignment a = parsed(j);
  const Exercise e = assignment_exercise(a, 0, "");
  const std::string right = text(s1(e.given["q1"].get<double>(), e.given["q2"].get<double>()));
  const json solved = {{"solved", true}, {"params", {{"samples", 30}}}};

  const AssignmentGrade none = grade(a, {{"answers", json::array()}});
  CHECK(none.raw == 0);
  CHECK(none.max == 6);
  CHECK(none.scaled == 0);
  CHECK(!none.completed);
  CHECK(!none.passed);

  // The exercise and the visit: 3 of 6, 0.5 >= 0.4 passes, but the task is not attempted.
  const AssignmentGrade half = grade(a, {{"answers", {{{"item", 0}, {"answer", right}}, {{"item", 1}, {"visited", true}}}}});
  CHECK(half.raw == 3);
  CHECK(half.scaled == 0.5);
  CHECK(half.passed);
  CHECK(!half.completed);

  const AssignmentGrade all = grade(a, {{"answers", {{{"item", 2}, {"state", solved}}, {{"item", 0}, {"answer", right}}, {{"item", 1}, {"visited", true}}}}});
  CHECK(all.raw == 6);
  CHECK(all.scaled == 1);
  CHECK(all.completed);
  CHECK(all.passed);

  // An unreadable answer is not an attempt; a wrong one is.
  const json rest = {{{"item", 1}, {"visited", true}}, {{"item", 2}, {"state", solved}}};
  json garbled = rest, wrong = rest;
  garbled.push_back({{"item", 0}, {"answer", "about two"}});
  wrong.push_back({{"item", 0}, {"answer", "99"}});
  CHECK(!grade(a, {{"answers", garbled}}).completed);
  const AssignmentGrade w = grade(a, {{"answers", wrong}});
  CHECK(w.completed);
  CHECK(w.raw == 4);
  CHECK(w.scaled == doctest::Approx(4.0 / 6.0));

  // Exactly at the pass mark passes; below it does not.
  j["pass"] = 0.5;
  CHECK(grade(parsed(j), {{"answers", {{{"item", 0}, {"answer", right}}, {{"item", 1}, {"visited", true}}}}}).passed);
  j["pass"] = 0.51;
  CHECK(!grade(parsed(j), {{"answers", {{{"item", 0}, {"answer", right}}, {{"item", 1}, {"visited", true}}}}}).passed);

  // Nothing to earn: scaled 1 once completed.
  json zero = base();
  zero["items"] = json::array({base()["items"][1]});
  const Assignment z = parsed(zero);
  CHECK(grade(z, {{"answers", json::array()}}).scaled == 0);
  CHECK(grade(z, {{"answers", {{{"item", 0}, {"visited", true}}}}}).scaled == 1);
  const json out = assignment_grade_to_json(a, all);
  CHECK(out["score"] == json({{"raw", 6.0}, {"min", 0.0}, {"max", 6.0}, {"scaled", 1.0}}));
}

TEST_CASE("assignment: answers: every problem at once, each naming its entry") {
  const Assignment a = parsed(base());
  const auto errors = [&](const json& j) { return parse_answer_sheet(j, a).errors; };
  CHECK(errors({{"answers", {{{"item", 3}, {"answer", "1"}}}}})[0] == "answers[0]: item: an item's index, 0 to 2, got 3");
  CHECK(errors({{"answers", {{{"item", 0}, {"answer", "1"}}, {{"item", 0}, {"answer", "2"}}}}})[0] == "answers[1]: item 0 is answered twice");
  CHECK(errors({{"answers", {{{"item", 2}, {"answer", "1"}}}}}).size() == 2);  // "answer" is not a task's field, and "state" is missing
  CHECK(errors({{"answers", {{{"item", 1}, {"visited", "yes"}}}}})[0].find("answers[0]: visited: true or false") == 0);
  CHECK(errors({{"answers", {{{"item", 0}, {"answer", 1.57}}}}})[0].find("answers[0]: answer: what the student typed") == 0);
  CHECK(errors({{"answer", json::array()}}).size() == 2);  // unknown field, and answers missing
  CHECK(errors({{"learner", 7}, {"answers", json::array()}})[0].find("learner: a learner id") == 0);
  const std::vector<std::string> all = errors({{"answers", {{{"item", 9}}, {{"item", 1}, {"visited", 1}}, {{"item", 0}, {"answer", "1"}, {"note", "x"}}}}});
  REQUIRE(all.size() == 3);
  CHECK(all[0].rfind("answers[0]: ", 0) == 0);
  CHECK(all[1].rfind("answers[1]: ", 0) == 0);
  CHECK(all[2].rfind("answers[2]: \"note\"", 0) == 0);
}
