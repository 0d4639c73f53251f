#include "core/teaching/assignment_grade.hpp"

#include <stdexcept>

#include "core/base/text.hpp"
#include "core/scene/scene.hpp"

namespace csl {

using json = nlohmann::json;

namespace {

std::string shown(const json& v) { return printable(v.dump(), 40); }

// The field an answer to each kind carries.
const char* answer_field(AssignmentItemKind kind) {
  switch (kind) {
    case AssignmentItemKind::Exercise: return "answer";
    case AssignmentItemKind::Explore: return "visited";
    case AssignmentItemKind::Task: return "state";
  }
  return "answer";
}

}  // namespace

AnswerSheetParse parse_answer_sheet(const json& j, const Assignment& a) {
  AnswerSheetParse out;
  std::vector<std::string>& errors = out.errors;
  if (!j.is_object()) {
    errors.push_back("answers are a JSON object {\"answers\": [...]}, got " + shown(j));
    return out;
  }
  AnswerSheet sheet;
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "learner" && it.key() != "answers")
      errors.push_back("\"" + printable(it.key(), 40) + "\": unknown field (learner, answers)");
  if (j.contains("learner")) {
    if (!j["learner"].is_string()) errors.push_back("learner: a learner id (a string), got " + shown(j["learner"]));
    else if (std::string p = learner_id_problem(j["learner"].get<std::string>()); !p.empty()) errors.push_back("learner: " + p);
    else sheet.learner = j["learner"].get<std::string>();
  }
  if (!j.contains("answers") || !j["answers"].is_array()) {
    errors.push_back("answers: required, a list of {\"item\": i, ...}");
    return out;
  }
  const json& list = j["answers"];
  if (list.size() > a.items.size())
    errors.push_back("answers: at most one per item, " + std::to_string(a.items.size()) + ", got " + std::to_string(list.size()));
  std::vector<bool> seen(a.items.size(), false);
  for (std::size_t i = 0; i < list.size() && i <= a.items.size(); ++i) {
    const json& e = list[i];
    const std::string where = "answers[" + std::to_string(i) + "]: ";
    if (!e.is_object()) {
      errors.push_back(where + "an object {\"item\": i, ...}, got " + shown(e));
      continue;
    }
    const bool index = e.contains("item") && e["item"].is_number_integer() &&
                       (e["item"].is_number_unsigned() || e["item"].get<std::int64_t>() >= 0) &&
                       e["item"].get<std::uint64_t>() < a.items.size();
    if (!index) {
      errors.push_back(where + "item: an item's index, 0 to " + std::to_string(a.items.size() - 1) + ", got " +
                       (e.contains("item") ? shown(e["item"]) : std::string("nothing")));
      continue;
    }
    AssignmentAnswer answer;
    answer.item = e["item"].get<std::size_t>();
    if (seen[answer.item]) {
      errors.push_back(where + "item " + std::to_string(answer.item) + " is answered twice");
      continue;
    }
    seen[answer.item] = true;
    const AssignmentItemKind kind = a.items[answer.item].kind;
    const std::string field = answer_field(kind);
    const std::string item_name = "item " + std::to_string(answer.item) + " (" + assignment_item_kind_name(kind) + ")";
    const bool counted = kind != AssignmentItemKind::Explore;  // a visit is no try
    for (auto it = e.begin(); it != e.end(); ++it)
      if (it.key() != "item" && it.key() != field && !(counted && it.key() == "tries"))
        errors.push_back(where + "\"" + printable(it.key(), 40) + "\": " + item_name + " is answered with \"" + field + "\"" +
                         (counted ? " (and \"tries\")" : ""));
    if (counted && e.contains("tries")) {
      // Reported beside the item's own limit, not judged: more than it allows is for the
      // instructor to read, not a reason to grade nothing.
      const json& t = e["tries"];
      constexpr std::uint64_t most = std::uint64_t{1} << 31;
      if (!t.is_number_integer() || t.get<std::int64_t>() < 1 || t.get<std::uint64_t>() > most)
        errors.push_back(where + "tries: how many times it was checked, an integer in [1, " + std::to_string(most) + "], got " +
                         shown(t));
      else
        answer.tries = static_cast<unsigned>(t.get<std::uint64_t>());
    }
    if (!e.contains(field)) {
      errors.push_back(where + field + ": required for " + item_name);
      continue;
    }
    const json& v = e[field];
    if (kind == AssignmentItemKind::Exercise) {
      if (!v.is_string() || v.get<std::string>().size() > kMaxAnswerText)
        errors.push_back(where + "answer: what the student typed, a text of at most " + std::to_string(kMaxAnswerText) +
                         " bytes, got " + (v.is_string() ? std::to_string(v.get<std::string>().size()) + " bytes" : shown(v)));
      else
        answer.text = v.get<std::string>();
    } else if (kind == AssignmentItemKind::Explore) {
      if (!v.is_boolean()) errors.push_back(where + "visited: true or false, got " + shown(v));
      else answer.visited = v.get<bool>();
    } else {
      if (!v.is_object()) errors.push_back(where + "state: the lesson's state, a JSON object, got " + shown(v));
      else answer.state = v;
    }
    sheet.answers.push_back(std::move(answer));
  }
  if (errors.empty()) out.sheet = std::move(sheet);
  return out;
}

AnswerSheetParse parse_answer_sheet_text(const std::string& text, const Assignment& a) {
  if (text.size() > kMaxAssignmentBytes) return {std::nullopt, {"larger than 16 MB, more than any answers need"}};
  json j;
  try {
    j = parse_json_text(text);
  } catch (const std::invalid_argument& e) {
    return {std::nullopt, {printable(e.what(), 300)}};
  }
  return parse_answer_sheet(j, a);
}

AssignmentGrade grade_assignment(const Assignment& a, const AnswerSheet& sheet, const std::string& learner) {
  AssignmentGrade g;
  g.learner = learner;
  std::vector<const AssignmentAnswer*> by_item(a.items.size(), nullptr);
  for (const AssignmentAnswer& ans : sheet.answers)
    if (ans.item < a.items.size()) by_item[ans.item] = &ans;
  g.completed = true;
  for (std::size_t i = 0; i < a.items.size(); ++i) {
    const AssignmentItem& item = a.items[i];
    const AssignmentAnswer* ans = by_item[i];
    ItemGrade r;
    r.item = i;
    r.kind = item.kind;
    r.max_points = item.points;
    r.tries = ans ? ans->tries : 0;
    switch (item.kind) {
      case AssignmentItemKind::Exercise: {
        const Exercise e = assignment_exercise(a, i, learner);
        r.seed = e.seed;
        const ExerciseCheck c = check_exercise(e, ans ? ans->text : "");
        r.expected = c.expected;
        r.attempted = ans && c.readable;
        r.correct = c.correct;
        r.explanation = ans ? c.explanation : "Not answered.";
        break;
      }
      case AssignmentItemKind::Explore:
        r.attempted = r.correct = ans && ans->visited;
        r.explanation = r.correct ? "Visited: the points of this item are for going there."
                                  : "Not visited yet: open it in the lab.";
        break;
      case AssignmentItemKind::Task: {
        r.expected = state_condition_text(item.check);
        if (!ans) {
          r.explanation = "Not submitted.";
          break;
        }
        const ConditionResult c = evaluate_state_condition(item.check, ans->state);
        r.attempted = true;
        r.correct = c.met;
        r.explanation = c.met ? "Done: " : "Not done: ";
        for (std::size_t k = 0; k < c.lines.size(); ++k) r.explanation += (k ? "; " : "") + c.lines[k];
        r.explanation += ".";
        break;
      }
    }
    r.points = r.correct ? item.points : 0.0;
    g.raw += r.points;  // in item order: the same sum in every build
    g.completed = g.completed && r.attempted;
    g.items.push_back(std::move(r));
  }
  g.max = a.max_points();
  g.scaled = g.max > 0 ? g.raw / g.max : (g.completed ? 1.0 : 0.0);
  g.passed = g.scaled >= a.pass;
  return g;
}

json assignment_grade_to_json(const Assignment& a, const AssignmentGrade& g) {
  json items = json::array();
  for (const ItemGrade& r : g.items) {
    json j{{"item", r.item},
           {"kind", assignment_item_kind_name(r.kind)},
           {"title", a.items.at(r.item).title},
           {"attempted", r.attempted},
           {"correct", r.correct},
           {"points", r.points},
           {"max_points", r.max_points},
           {"expected", r.expected},
           {"explanation", r.explanation}};
    if (r.seed) j["seed"] = *r.seed;
    if (r.tries) j["tries"] = r.tries;
    if (const auto allowed = a.items.at(r.item).tries) j["tries_allowed"] = *allowed;
    items.push_back(std::move(j));
  }
  return {{"learner", g.learner},
          {"items", items},
          {"score", {{"raw", g.raw}, {"min", g.min}, {"max", g.max}, {"scaled", g.scaled}}},
          {"completed", g.completed},
          {"passed", g.passed},
          {"pass", a.pass}};
}

}  // namespace csl
