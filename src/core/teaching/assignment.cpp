#include "core/teaching/assignment.hpp"

#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "core/base/text.hpp"
#include "core/scene/scene.hpp"
#include "core/teaching/lesson_catalogue.hpp"

namespace csl {

using json = nlohmann::json;

namespace {

std::string shown(const json& v) { return printable(v.dump(), 40); }
bool finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

// UTF-8 characters (code points), as authors count them; a byte that starts no sequence counts
// as one.
std::size_t characters(const std::string& s) {
  std::size_t n = 0;
  for (const char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

// Collects the errors of one place ("items[2] (\"Find a path\")", or "" at the top).
struct Sink {
  std::vector<std::string>& errors;
  std::string where;
  void operator()(const std::string& field, const std::string& what) const {
    errors.push_back((where.empty() ? "" : where + ": ") + field + ": " + what);
  }
};

// A text field: required or not, 1 to `max` characters. Returns it, or "" (error recorded).
std::string text_field(const json& j, const char* key, std::size_t max, bool required, const Sink& error) {
  if (!j.contains(key)) {
    if (required) error(key, "required, a text of 1 to " + std::to_string(max) + " characters");
    return "";
  }
  const json& v = j[key];
  if (!v.is_string()) {
    error(key, "a text of 1 to " + std::to_string(max) + " characters, got " + shown(v));
    return "";
  }
  const std::string s = v.get<std::string>();
  const std::size_t n = characters(s);
  if (n == 0 || n > max) {
    error(key, "a text of 1 to " + std::to_string(max) + " characters, got " + std::to_string(n));
    return "";
  }
  return s;
}

void unknown_fields(const json& j, std::initializer_list<const char*> known, const Sink& error) {
  std::string list;
  for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) error("\"" + printable(it.key(), 40) + "\"", "unknown field (this kind has " + list + ")");
  }
}

// The item's name in messages: its index, and its title if it has a readable one.
std::string item_where(const json& item, std::size_t i) {
  std::string where = "items[" + std::to_string(i) + "]";
  if (item.is_object() && item.contains("title") && item["title"].is_string() && !item["title"].get<std::string>().empty())
    where += " (\"" + printable(item["title"].get<std::string>(), 40) + "\")";
  else if (item.is_object() && item.contains("problem") && item["problem"].is_string())
    where += " (" + printable(item["problem"].get<std::string>(), 16) + ")";
  return where;
}

double points_field(const json& j, double fallback, const Sink& error) {
  if (!j.contains("points")) return fallback;
  const json& v = j["points"];
  if (!finite_number(v) || v.get<double>() < 0 || v.get<double>() > kMaxItemPoints) {
    error("points", "a number in [0, " + significant(kMaxItemPoints, 6) + "], got " + shown(v));
    return fallback;
  }
  return v.get<double>() + 0.0;  // never -0
}

std::optional<unsigned> tries_field(const json& j, const Sink& error) {
  if (!j.contains("tries")) return std::nullopt;
  const json& v = j["tries"];
  if (!v.is_number_integer() || v.get<std::int64_t>() < 1 || v.get<std::int64_t>() > std::int64_t{kMaxItemTries}) {
    error("tries", "how many checks the student has, an integer in [1, " + std::to_string(kMaxItemTries) + "], got " + shown(v));
    return std::nullopt;
  }
  return static_cast<unsigned>(v.get<std::int64_t>());
}

void read_exercise(const json& j, AssignmentItem& item, const Sink& error) {
  unknown_fields(j, {"kind", "title", "problem", "seed", "points", "tolerance", "tries"}, error);
  item.points = points_field(j, 1, error);
  item.tries = tries_field(j, error);
  const HomeworkProblem* problem = nullptr;
  if (!j.contains("problem") || !j["problem"].is_string()) {
    error("problem", "required, a homework problem P1 to P13");
  } else if (!(problem = find_homework_problem(j["problem"].get<std::string>()))) {
    error("problem", "P1 to P13, got " + shown(j["problem"]));
  } else {
    item.problem = problem->id;
  }
  const std::string title = text_field(j, "title", kMaxAssignmentTitle, false, error);
  item.title = !title.empty() ? title : problem ? problem->id + ": " + problem->title : "";
  if (j.contains("seed")) {
    const json& s = j["seed"];
    if (s == "learner") {
      item.seed.reset();
    } else if (s.is_number_integer() && (s.is_number_unsigned() || s.get<std::int64_t>() >= 0) &&
               s.get<std::uint64_t>() <= kMaxExerciseSeed) {  // text gives unsigned, code may give signed
      item.seed = s.get<std::uint64_t>();
    } else {
      error("seed", "an integer in [0, 2^53 - 1] or \"learner\", got " + shown(s));
    }
  }
  if (j.contains("tolerance")) {
    const json& t = j["tolerance"];
    if (!finite_number(t) || t.get<double>() < 0) {
      error("tolerance", "a finite number >= 0, got " + shown(t));
    } else if (problem) {
      // P1-P7 are answered in notation: there is nothing to be within.
      if (make_exercise(problem->id, 0).answer_format == "notation")
        error("tolerance", problem->id + "'s answer is a configuration space in notation: no tolerance applies");
      else
        item.tolerance = t.get<double>() + 0.0;
    }
  }
}

void read_lab_state(const json& j, AssignmentItem& item, const Sink& error) {
  item.title = text_field(j, "title", kMaxAssignmentTitle, true, error);
  item.prompt = text_field(j, "prompt", kMaxAssignmentPrompt, true, error);
  const CataloguedLesson* lesson = nullptr;
  if (!j.contains("lesson") || !j["lesson"].is_string()) {
    error("lesson", "required, one of " + lesson_ids_text());
  } else if (!(lesson = find_catalogued_lesson(j["lesson"].get<std::string>()))) {
    error("lesson", "one of " + lesson_ids_text() + ", got " + shown(j["lesson"]));
  } else {
    item.lesson = std::string(lesson->id);
  }
  if (j.contains("scene")) {
    try {
      if (!j["scene"].is_object()) throw SceneError("a scene (a JSON object, schema v1), got " + shown(j["scene"]));
      const Scene scene = scene_from_json(j["scene"]);
      if (lesson)
        if (std::string p = lesson_scene_problem(*lesson, scene); !p.empty()) throw SceneError(p);
      item.scene = scene_to_json(scene);
    } catch (const SceneError& e) {
      error("scene", printable(e.what(), 300));
    }
  }
  if (j.contains("params")) {
    const json& p = j["params"];
    if (!p.is_object()) {
      error("params", "an object of the lesson's parameters, got " + shown(p));
    } else if (lesson) {
      if (std::string problem = lesson_params_problem(*lesson, p); !problem.empty()) error("params", problem);
      else item.params = p;
    }
  }
}

AssignmentItem read_item(const json& j, std::size_t i, std::vector<std::string>& errors) {
  AssignmentItem item;
  const Sink error{errors, item_where(j, i)};
  if (!j.is_object()) {
    errors.push_back(error.where + ": an item is an object with a \"kind\" (exercise, explore, task), got " + shown(j));
    return item;
  }
  const std::string kind = j.contains("kind") && j["kind"].is_string() ? j["kind"].get<std::string>() : "";
  if (kind == "exercise") {
    item.kind = AssignmentItemKind::Exercise;
    read_exercise(j, item, error);
  } else if (kind == "explore") {
    item.kind = AssignmentItemKind::Explore;
    unknown_fields(j, {"kind", "title", "prompt", "lesson", "scene", "params", "points"}, error);
    read_lab_state(j, item, error);
    item.points = points_field(j, 0, error);
  } else if (kind == "task") {
    item.kind = AssignmentItemKind::Task;
    unknown_fields(j, {"kind", "title", "prompt", "lesson", "scene", "params", "points", "check", "tries"}, error);
    read_lab_state(j, item, error);
    item.points = points_field(j, 1, error);
    item.tries = tries_field(j, error);
    if (!j.contains("check")) {
      error("check", "required: a condition on the lesson's state, e.g. {\"pointer\": \"/solved\", \"equals\": true}");
    } else if (auto c = parse_state_condition(j["check"], error.where + ": check", errors)) {
      item.check = std::move(*c);
    }
  } else {
    error("kind", "exercise, explore or task, got " + (j.contains("kind") ? shown(j["kind"]) : std::string("nothing")));
  }
  return item;
}

// FNV-1a, 64 bits.
struct Fnv {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  void bytes(const std::string& s) {
    for (const char c : s) {
      h ^= static_cast<unsigned char>(c);
      h *= 0x100000001b3ULL;
    }
  }
  // A field with its length first: ("ab", "c") and ("a", "bc") hash apart.
  void field(const std::string& s) {
    bytes(std::to_string(s.size()) + ":");
    bytes(s);
  }
};

std::uint64_t splitmix64_final(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

const char* assignment_item_kind_name(AssignmentItemKind kind) {
  switch (kind) {
    case AssignmentItemKind::Exercise: return "exercise";
    case AssignmentItemKind::Explore: return "explore";
    case AssignmentItemKind::Task: return "task";
  }
  return "exercise";
}

double Assignment::max_points() const {
  double total = 0;
  for (const AssignmentItem& item : items) total += item.points;  // in order: the same sum everywhere
  return total;
}

AssignmentParse parse_assignment(const json& j) {
  AssignmentParse out;
  std::vector<std::string>& errors = out.errors;
  const Sink error{errors, ""};
  if (!j.is_object()) {
    errors.push_back("an assignment is a JSON object {\"format\": \"cspacelab-assignment\", \"version\": 1, ...}, got " + shown(j));
    return out;
  }
  unknown_fields(j, {"format", "version", "title", "description", "pass", "seed_key", "items"}, error);
  if (!j.contains("format") || j["format"] != kAssignmentFormat)
    error("format", std::string("\"") + kAssignmentFormat + "\" (this is not an assignment file?), got " +
                        (j.contains("format") ? shown(j["format"]) : std::string("nothing")));
  if (!j.contains("version") || !j["version"].is_number_integer()) {
    error("version", "required, the integer " + std::to_string(kAssignmentVersion));
  } else if (j["version"] != kAssignmentVersion) {
    error("version", shown(j["version"]) + " is not one this lab reads (" + std::to_string(kAssignmentVersion) + ")");
  }
  Assignment a;
  a.title = text_field(j, "title", kMaxAssignmentTitle, true, error);
  a.description = j.contains("description") ? text_field(j, "description", kMaxAssignmentDescription, false, error) : "";
  a.seed_key = j.contains("seed_key") ? text_field(j, "seed_key", kMaxAssignmentTitle, false, error) : a.title;
  if (j.contains("pass")) {
    const json& p = j["pass"];
    if (!finite_number(p) || p.get<double>() < 0 || p.get<double>() > 1)
      error("pass", "the scaled score that passes, a number in [0, 1], got " + shown(p));
    else
      a.pass = p.get<double>() + 0.0;
  }
  if (!j.contains("items") || !j["items"].is_array() || j["items"].empty() || j["items"].size() > kMaxAssignmentItems) {
    error("items", "a list of 1 to " + std::to_string(kMaxAssignmentItems) + " items" +
                       (j.contains("items") && j["items"].is_array() ? ", got " + std::to_string(j["items"].size()) : ""));
  } else {
    for (std::size_t i = 0; i < j["items"].size(); ++i) a.items.push_back(read_item(j["items"][i], i, errors));
  }
  if (errors.empty()) out.assignment = std::move(a);
  return out;
}

AssignmentParse parse_assignment_text(const std::string& text) {
  if (text.size() > kMaxAssignmentBytes) return {std::nullopt, {"larger than 16 MB, more than any assignment needs"}};
  json j;
  try {
    j = parse_json_text(text);
  } catch (const std::invalid_argument& e) {
    return {std::nullopt, {printable(e.what(), 300)}};
  }
  return parse_assignment(j);
}

std::string learner_id_problem(const std::string& learner) {
  if (learner.size() > kMaxLearnerId) return "a learner id has at most " + std::to_string(kMaxLearnerId) + " bytes";
  return "";
}

std::uint64_t learner_seed(const Assignment& a, std::size_t index, const std::string& learner) {
  Fnv f;
  f.field(a.seed_key);
  f.field(std::to_string(index));
  f.field(index < a.items.size() ? a.items[index].problem : "");
  f.field(learner);
  return splitmix64_final(f.h) & kMaxExerciseSeed;
}

Exercise assignment_exercise(const Assignment& a, std::size_t index, const std::string& learner) {
  const AssignmentItem& item = a.items.at(index);
  if (item.kind != AssignmentItemKind::Exercise) throw std::invalid_argument("item " + std::to_string(index) + " is no exercise");
  Exercise e = make_exercise(item.problem, item.seed ? *item.seed : learner_seed(a, index, learner));
  if (item.tolerance) {
    e.tolerance = *item.tolerance;
    // The assignment's tolerance in the problem's own place in the hint: a student reads one
    // tolerance, the one that counts.
    set_format_hint(e, e.answer_form, significant(*item.tolerance, 6) + " in this assignment", e.hint_note);
  }
  return e;
}

json assignment_to_json(const Assignment& a) {
  json items = json::array();
  for (const AssignmentItem& item : a.items) {
    json j{{"kind", assignment_item_kind_name(item.kind)}, {"title", item.title}, {"points", item.points}};
    if (item.kind == AssignmentItemKind::Exercise) {
      j["problem"] = item.problem;
      j["seed"] = item.seed ? json(*item.seed) : json("learner");
      if (item.tolerance) j["tolerance"] = *item.tolerance;
    } else {
      j["prompt"] = item.prompt;
      j["lesson"] = item.lesson;
      if (!item.scene.is_null()) j["scene"] = item.scene;
      j["params"] = item.params;
      if (item.kind == AssignmentItemKind::Task) j["check"] = state_condition_to_json(item.check);
    }
    if (item.tries) j["tries"] = *item.tries;
    items.push_back(std::move(j));
  }
  json out{{"format", kAssignmentFormat}, {"version", kAssignmentVersion}, {"title", a.title},
           {"seed_key", a.seed_key}, {"pass", a.pass}, {"items", items}};
  if (!a.description.empty()) out["description"] = a.description;
  return out;
}

json assignment_student_view(const Assignment& a, const std::string& learner) {
  json items = json::array();
  for (std::size_t i = 0; i < a.items.size(); ++i) {
    const AssignmentItem& item = a.items[i];
    json j{{"item", i}, {"kind", assignment_item_kind_name(item.kind)}, {"title", item.title}, {"points", item.points}};
    if (item.kind == AssignmentItemKind::Exercise) {
      const Exercise e = assignment_exercise(a, i, learner);
      j["problem"] = item.problem;
      j["seed_from"] = item.seed ? "fixed" : "learner";
      j.update(exercise_to_json(e));  // id, seed, prompt, given, answer_format, format_hint: no answer
    } else {
      j["prompt"] = item.prompt;
      j["lesson"] = item.lesson;
      if (!item.scene.is_null()) j["scene"] = item.scene;
      j["params"] = item.params;
      if (item.kind == AssignmentItemKind::Task) {
        j["check"] = state_condition_to_json(item.check);
        j["check_text"] = state_condition_text(item.check);
      }
    }
    if (item.tries) j["tries"] = *item.tries;
    items.push_back(std::move(j));
  }
  json out{{"title", a.title}, {"pass", a.pass}, {"max_points", a.max_points()}, {"learner", learner}, {"items", items}};
  if (!a.description.empty()) out["description"] = a.description;
  return out;
}

}  // namespace csl
