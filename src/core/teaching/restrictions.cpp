#include "core/teaching/restrictions.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "core/base/text.hpp"
#include "core/teaching/lesson_catalogue.hpp"

namespace csl {

using json = nlohmann::json;

namespace {

// Each lesson's answers to the homework (README's table: P1-P13), and what an exercise on its
// own would ask. What stays visible is said where it is a choice: pictures that are not numbers
// (the arc on the circle, the cone in sight, the force arrows, the path drawn), and the given
// numbers and the first steps of a method (a ray's slope, a point's clearance check).
const HideableAnswer kAnswers[] = {
      {"path_length", "torus", "the length of the path PRM found on the torus (the path itself is drawn)", {},
       {"/prm/path_length"}},
      {"q_notation",
       "notation",
       "Q of the robot built (or of the practice exercise before it is checked): its notation, dimension, "
       "factors and other spellings",
       {"P1", "P2", "P3", "P4", "P5", "P6", "P7"},
       {"/notation", "/dimension", "/factors", "/equivalent"}},
      {"min_n",
       "collision",
       "the smallest N whose N configurations (p and q counted) see the collision, and the same N counted with "
       "one end or neither",
       {"P12"},
       {"/min_grid", "/min_grid_interior", "/min_grid_one_end"}},
      {"s1_distance",
       "distances",
       "the distance between the two angles on S^1, and the steps that give it away: the difference mod 2 pi, the "
       "other way round, the dot product and its arccos, the case",
       {"P10"},
       {"/s1/modulus", "/s1/other_way", "/s1/modular_distance", "/s1/dot", "/s1/cross", "/s1/arccos_distance",
        "/s1/distance", "/s1/rotation_distance", "/s1/signed_turn", "/s1/wraps_around", "/s1/case"}},
      {"segment_distance",
       "distances",
       "the distance from the segment to the disk, and the steps that give it away: the projection parameter t "
       "(raw and clamped), the closest point, the centre's distance, the case",
       {"P11"},
       {"/segment/length_squared", "/segment/dot", "/segment/t_raw", "/segment/t", "/segment/foot",
        "/segment/closest", "/segment/centre_distance", "/segment/distance", "/segment/signed_distance",
        "/segment/lab_clearance", "/segment/meets", "/segment/case"}},
      {"p8_n",
       "analysis",
       "P8's n: the samples at which the whole-cube bound reaches the target p, as the handout has it and refined",
       {"P8"},
       {"/handout/n_for_target", "/refined/n_for_target"}},
      {"p9_probability",
       "analysis",
       "P9's visibility probability: exact (the areas under the rays, by cases) and its Monte Carlo estimate with "
       "its interval (the region in sight stays drawn)",
       {"P9"},
       {"/visibility/exact", "/visibility/probability", "/visibility/left_area", "/visibility/right_area",
        "/visibility/upper/area_under", "/visibility/lower/area_under", "/visibility/monte_carlo",
        "/visibility/ci_low", "/visibility/ci_high", "/visibility/within_ci"}},
      {"p13_forces",
       "potential",
       "at each control point rho, its gradient, the attractive and repulsive forces, the repulsive potential and "
       "the torque J^T F, and their sums: the numbers of the forces table (the arrows stay drawn)",
       {"P13"},
       {"/control_points/*/rho", "/control_points/*/grad_rho", "/control_points/*/F_att", "/control_points/*/F_rep",
        "/control_points/*/U_rep", "/control_points/*/tau", "/tau", "/F_att", "/F_rep", "/U_rep", "/tau_att",
        "/tau_rep", "/forces_table"}},
      {"path_length", "step-prm", "the length of the path PRM found (the path itself is drawn)", {}, {"/path_length"}},
};

// "a,b" -> {"a", "b"}; "" -> {} (an empty piece between separators is kept: a bad word).
std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(sep, start);
    out.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) break;
    start = at + 1;
  }
  return out;
}
std::vector<std::string> split_words(const std::string& text) { return split(text, ','); }

template <class T>
void add_unique(std::vector<T>& list, const T& value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

std::string quoted(const std::string& word) { return word.empty() ? "an empty word" : "\"" + printable(word, 40) + "\""; }

std::string join(const std::vector<std::string>& words, const char* sep = ", ") {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : sep) + w;
  return out;
}

// The answer names a link to `lesson` may hide ("": any lesson's).
std::vector<std::string> answer_names(const std::string& lesson) {
  std::vector<std::string> out;
  for (const HideableAnswer& a : hideable_answers())
    if (lesson.empty() || a.lesson == lesson) add_unique(out, std::string(a.name));
  return out;
}

std::vector<std::string> param_names(const std::string& lesson) {
  std::vector<std::string> out;
  for (const CataloguedLesson& l : lesson_catalogue())
    if (lesson.empty() || l.id == lesson)
      for (const LessonParam& p : l.params) add_unique(out, std::string(p.name));
  return out;
}

// Erases the field at `path` (split at '/'), from `at` on: "*" walks every element.
void erase_path(json& node, const std::vector<std::string>& path, std::size_t at) {
  if (at >= path.size()) return;
  const std::string& key = path[at];
  if (key == "*") {
    if (node.is_array())
      for (json& element : node) erase_path(element, path, at + 1);
    return;
  }
  if (!node.is_object()) return;
  auto it = node.find(key);
  if (it == node.end()) return;
  if (at + 1 == path.size()) node.erase(it);
  else erase_path(*it, path, at + 1);
}

}  // namespace

const std::vector<HideableAnswer>& hideable_answers() {
  static const std::vector<HideableAnswer> answers(std::begin(kAnswers), std::end(kAnswers));
  return answers;
}

std::vector<const HideableAnswer*> answers_of(const std::string& lesson) {
  std::vector<const HideableAnswer*> out;
  for (const HideableAnswer& a : hideable_answers())
    if (a.lesson == lesson) out.push_back(&a);
  return out;
}

bool Restrictions::param_locked(const std::string& key) const {
  return lock_params || std::find(locked_params.begin(), locked_params.end(), key) != locked_params.end();
}

std::string Restrictions::lock_text() const {
  std::vector<std::string> words;
  if (lock_scene) words.push_back("scene");
  if (lock_params) words.push_back("params");
  if (lock_lesson) words.push_back("lesson");
  if (!lock_params)
    for (const std::string& p : locked_params) words.push_back(p);
  return join(words, ",");
}

std::string Restrictions::hide_text() const {
  if (hide_all) return "answers";
  // In the list's order: the same hide= text for the same answers, whatever order a link gave.
  std::vector<std::string> names;
  for (const HideableAnswer& a : hideable_answers())
    if (hidden.count(std::string(a.name))) add_unique(names, std::string(a.name));
  return join(names, ",");
}

std::string Restrictions::reveal_text() const { return reveal == Reveal::AfterAnswer ? "after-answer" : "never"; }

Restrictions parse_restrictions(const std::string& lock, const std::string& hide, const std::string& reveal,
                                const std::string& lesson, std::vector<std::string>* problems) {
  const auto bad = [&](const std::string& line) {
    if (!problems) throw std::invalid_argument(line);
    problems->push_back(line);
  };
  const std::string of = lesson.empty() ? "any lesson" : lesson;
  Restrictions r;
  const std::vector<std::string> params = param_names(lesson);
  for (const std::string& w : split_words(lock)) {
    if (w == "scene") r.lock_scene = true;
    else if (w == "params") r.lock_params = true;
    else if (w == "lesson") r.lock_lesson = true;
    else if (std::find(params.begin(), params.end(), w) != params.end()) add_unique(r.locked_params, w);
    else
      bad("lock: " + quoted(w) + " is not scene, params, lesson or a parameter of " + of +
          (params.empty() ? "" : " (" + join(params) + ")"));
  }
  if (r.lock_params) r.locked_params.clear();  // all of them

  const std::vector<std::string> answers = answer_names(lesson);
  for (const std::string& w : split_words(hide)) {
    if (w == "answers") {
      r.hide_all = true;
    } else if (w == "none") {
      // nothing: hide=none says so explicitly
    } else if (std::find(answers.begin(), answers.end(), w) != answers.end()) {
      r.hidden.insert(w);
    } else {
      bad("hide: " + quoted(w) + " is not answers, none or an answer of " + of +
          (answers.empty() ? " (it has none to hide)" : " (" + join(answers) + ")"));
    }
  }
  if (r.hide_all)
    for (const HideableAnswer& a : hideable_answers()) r.hidden.emplace(a.name);

  if (reveal == "after-answer") r.reveal = Reveal::AfterAnswer;
  else if (!reveal.empty() && reveal != "never") bad("reveal: " + quoted(reveal) + " is not never or after-answer");
  return r;
}

bool answer_hidden(const Restrictions& r, const HideableAnswer& answer, const std::set<std::string>& solved) {
  if (!r.hidden.count(std::string(answer.name))) return false;
  if (r.reveal == Reveal::AfterAnswer)
    for (const std::string_view p : answer.problems)
      if (solved.count(std::string(p))) return false;
  return true;
}

void strip_answer_fields(json& state, const std::vector<const HideableAnswer*>& answers) {
  for (const HideableAnswer* a : answers)
    for (const std::string_view field : a->fields) {
      std::vector<std::string> path = split(std::string(field), '/');
      if (!path.empty() && path.front().empty()) path.erase(path.begin());  // the pointer's leading "/"
      erase_path(state, path, 0);
    }
}

json restrictions_to_json(const Restrictions& r) {
  return {{"lock", r.lock_text()},
          {"hide", r.hide_text()},
          {"reveal", r.reveal_text()},
          {"scene", r.lock_scene},
          {"params", r.lock_params},
          {"lesson", r.lock_lesson},
          {"locked_params", r.locked_params},
          {"hidden", std::vector<std::string>(r.hidden.begin(), r.hidden.end())}};
}

}  // namespace csl
