// What a link may lock and hide (core/teaching/restrictions.hpp) and the lessons it checks the
// words against (core/teaching/lesson_catalogue.hpp): the words read, a bad word named with the
// words allowed, the canonical text Share writes, a lesson's answers stripped from its state.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene/scene.hpp"
#include "core/teaching/answer_descriptions.hpp"
#include "core/teaching/homework.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/teaching/lesson_catalogue.hpp"
#include "core/teaching/restrictions.hpp"

using json = nlohmann::json;

namespace {
std::string error_of(const std::string& lock, const std::string& hide, const std::string& reveal, const std::string& lesson) {
  try {
    csl::parse_restrictions(lock, hide, reveal, lesson);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("lock words: scene, params, lesson and the lesson's own parameters") {
  const csl::Restrictions r = csl::parse_restrictions("scene,grid_n", "", "", "collision");
  CHECK(r.lock_scene);
  CHECK_FALSE(r.lock_params);
  CHECK_FALSE(r.lock_lesson);
  CHECK(r.locked_params == std::vector<std::string>{"grid_n"});
  CHECK(r.param_locked("grid_n"));
  CHECK_FALSE(r.param_locked("p"));
  CHECK(r.lock_text() == "scene,grid_n");
  CHECK(r.any_lock());

  const csl::Restrictions all = csl::parse_restrictions("params,lesson,grid_n,params", "", "", "collision");
  CHECK(all.lock_params);
  CHECK(all.lock_lesson);
  CHECK(all.param_locked("anything"));
  CHECK(all.lock_text() == "params,lesson");  // grid_n is in params already

  CHECK(csl::parse_restrictions("", "", "", "collision").empty());
  CHECK(csl::parse_restrictions("", "", "", "collision").lock_text().empty());
}

TEST_CASE("a bad word is named, with the words allowed; collected, the rest applies") {
  CHECK(error_of("scene,grid", "", "", "collision") ==
        "lock: \"grid\" is not scene, params, lesson or a parameter of collision (grid_n, p, q)");
  CHECK(error_of("samples", "", "", "collision").find("\"samples\" is not") != std::string::npos);
  CHECK(error_of("samples", "", "", "step-prm").empty());  // a parameter of that lesson
  CHECK(error_of("scene,", "", "", "collision") ==
        "lock: an empty word is not scene, params, lesson or a parameter of collision (grid_n, p, q)");
  CHECK(error_of("", "min_n,path_length", "", "collision") ==
        "hide: \"path_length\" is not answers, none or an answer of collision (min_n)");
  CHECK(error_of("", "min_n", "", "distances").find("(s1_distance, segment_distance)") != std::string::npos);
  CHECK(error_of("", "", "later", "collision") == "reveal: \"later\" is not never or after-answer");
  // Any lesson (no lesson given): any lesson's words.
  CHECK(error_of("samples,grid_n", "min_n,path_length", "after-answer", "").empty());
  // A quoted word is printable, whatever it holds.
  CHECK(error_of("a\nb", "", "", "collision").find("\"a\\nb\"") != std::string::npos);

  std::vector<std::string> problems;
  const csl::Restrictions r = csl::parse_restrictions("scene,bogus,params", "min_n,x", "soon", "collision", &problems);
  REQUIRE(problems.size() == 3);
  CHECK(problems[0].rfind("lock: \"bogus\"", 0) == 0);
  CHECK(problems[1].rfind("hide: \"x\"", 0) == 0);
  CHECK(problems[2].rfind("reveal: \"soon\"", 0) == 0);
  CHECK(r.lock_scene);
  CHECK(r.lock_params);
  CHECK(r.hidden == std::vector<std::string>{"min_n"});
  CHECK(r.reveal == csl::Reveal::Never);
}

TEST_CASE("hide=answers hides every lesson's answers; hide=none nothing; the text is canonical") {
  const csl::Restrictions all = csl::parse_restrictions("", "answers", "after-answer", "collision");
  CHECK(all.hide_all);
  for (const csl::HideableAnswer& a : csl::hideable_answers()) CHECK(all.hides(a.name));
  CHECK(all.hidden.size() == 8);  // path_length once, for the torus and Step PRM
  CHECK(all.hide_text() == "answers");
  CHECK(all.reveal_text() == "after-answer");
  CHECK(csl::parse_restrictions("", "none", "", "collision").hidden.empty());
  // Listed in the catalogue's order, each once, whatever order the link gave.
  const csl::Restrictions two = csl::parse_restrictions("", "p9_probability,p8_n,p8_n", "never", "analysis");
  CHECK(two.hide_text() == "p8_n,p9_probability");
  CHECK(two.reveal == csl::Reveal::Never);
}

TEST_CASE("every answer belongs to a catalogued lesson, answers a real problem, and names state fields") {
  std::set<std::string> lessons_with_answers;
  for (const csl::HideableAnswer& a : csl::hideable_answers()) {
    CAPTURE(a.name);
    REQUIRE(csl::find_catalogued_lesson(std::string(a.lesson)) != nullptr);
    lessons_with_answers.emplace(a.lesson);
    CHECK(csl::answer_description(a.lesson, a.name).size() > 20);
    CHECK(a.fields.size() > 0);
    for (const std::string_view f : a.fields) CHECK(f.rfind("/", 0) == 0);
    for (const std::string_view p : a.problems) {
      const csl::HomeworkProblem* problem = csl::find_homework_problem(std::string(p));
      REQUIRE(problem != nullptr);
      CHECK(problem->lesson == a.lesson);  // revealed by an exercise of its own lesson
    }
  }
  // Every lesson has something to hide (the torus and Step PRM: their path's length).
  for (const csl::CataloguedLesson& l : csl::lesson_catalogue()) CHECK(lessons_with_answers.count(std::string(l.id)) == 1);
  // Every homework problem is answered by some lesson's hidden answer.
  for (const csl::HomeworkProblem& p : csl::homework_problems()) {
    bool covered = false;
    for (const csl::HideableAnswer& a : csl::hideable_answers())
      for (const std::string_view id : a.problems) covered = covered || id == p.id;
    CHECK_MESSAGE(covered, p.id);
  }
}

TEST_CASE("reveal=after-answer brings an answer back once one of its problems was answered right") {
  const csl::HideableAnswer* min_n = csl::answers_of("collision").at(0);
  const csl::Restrictions never = csl::parse_restrictions("", "min_n", "never", "collision");
  const csl::Restrictions after = csl::parse_restrictions("", "min_n", "after-answer", "collision");
  CHECK(csl::answer_hidden(never, *min_n, {}));
  CHECK(csl::answer_hidden(never, *min_n, {"P12"}));
  CHECK(csl::answer_hidden(after, *min_n, {"P10"}));
  CHECK_FALSE(csl::answer_hidden(after, *min_n, {"P12"}));
  // An answer no problem asks for stays hidden.
  const csl::HideableAnswer* length = csl::answers_of("step-prm").at(0);
  const csl::Restrictions prm = csl::parse_restrictions("", "answers", "after-answer", "step-prm");
  CHECK(csl::answer_hidden(prm, *length, {"P1", "P2", "P8", "P9", "P10", "P11", "P12", "P13"}));
  CHECK_FALSE(csl::answer_hidden(csl::Restrictions{}, *length, {}));
}

TEST_CASE("strip_answer_fields removes the answers' fields, in arrays too, and leaves the rest") {
  json state = {{"grid_n", 4}, {"min_grid", 5}, {"min_grid_interior", 7}, {"shown", 0}};
  csl::strip_answer_fields(state, csl::answers_of("collision"));
  CHECK(state == json{{"grid_n", 4}, {"shown", 0}});

  json potential = {{"control_points", json::array({{{"name", "v1"}, {"rho", 0.2}, {"F_rep", {1, 2}}},
                                                    {{"name", "v2"}, {"rho", nullptr}}})},
                    {"tau", {0.1, 0.2, 0.3}},
                    {"U", 1.5},
                    {"forces_table", {{"rows", json::array()}}}};
  csl::strip_answer_fields(potential, csl::answers_of("potential"));
  CHECK(potential == json{{"control_points", json::array({{{"name", "v1"}}, {{"name", "v2"}}})}, {"U", 1.5}});

  json analysis = {{"handout", nullptr}, {"visibility", {{"x", 0.25}, {"exact", 0.6}, {"upper", {{"slope", 1}, {"area_under", 0.1}}}}}};
  csl::strip_answer_fields(analysis, csl::answers_of("analysis"));  // a null handout: nothing there to strip
  CHECK(analysis == json{{"handout", nullptr}, {"visibility", {{"x", 0.25}, {"upper", {{"slope", 1}}}}}});
}

TEST_CASE("the catalogue: lessons, their parameters checked as a link would set them") {
  CHECK(csl::lesson_ids_text() == "torus, notation, cspace-3d, collision, compare, distances, analysis, potential, step-prm");
  const csl::CataloguedLesson* c = csl::find_catalogued_lesson("collision");
  REQUIRE(c);
  CHECK(c->name == "Collision checking");
  CHECK(csl::find_catalogued_lesson("Collision") == nullptr);
  CHECK(csl::lesson_params_problem(*c, json{{"grid_n", 9}, {"p", {0.2, 0.3}}}).empty());
  CHECK(csl::lesson_params_problem(*c, json{{"grid_n", 1}}) == "grid_n: an integer in [2, 100000]");
  CHECK(csl::lesson_params_problem(*c, json{{"grid_n", 4.5}}) == "grid_n: an integer in [2, 100000]");
  CHECK(csl::lesson_params_problem(*c, json{{"p", {1}}}) == "p: [a, b], two numbers");
  CHECK(csl::lesson_params_problem(*c, json{{"seed", 1}}) == "\"seed\" is not a parameter of collision (grid_n, p, q)");
  CHECK(csl::lesson_params_problem(*c, json::array()) == "the parameters must be a JSON object");

  const csl::CataloguedLesson* prm = csl::find_catalogued_lesson("step-prm");
  REQUIRE(prm);
  CHECK(csl::lesson_params_problem(*prm, json{{"samples", 120}, {"neighbors", "k:8"}, {"checker", "grid:5"}, {"seed", 7}}).empty());
  CHECK(csl::lesson_params_problem(*prm, json{{"samples", 20001}}) == "samples: an integer in [0, 20000] in the lab");
  CHECK(csl::lesson_params_problem(*prm, json{{"neighbors", "k8"}}).rfind("neighbors: ", 0) == 0);
  CHECK(csl::lesson_params_problem(*prm, json{{"checker", "step:0.0001"}}) == "checker: D must be at least 0.001 in the lab");
  CHECK(csl::lesson_params_problem(*prm, json{{"seed", -1}}) == "seed: an integer >= 0");
  // The samplers as the CLI spells them, sigma within the lab's [0.001, 1].
  for (const char* ok : {"uniform", "halton", "gaussian:0.05", "bridge:0.001", "bridge:1"})
    CHECK(csl::lesson_params_problem(*prm, json{{"sampler", ok}}).empty());
  CHECK(csl::lesson_params_problem(*prm, json{{"sampler", "bridge:1.5"}}) == "sampler: sigma: a number in [0.001, 1] in the lab");
  CHECK(csl::lesson_params_problem(*prm, json{{"sampler", "gaussian:0.0009"}}) ==
        "sampler: sigma: a number in [0.001, 1] in the lab");
  CHECK(csl::lesson_params_problem(*prm, json{{"sampler", "bridge:0"}}).rfind("sampler: sampler 'bridge:0': sigma", 0) == 0);
  CHECK(csl::lesson_params_problem(*prm, json{{"sampler", "sobol"}}).rfind("sampler: unknown sampler 'sobol'", 0) == 0);
  CHECK(csl::lesson_params_problem(*prm, json{{"sampler", 3}}) == "sampler: a string");

  const csl::CataloguedLesson* analysis = csl::find_catalogued_lesson("analysis");
  REQUIRE(analysis);
  CHECK(csl::lesson_params_problem(*analysis, json{{"tab", "visibility"}, {"gap", 0.2}, {"sample_counts", {20, 50}}}).empty());
  CHECK(csl::lesson_params_problem(*analysis, json{{"tab", "cube"}}) == "tab: one of bound, tiling, visibility");
  CHECK(csl::lesson_params_problem(*analysis, json{{"gap", 2}}) == "gap: a number in [0, 1]");
  CHECK(csl::lesson_params_problem(*analysis, json{{"sample_counts", json::array()}}).rfind("sample_counts: 1 to 20 integers", 0) == 0);

  // Compare planners: its planners are the planner choice's, whatever its table lists.
  const csl::CataloguedLesson* compare = csl::find_catalogued_lesson("compare");
  REQUIRE(compare);
  for (const csl::PlannerKindInfo& k : csl::planner_kinds())
    CHECK(csl::lesson_params_problem(*compare, json{{"planner_a", k.name}, {"planner_b", k.name}}).empty());
  CHECK(csl::lesson_params_problem(*compare, json{{"planner_b", "rrt*"}}) ==
        "planner_b: unknown planner 'rrt*' (" + csl::planner_names(", ") + ")");
  CHECK(csl::lesson_params_problem(*compare, json{{"passage", 0.6}}) == "passage: a number in [0, 0.5]");
  CHECK(csl::lesson_params_problem(*compare, json{{"budgets", {10, 20, 30, 40, 50, 60, 70}}}).rfind("budgets: 1 to 6 integers", 0) == 0);
  CHECK(csl::lesson_params_problem(*compare, json{{"samples_a", 300}, {"goal_bias_a", 0.1}, {"mode", "experiment"}}).empty());

  const csl::CataloguedLesson* notation = csl::find_catalogued_lesson("notation");
  REQUIRE(notation);
  CHECK(csl::lesson_params_problem(*notation, json{{"description", "base=planar joints=RR"}}).empty());
  CHECK(csl::lesson_params_problem(*notation, json{{"description", "joints=RX"}}).rfind("description: ", 0) == 0);
}

TEST_CASE("the catalogue: the scenes a lesson takes") {
  const csl::Scene point = csl::scene_from_string(
      R"({"version": 1, "workspace": {"min": [0, 0], "max": [1, 1]}, "robot": {"type": "point"},)"
      R"( "obstacles": [], "start": [0.1, 0.1], "goal": [0.9, 0.9]})");
  CHECK(csl::lesson_scene_problem(*csl::find_catalogued_lesson("step-prm"), point).empty());
  CHECK(csl::lesson_scene_problem(*csl::find_catalogued_lesson("torus"), point) ==
        "the torus lesson takes scenes with robot arm2; this one has 'point'");
  CHECK(csl::lesson_scene_problem(*csl::find_catalogued_lesson("distances"), point) == "the distances lesson has no scene");
}
