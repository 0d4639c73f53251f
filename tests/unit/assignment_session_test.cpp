// One student's work on an assignment (core/teaching/assignment_session.hpp): answers recorded
// and graded by the grade's code, statuses, the task's state cut to what its check reads, the
// suspend object small and resumed exactly, answers frozen by submission, and the review only
// after it. Right answers are computed here from the exercise's given numbers.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/teaching/assignment_session.hpp"

namespace {

using json = nlohmann::json;
using namespace csl;

// `tries`: the exercise's and the task's limit, if any.
Assignment example(std::optional<unsigned> tries = std::nullopt) {
  json j = json::parse(R"({"format": "cspacelab-assignment", "version": 1, "title": "Week 3", "pass": 0.5,
    "items": [
      {"kind": "exercise", "problem": "P10", "points": 2},
      {"kind": "explore", "title": "Look", "prompt": "Step it.", "lesson": "step-prm"},
      {"kind": "task", "title": "Find a path", "prompt": "At most 50 samples.", "lesson": "step-prm", "points": 3,
       "check": {"all": [{"pointer": "/solved", "equals": true}, {"pointer": "/params/samples", "max": 50}]}}]})");
  if (tries) j["items"][0]["tries"] = j["items"][2]["tries"] = *tries;
  AssignmentParse p = parse_assignment(j);
  REQUIRE(p.assignment);
  return *p.assignment;
}

// The S^1 distance written again: the least |q2 - q1 + 2 pi k|.
std::string s1_answer(const Exercise& e) {
  const double q1 = e.given["q1"].get<double>(), q2 = e.given["q2"].get<double>();
  double best = 1e300;
  for (int k = -4; k <= 4; ++k) best = std::min(best, std::fabs(q2 - q1 + 2 * 3.14159265358979323846 * k));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", best);
  return buf;
}

// A state as the step-prm lesson answers it, with much the check does not read.
json big_state(bool solved, int samples) {
  json vertices = json::array();
  for (int i = 0; i < 500; ++i) vertices.push_back({i * 0.001, 0.5});
  return {{"solved", solved}, {"params", {{"samples", samples}, {"k", 8}, {"seed", 3}}}, {"roadmap", {{"vertices", vertices}}},
          {"scene_name", "A wall with a gap"}};
}

}  // namespace

TEST_CASE("assignment session: answers graded by the grade's code, statuses and totals") {
  AssignmentSession s = start_assignment_session(example(), "student-7");
  json st = assignment_session_json(s);
  CHECK(st["items"][0]["status"] == "open");
  CHECK(st["items"][0]["id"] == "item-1");
  CHECK(st["grade"]["max"] == 5);  // 2 + 0 (explore) + 3
  CHECK(st["grade"]["raw"] == 0);
  CHECK(st["interactions"][0]["result"] == "neutral");
  CHECK(st["interactions"][0]["type"] == "numeric");
  CHECK(st["interactions"][1]["type"] == "other");

  const Exercise e = assignment_exercise(s.assignment, 0, "student-7");
  CHECK(st["items"][0]["seed"] == e.seed);
  record_exercise_answer(s, 0, "abc");
  CHECK(assignment_session_json(s)["items"][0]["status"] == "answered");  // unreadable: no attempt
  record_exercise_answer(s, 0, "0.0");
  st = assignment_session_json(s);
  CHECK(st["items"][0]["status"] == (s1_answer(e) == "0.000000" ? "correct" : "incorrect"));
  record_exercise_answer(s, 0, s1_answer(e));
  record_visit(s, 1);
  st = assignment_session_json(s);
  CHECK(st["items"][0]["status"] == "correct");
  CHECK(st["items"][0]["feedback"] == "Right.");
  CHECK(st["items"][1]["status"] == "viewed");
  CHECK(st["grade"]["raw"] == 2);
  CHECK(st["grade"]["completed"] == false);

  // The task: a state with too many samples, then one that meets the check.
  record_task_state(s, 2, big_state(true, 80));
  CHECK(assignment_session_json(s)["items"][2]["status"] == "incorrect");
  record_task_state(s, 2, big_state(true, 50));
  st = assignment_session_json(s);
  CHECK(st["items"][2]["status"] == "correct");
  CHECK(st["grade"]["raw"] == 5);
  CHECK(st["grade"]["scaled"] == 1.0);
  CHECK(st["grade"]["completed"] == true);
  CHECK(st["grade"]["passed"] == true);
  // Kept of the state: what the check reads, nothing else.
  CHECK(st["items"][2]["answer"] == json({{"solved", true}, {"params", {{"samples", 50}}}}));
  CHECK(st["interactions"][2]["learner_response"].get<std::string>().find("50") != std::string::npos);

  // The answers it reports grade to the same totals through the grade's reader (the CLI's).
  AnswerSheetParse sheet = parse_answer_sheet(st["answers"], s.assignment);
  REQUIRE(sheet.sheet);
  const AssignmentGrade g = grade_assignment(s.assignment, *sheet.sheet, "student-7");
  CHECK(g.raw == st["grade"]["raw"].get<double>());
  CHECK(g.completed);
}

TEST_CASE("assignment session: wrong kinds and out-of-range items change nothing") {
  AssignmentSession s = start_assignment_session(example(), "");
  CHECK_THROWS_WITH_AS(record_visit(s, 0), doctest::Contains("is an exercise item"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(record_exercise_answer(s, 3, "1"), doctest::Contains("0 to 2"), std::invalid_argument);
  CHECK_THROWS_AS(record_task_state(s, 1, json::object()), std::invalid_argument);
  CHECK_THROWS_AS(record_exercise_answer(s, 0, std::string(kMaxAnswerText + 1, '1')), std::invalid_argument);
  CHECK_THROWS_AS(start_assignment_session(example(), std::string(kMaxLearnerId + 1, 'x')), std::invalid_argument);
  for (const auto& a : s.answers) CHECK(!a);
}

TEST_CASE("assignment session: the excerpt of a state judges as the state does") {
  std::vector<std::string> errors;
  const auto cond = parse_state_condition(
      json::parse(R"({"any": [{"pointer": "/roadmap", "equals": 3}, {"all": [{"pointer": "/a/b", "min": 1},
                  {"pointer": "/a", "equals": null}, {"pointer": "/list/1", "max": 2}, {"pointer": "/missing", "equals": 1}]}]})"),
      "check", errors);
  REQUIRE(cond);
  const json state = {{"roadmap", {{"vertices", json::array({1, 2, 3})}}}, {"a", {{"b", 4}, {"c", "x"}}}, {"list", {5, 1, 7}}};
  const json ex = task_state_excerpt(*cond, state);
  CHECK(ex["roadmap"] == json::object());  // in place of the roadmap: no comparison takes either
  CHECK(ex["a"] == json({{"b", 4}}));        // /a's stand-in did not overwrite /a/b
  CHECK(ex.at(json::json_pointer("/list/1")) == 1);
  CHECK(!ex.contains("missing"));
  CHECK(evaluate_state_condition(*cond, ex).met == evaluate_state_condition(*cond, state).met);
  CHECK(evaluate_state_condition(*cond, ex).lines.size() == evaluate_state_condition(*cond, state).lines.size());
}

TEST_CASE("assignment session: the suspend object is small and resumes exactly") {
  AssignmentSession s = start_assignment_session(example(), "student-7");
  record_exercise_answer(s, 0, "pi/2");
  record_task_state(s, 2, big_state(true, 50));
  s.current = 2;
  const json suspend = session_suspend(s);
  CHECK(suspend.dump().size() < 200);  // the roadmap of the state is not in it
  // Each answer with its tries (one each: both could be graded).
  CHECK(suspend ==
        json::parse(R"({"v": 1, "c": 2, "s": 0, "a": [[0, "pi/2", 1], [2, {"params": {"samples": 50}, "solved": true}, 1]]})"));

  AssignmentSession r = start_assignment_session(example(), "student-7");
  // Through its text, as an LMS keeps it.
  CHECK(resume_session(r, json::parse(suspend.dump())).empty());
  CHECK(assignment_session_json(r) == assignment_session_json(s));

  // Submitted: the answers are final, the review shows what was expected.
  s.submitted = true;
  CHECK_THROWS_WITH_AS(record_visit(s, 1), doctest::Contains("submitted"), std::invalid_argument);
  const json st = assignment_session_json(s);
  CHECK(st["items"][0].contains("expected"));
  CHECK(!st["items"][0]["explanation"].get<std::string>().empty());
  CHECK(st["interactions"][0].contains("correct_response"));
  CHECK(!assignment_session_json(r)["items"][0].contains("expected"));
  CHECK(!assignment_session_json(r)["interactions"][0].contains("correct_response"));
  AssignmentSession r2 = start_assignment_session(example(), "student-7");
  CHECK(resume_session(r2, session_suspend(s)).empty());
  CHECK(r2.submitted);
}

TEST_CASE("assignment session: a bad suspend object is refused whole, naming each problem") {
  AssignmentSession s = start_assignment_session(example(), "");
  record_exercise_answer(s, 0, "1");
  const json before = assignment_session_json(s);
  const std::vector<std::string> errors =
      resume_session(s, json::parse(R"({"v": 2, "c": 9, "s": 3, "a": [[0, 5], [1, 1], [1, 1], [7, "x"]], "x": 1})"));
  REQUIRE(errors.size() >= 6);
  const auto has = [&](const std::string& part) {
    for (const std::string& e : errors)
      if (e.find(part) != std::string::npos) return true;
    return false;
  };
  CHECK(has("\"x\": unknown field"));
  CHECK(has("v: 1"));
  CHECK(has("c: the current item, 0 to 2"));
  CHECK(has("s: 0 or 1"));
  CHECK(has("a[3]: [item, answer]"));
  CHECK(has("answer: what the student typed"));
  CHECK(has("answered twice"));
  for (const std::string& e : errors) CHECK(e.rfind("resume: ", 0) == 0);
  CHECK(assignment_session_json(s) == before);
}

TEST_CASE("assignment session: an answer that would overflow the suspend data is refused") {
  json j = json::parse(R"({"format": "cspacelab-assignment", "version": 1, "title": "Many", "items": []})");
  for (int i = 0; i < 10; ++i) j["items"].push_back({{"kind", "exercise"}, {"problem", "P10"}});
  AssignmentParse p = parse_assignment(j);
  REQUIRE(p.assignment);
  AssignmentSession s = start_assignment_session(*p.assignment, "");
  for (int i = 0; i < 4; ++i) record_exercise_answer(s, i, std::string(900, '1'));
  CHECK_THROWS_WITH_AS(record_exercise_answer(s, 4, std::string(900, '2')), doctest::Contains("too long"), std::invalid_argument);
  CHECK(!s.answers[4]);
  CHECK(session_suspend(s).dump().size() < kMaxSuspendChars);
}

TEST_CASE("assignment session: a slip over a checked answer is refused and keeps its grade") {
  AssignmentSession s = start_assignment_session(example(2), "student-7");
  const Exercise e = assignment_exercise(s.assignment, 0, "student-7");
  const auto item = [&](std::size_t i) { return assignment_session_json(s)["items"][i]; };
  // Unreadable with nothing recorded: recorded, as it was (the card says what could not be read).
  record_exercise_answer(s, 0, "2 pi +");
  CHECK(item(0)["answer"] == "2 pi +");
  CHECK(item(0)["status"] == "answered");
  record_exercise_answer(s, 0, s1_answer(e));
  const json right = assignment_session_json(s);
  CHECK(right["items"][0]["status"] == "correct");
  CHECK(right["grade"]["raw"] == 2);
  // A slip typed over it ("8x", an empty field) would have made it "answered" with no points.
  const std::string stands = "Your checked answer \"" + s1_answer(e) + "\" stands.";
  for (const char* slip : {"8x", "", "2 pi +"}) {
    CHECK_THROWS_WITH_AS(record_exercise_answer(s, 0, slip), doctest::Contains(stands.c_str()), std::invalid_argument);
    CHECK(assignment_session_json(s) == right);
  }
  // A readable wrong one still replaces it: that is the student's new answer, and a try.
  record_exercise_answer(s, 0, "0.5");
  CHECK(item(0)["status"] == "incorrect");
  CHECK(item(0)["tries"] == 2);
}

TEST_CASE("assignment session: tries are counted, limited, told, saved and resumed") {
  const Assignment two = example(2);
  AssignmentSession s = start_assignment_session(two, "student-7");
  const Exercise e = assignment_exercise(s.assignment, 0, "student-7");
  const auto item = [&](std::size_t i) { return assignment_session_json(s)["items"][i]; };
  CHECK(item(0)["tries"] == 0);
  CHECK(item(0)["tries_allowed"] == 2);
  CHECK(item(0)["tries_left"] == 2);
  CHECK(item(0)["tries_text"] == "Tries: 0 of 2 used.");
  CHECK(item(1)["tries_allowed"].is_null());
  CHECK(item(1)["tries_text"] == "");

  // An answer the lab cannot read costs no try, and says what is left.
  record_exercise_answer(s, 0, "2 pi +");
  CHECK(item(0)["tries"] == 0);
  CHECK(item(0)["feedback"].get<std::string>().find("2 tries left.") != std::string::npos);
  // A wrong answer (P10's is at most pi) costs one; checked again it costs none.
  record_exercise_answer(s, 0, "4");
  CHECK(item(0)["tries"] == 1);
  CHECK(item(0)["feedback"] == "Not right yet. 1 try left.");
  record_exercise_answer(s, 0, " 4 ");
  CHECK(item(0)["tries"] == 1);
  // The last try, right: the answer is final.
  record_exercise_answer(s, 0, s1_answer(e));
  CHECK(item(0)["status"] == "correct");
  CHECK(item(0)["tries"] == 2);
  CHECK(item(0)["tries_left"] == 0);
  CHECK(item(0)["feedback"] == "Right. No tries left: this answer is final.");
  const json before = assignment_session_json(s);
  CHECK_THROWS_WITH_AS(record_exercise_answer(s, 0, "1"), doctest::Contains("no tries left: item 1 allows 2 checks"),
                       std::invalid_argument);
  CHECK_THROWS_AS(record_exercise_answer(s, 0, "x"), std::invalid_argument);  // unreadable or not: final
  CHECK(assignment_session_json(s) == before);
  record_exercise_answer(s, 0, s1_answer(e));  // the recorded answer checked again: nothing to refuse
  CHECK(assignment_session_json(s) == before);

  // A task: each different state checked is a try; the same state again is not.
  record_visit(s, 1);
  record_task_state(s, 2, big_state(true, 80));
  record_task_state(s, 2, big_state(true, 80));
  CHECK(item(2)["tries"] == 1);
  CHECK(item(2)["status"] == "incorrect");
  CHECK(item(2)["feedback"].get<std::string>().rfind("Not yet: ", 0) == 0);  // it may still be checked again
  CHECK(item(2)["feedback"].get<std::string>().find("1 try left.") != std::string::npos);
  record_task_state(s, 2, big_state(false, 70));
  CHECK(item(2)["tries_left"] == 0);
  // Final, not met: "Not done", not "Not yet".
  CHECK(item(2)["feedback"].get<std::string>().rfind("Not done: ", 0) == 0);
  CHECK(item(2)["feedback"].get<std::string>().find("No tries left: this answer is final.") != std::string::npos);
  CHECK_THROWS_WITH_AS(record_task_state(s, 2, big_state(true, 50)), doctest::Contains("no tries left"), std::invalid_argument);
  CHECK(item(2)["status"] == "incorrect");

  // Reported: a reviewer reads the count in the interaction; the grade's reader takes it.
  const json st = assignment_session_json(s);
  CHECK(st["interactions"][0]["description"] == st["items"][0]["title"].get<std::string>() + " (2 tries)");
  CHECK(st["interactions"][1]["description"] == "Look");
  CHECK(st["answers"]["answers"][0]["tries"] == 2);
  CHECK(!st["answers"]["answers"][1].contains("tries"));
  AnswerSheetParse sheet = parse_answer_sheet(st["answers"], s.assignment);
  REQUIRE(sheet.sheet);
  CHECK(assignment_grade_to_json(s.assignment, grade_assignment(s.assignment, *sheet.sheet, "student-7"))["items"][2]["tries"] == 2);

  // Saved and resumed: the count comes back, and the answer stays final.
  CHECK(st["suspend"]["a"][0] == json({0, s1_answer(e), 2}));
  CHECK(st["suspend"]["a"][1] == json({1, 1}));
  AssignmentSession r = start_assignment_session(two, "student-7");
  REQUIRE(resume_session(r, json::parse(st["suspend"].dump())).empty());
  CHECK(assignment_session_json(r) == st);
  CHECK_THROWS_AS(record_exercise_answer(r, 0, "1"), std::invalid_argument);
  // More tries than the item allows (its limit lowered since) resume as used up, the work and
  // the true count kept.
  AssignmentSession r2 = start_assignment_session(two, "student-7");
  REQUIRE(resume_session(r2, json::parse(R"({"v": 1, "c": 0, "s": 0, "a": [[0, "1", 3]]})")).empty());
  CHECK(r2.answers[0]->text == "1");
  CHECK(r2.answers[0]->tries == 3);
  CHECK(tries_left(r2, 0) == 0u);
  CHECK(assignment_session_json(r2)["items"][0]["tries_text"] == "Tries: 3 (2 allowed).");
  CHECK(session_suspend(r2)["a"][0][2] == 3);
  // Saved without a count (from before tries, or the count deleted by hand): one try for each
  // graded answer, none for one the lab cannot read; a bad count is refused whole.
  AssignmentSession r3 = start_assignment_session(two, "student-7");
  REQUIRE(resume_session(r3, json::parse(R"({"v": 1, "c": 0, "s": 0, "a": [[0, "1"], [2, {"solved": false}]]})")).empty());
  CHECK(r3.answers[0]->tries == 1);
  CHECK(r3.answers[2]->tries == 1);
  REQUIRE(resume_session(r3, json::parse(R"({"v": 1, "c": 0, "s": 0, "a": [[0, "((("]]})")).empty());
  CHECK(r3.answers[0]->tries == 0);
  const std::vector<std::string> errors = resume_session(r3, json::parse(R"({"v": 1, "c": 0, "s": 0, "a": [[0, "1", 0]]})"));
  REQUIRE(errors.size() == 1);
  CHECK(errors[0].find("tries: ") != std::string::npos);
  CHECK(r3.answers[0]->text == "(((");

  // Submitted: no item has a try left, and the feedback no longer counts them.
  s.submitted = true;
  const json done = assignment_session_json(s);
  CHECK(done["items"][0]["tries_left"] == 0);
  CHECK(done["items"][2]["tries_left"] == 0);
  CHECK(done["items"][0]["feedback"] == "Right.");
  CHECK(done["items"][1]["tries_left"].is_null());
}

TEST_CASE("assignment session: without a limit every graded check is still counted") {
  AssignmentSession s = start_assignment_session(example(), "student-7");
  record_exercise_answer(s, 0, "1");
  CHECK_THROWS_AS(record_exercise_answer(s, 0, "abc"), std::invalid_argument);  // a slip over it: refused, no try
  record_exercise_answer(s, 0, "2");
  record_exercise_answer(s, 0, "2");
  const json it = assignment_session_json(s)["items"][0];
  CHECK(it["tries"] == 2);
  CHECK(it["tries_left"].is_null());
  CHECK(it["tries_text"] == "Tries: 2.");
  CHECK(it["feedback"].get<std::string>().find("left") == std::string::npos);
  s.submitted = true;
  const json done = assignment_session_json(s)["items"][0];
  CHECK(done["tries_left"] == 0);
  CHECK(done["feedback"] == "Not right.");
}
