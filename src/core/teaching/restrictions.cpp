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
// own would ask; answer_descriptions.cpp says each in words, and what stays visible where that
// is a choice (pictures that are not numbers, the given numbers, the first steps of a method).
const HideableAnswer kAnswers[] = {
    {"path_length", "torus", {}, {"/prm/path_length"}},
    {"q_notation", "notation", {"P1", "P2", "P3", "P4", "P5", "P6", "P7"},
     {"/notation", "/dimension", "/factors", "/equivalent"}},
    {"min_n", "collision", {"P12"}, {"/min_grid", "/min_grid_interior", "/min_grid_one_end"}},
    {"s1_distance", "distances", {"P10"},
     {"/s1/modulus", "/s1/other_way", "/s1/modular_distance", "/s1/dot", "/s1/cross", "/s1/arccos_distance",
      "/s1/distance", "/s1/rotation_distance", "/s1/signed_turn", "/s1/wraps_around", "/s1/case"}},
    {"segment_distance", "distances", {"P11"},
     {"/segment/length_squared", "/segment/dot", "/segment/t_raw", "/segment/t", "/segment/foot", "/segment/closest",
      "/segment/centre_distance", "/segment/distance", "/segment/signed_distance", "/segment/lab_clearance",
      "/segment/meets", "/segment/case"}},
    {"p8_n", "analysis", {"P8"}, {"/handout/n_for_target", "/refined/n_for_target"}},
    {"p9_probability", "analysis", {"P9"},
     {"/visibility/exact", "/visibility/probability", "/visibility/left_area", "/visibility/right_area",
      "/visibility/upper/area_under", "/visibility/lower/area_under", "/visibility/monte_carlo", "/visibility/ci_low",
      "/visibility/ci_high", "/visibility/within_ci"}},
    {"p13_forces", "potential", {"P13"},
     {"/control_points/*/rho", "/control_points/*/grad_rho", "/control_points/*/F_att", "/control_points/*/F_rep",
      "/control_points/*/U_rep", "/control_points/*/tau", "/tau", "/F_att", "/F_rep", "/U_rep", "/tau_att", "/tau_rep",
      "/forces_table"}},
    {"path_length", "step-prm", {}, {"/path_length"}},
    {"path_length", "compare", {}, {"/planners/*/path_length"}},
    {"path_length", "cspace-3d", {}, {"/prm/path_length"}},
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

bool Restrictions::param_locked(std::string_view key) const {
  return lock_params || std::find(locked_params.begin(), locked_params.end(), key) != locked_params.end();
}

bool Restrictions::hides(std::string_view answer) const {
  return std::find(hidden.begin(), hidden.end(), answer) != hidden.end();
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
    if (hides(a.name)) add_unique(names, std::string(a.name));
  return join(names, ",");
}

std::string Restrictions::reveal_text() const { return reveal == Reveal::AfterAnswer ? "after-answer" : "never"; }

Restrictions parse_restrictions(const std::string& lock, const std::string& hide, const std::string& reveal,
                                const std::string& lesson, std::vector<std::string>* problems) {
  // "KEY: "WORD" is not ALLOWED": thrown, or collected and the word left out.
  const auto bad = [&](const char* key, const std::string& word, const std::string& allowed) {
    std::string line = std::string(key) + ": " + quoted(word) + " is not " + allowed;
    if (!problems) throw std::invalid_argument(line);
    problems->push_back(std::move(line));
  };
  const std::string of = lesson.empty() ? "any lesson" : lesson;
  Restrictions r;
  const std::vector<std::string> params = param_names(lesson);
  for (const std::string& w : split_words(lock)) {
    if (w == "scene") r.lock_scene = true;
    else if (w == "params") r.lock_params = true;
    else if (w == "lesson") r.lock_lesson = true;
    else if (std::find(params.begin(), params.end(), w) != params.end()) add_unique(r.locked_params, w);
    else bad("lock", w, "scene, params, lesson or a parameter of " + of + " (" + join(params) + ")");
  }
  if (r.lock_params) r.locked_params.clear();  // all of them

  const std::vector<std::string> answers = answer_names(lesson);
  for (const std::string& w : split_words(hide)) {
    if (w == "answers") {
      r.hide_all = true;
    } else if (w == "none") {
      // nothing: hide=none says so explicitly
    } else if (std::find(answers.begin(), answers.end(), w) != answers.end()) {
      add_unique(r.hidden, w);
    } else {
      bad("hide", w, "answers, none or an answer of " + of + " (" + join(answers) + ")");
    }
  }
  if (r.hide_all)
    for (const HideableAnswer& a : hideable_answers()) add_unique(r.hidden, std::string(a.name));

  if (reveal == "after-answer") r.reveal = Reveal::AfterAnswer;
  else if (!reveal.empty() && reveal != "never") bad("reveal", reveal, "never or after-answer");
  return r;
}

bool answer_hidden(const Restrictions& r, const HideableAnswer& answer, const std::vector<std::string>& solved) {
  if (!r.hides(answer.name)) return false;
  if (r.reveal == Reveal::AfterAnswer)
    for (const std::string_view p : answer.problems)
      if (std::find(solved.begin(), solved.end(), p) != solved.end()) return false;
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

}  // namespace csl
