#include "core/teaching/assignment_session.hpp"

#include <stdexcept>

#include "core/base/text.hpp"

namespace csl {

using json = nlohmann::json;

namespace {

const AssignmentItem& item_of(const AssignmentSession& s, std::size_t index, AssignmentItemKind kind) {
  if (s.submitted) throw std::invalid_argument("the assignment was submitted: its answers are final");
  if (index >= s.assignment.items.size())
    throw std::invalid_argument("index: an item's index, 0 to " + std::to_string(s.assignment.items.size() - 1) + ", got " +
                                std::to_string(index));
  const AssignmentItem& item = s.assignment.items[index];
  if (item.kind != kind)
    throw std::invalid_argument("item " + std::to_string(index) + " is an " + assignment_item_kind_name(item.kind) +
                                " item, not an " + assignment_item_kind_name(kind));
  return item;
}

// Records `answer` for its item unless the suspend object would then be too long for SCORM 1.2.
void record(AssignmentSession& s, AssignmentAnswer answer) {
  const std::size_t index = answer.item;
  std::optional<AssignmentAnswer> before = std::move(s.answers[index]);
  s.answers[index] = std::move(answer);
  if (session_suspend(s).dump().size() >= kMaxSuspendChars) {
    s.answers[index] = std::move(before);
    throw std::invalid_argument("this answer is too long to be saved with the others (an LMS keeps " +
                                std::to_string(kMaxSuspendChars) + " characters of them): shorten it");
  }
}

void collect_pointers(const StateCondition& c, std::vector<std::string>& out) {
  if (c.op == StateCondition::Op::Compare) out.push_back(c.pointer);
  for (const StateCondition& t : c.terms) collect_pointers(t, out);
}

// What a reviewer reads of a task's answer: the values its check compared, in words.
std::string task_response(const AssignmentItem& item, const json& state) {
  const ConditionResult r = evaluate_state_condition(item.check, state);
  std::string out;
  for (std::size_t k = 0; k < r.lines.size(); ++k) out += (k ? "; " : "") + r.lines[k];
  return out;
}

json expected_text(const json& expected) { return expected.is_string() ? expected : json(expected.dump()); }

// Refuses a new answer to an item whose tries are used up.
void require_try(const AssignmentSession& s, std::size_t index) {
  const std::optional<unsigned> left = tries_left(s, index);
  if (left && *left == 0)
    throw std::invalid_argument("no tries left: item " + std::to_string(index + 1) + " allows " +
                                std::to_string(*s.assignment.items[index].tries) + " checks, and its answer is final");
}

std::string tries_count(unsigned n) { return std::to_string(n) + (n == 1 ? " try" : " tries"); }

// "Tries: 1 of 3 used." with a limit ("Tries: 3 (2 allowed)." over one lowered since); "Tries:
// 2." without one, once there are any.
std::string tries_text(const AssignmentItem& item, unsigned used) {
  if (item.kind == AssignmentItemKind::Explore) return "";
  if (item.tries && used > *item.tries)
    return "Tries: " + std::to_string(used) + " (" + std::to_string(*item.tries) + " allowed).";
  if (item.tries) return "Tries: " + std::to_string(used) + " of " + std::to_string(*item.tries) + " used.";
  return used ? "Tries: " + std::to_string(used) + "." : "";
}

}  // namespace

AssignmentSession start_assignment_session(Assignment assignment, std::string learner) {
  if (std::string p = learner_id_problem(learner); !p.empty()) throw std::invalid_argument("learner: " + p);
  AssignmentSession s;
  s.answers.resize(assignment.items.size());
  s.assignment = std::move(assignment);
  s.learner = std::move(learner);
  return s;
}

void record_exercise_answer(AssignmentSession& s, std::size_t index, const std::string& text) {
  item_of(s, index, AssignmentItemKind::Exercise);
  if (text.size() > kMaxAnswerText)
    throw std::invalid_argument("answer: at most " + std::to_string(kMaxAnswerText) + " characters");
  const std::optional<AssignmentAnswer>& before = s.answers[index];
  if (before && trim(before->text) == trim(text)) return;  // the recorded answer checked again: no new try
  require_try(s, index);
  const Exercise exercise = assignment_exercise(s.assignment, index, s.learner);
  const ExerciseCheck check = check_exercise(exercise, text);
  // An answer the lab cannot read (a typo, an empty field) is told so and costs no try. Over a
  // graded answer it is refused, so that a slip does not take the graded one (and its points)
  // off the record: the card's note says why, and the field keeps the slip to correct.
  if (!check.readable && before && check_exercise(exercise, before->text).readable)
    throw std::invalid_argument(check.feedback + " Your checked answer \"" + before->text + "\" stands.");
  AssignmentAnswer a;
  a.item = index;
  a.text = text;
  a.tries = (before ? before->tries : 0) + (check.readable ? 1 : 0);
  record(s, std::move(a));
}

void record_visit(AssignmentSession& s, std::size_t index) {
  item_of(s, index, AssignmentItemKind::Explore);
  AssignmentAnswer a;
  a.item = index;
  a.visited = true;
  record(s, std::move(a));
}

void record_task_state(AssignmentSession& s, std::size_t index, const json& state) {
  const AssignmentItem& item = item_of(s, index, AssignmentItemKind::Task);
  json excerpt = task_state_excerpt(item.check, state);
  const std::optional<AssignmentAnswer>& before = s.answers[index];
  if (before && before->state == excerpt) return;  // the lab as it was checked: no new try
  require_try(s, index);
  AssignmentAnswer a;
  a.item = index;
  a.state = std::move(excerpt);
  a.tries = (before ? before->tries : 0) + 1;
  record(s, std::move(a));
}

json task_state_excerpt(const StateCondition& condition, const json& state) {
  std::vector<std::string> pointers;
  collect_pointers(condition, pointers);
  json out = json::object();
  // Scalars first: a larger value's stand-in ({} or []) never overwrites what is under it.
  for (const bool scalars : {true, false}) {
    for (const std::string& p : pointers) {
      try {
        const json::json_pointer ptr(p);
        if (p.empty() || !state.contains(ptr)) continue;  // the whole state: no comparison takes it
        const json& v = state.at(ptr);
        if (v.is_structured() == scalars) continue;
        if (scalars) out[ptr] = v;
        else if (!out.contains(ptr)) out[ptr] = v.is_array() ? json::array() : json::object();
      } catch (const json::exception&) {
        // A pointer nlohmann cannot follow here (an array index "01"): not in the excerpt, as
        // it is not in the state for the condition either.
      }
    }
  }
  // The excerpt must judge as the state does; where it might not (a pointer through an array
  // the excerpt rebuilt with nulls), the whole state is kept instead.
  if (evaluate_state_condition(condition, out).met != evaluate_state_condition(condition, state).met) return state;
  return out;
}

AnswerSheet session_answer_sheet(const AssignmentSession& s) {
  AnswerSheet sheet;
  sheet.learner = s.learner;
  for (const auto& a : s.answers)
    if (a) sheet.answers.push_back(*a);
  return sheet;
}

AssignmentGrade grade_session(const AssignmentSession& s) {
  return grade_assignment(s.assignment, session_answer_sheet(s), s.learner);
}

std::optional<unsigned> tries_left(const AssignmentSession& s, std::size_t index) {
  const AssignmentItem& item = s.assignment.items.at(index);
  if (s.submitted && item.kind != AssignmentItemKind::Explore) return 0;  // every answer final
  const std::optional<unsigned> allowed = item.tries;
  if (!allowed) return std::nullopt;
  const unsigned used = s.answers[index] ? s.answers[index]->tries : 0;
  return used < *allowed ? *allowed - used : 0;
}

const char* item_status(const AssignmentSession& s, const ItemGrade& g) {
  if (!s.answers.at(g.item)) return "open";
  if (g.kind == AssignmentItemKind::Explore) return g.correct ? "viewed" : "open";
  if (!g.attempted) return "answered";
  return g.correct ? "correct" : "incorrect";
}

json session_suspend(const AssignmentSession& s) {
  json answers = json::array();
  for (const auto& a : s.answers) {
    if (!a) continue;
    json e;
    switch (s.assignment.items[a->item].kind) {
      case AssignmentItemKind::Exercise: e = {a->item, a->text}; break;
      case AssignmentItemKind::Explore: e = {a->item, 1}; break;
      case AssignmentItemKind::Task: e = {a->item, a->state}; break;
    }
    if (a->tries) e.push_back(a->tries);
    answers.push_back(std::move(e));
  }
  return {{"v", 1}, {"c", s.current}, {"s", s.submitted ? 1 : 0}, {"a", answers}};
}

std::vector<std::string> resume_session(AssignmentSession& s, const json& suspend) {
  std::vector<std::string> errors;
  const auto error = [&](const std::string& what) { errors.push_back("resume: " + what); };
  if (!suspend.is_object()) {
    error("the \"suspend\" object of an earlier assignment_state, got " + printable(suspend.dump(), 40));
    return errors;
  }
  for (auto it = suspend.begin(); it != suspend.end(); ++it)
    if (it.key() != "v" && it.key() != "c" && it.key() != "s" && it.key() != "a")
      error("\"" + printable(it.key(), 40) + "\": unknown field (v, c, s, a)");
  if (suspend.value("v", json()) != 1) error("v: 1, the version of the suspend object");
  const std::size_t n = s.assignment.items.size();
  const json c = suspend.value("c", json());
  if (!c.is_number_unsigned() || c.get<std::size_t>() >= n)
    error("c: the current item, 0 to " + std::to_string(n - 1));
  const json sub = suspend.value("s", json());
  if (sub != 0 && sub != 1) error("s: 0 or 1 (submitted)");
  // The answers through the grade's own reader: the same checks as an answers file gets.
  const json list = suspend.value("a", json());
  json sheet{{"answers", json::array()}};
  if (!list.is_array()) {
    error("a: a list of [item, answer]");
  } else {
    for (std::size_t k = 0; k < list.size(); ++k) {
      const json& e = list[k];
      if (!e.is_array() || e.size() < 2 || e.size() > 3 || !e[0].is_number_unsigned() || e[0].get<std::size_t>() >= n) {
        error("a[" + std::to_string(k) + "]: [item, answer] or [item, answer, tries] with an item 0 to " + std::to_string(n - 1));
        continue;
      }
      const std::size_t item = e[0].get<std::size_t>();
      const AssignmentItemKind kind = s.assignment.items[item].kind;
      json answer{{"item", item}};
      if (kind == AssignmentItemKind::Exercise) answer["answer"] = e[1];
      else if (kind == AssignmentItemKind::Explore) answer["visited"] = e[1] == 1 ? json(true) : e[1];
      else answer["state"] = e[1];
      if (e.size() == 3) answer["tries"] = e[2];  // checked by the reader: an integer >= 1
      sheet["answers"].push_back(std::move(answer));
    }
  }
  AnswerSheetParse parsed = parse_answer_sheet(sheet, s.assignment);
  for (const std::string& e : parsed.errors) error(e);
  if (!errors.empty()) return errors;
  std::vector<std::optional<AssignmentAnswer>> answers(n);
  for (AssignmentAnswer& a : parsed.sheet->answers) {
    const AssignmentItem& item = s.assignment.items[a.item];
    if (item.kind == AssignmentItemKind::Explore && !a.visited) continue;
    // Saved without a count (a suspend object from before tries, or one edited by hand): one try
    // for an answer that was graded, never none, so that deleting the count does not give back
    // every try.
    if (item.kind != AssignmentItemKind::Explore && a.tries == 0)
      a.tries = item.kind == AssignmentItemKind::Task ||
                check_exercise(assignment_exercise(s.assignment, a.item, s.learner), a.text).readable;
    // More than the item allows (the instructor lowered its "tries") is kept as counted: the
    // answer is final (tries_left() is 0), the work kept rather than the resume refused, and the
    // count an LMS holds stays the true one.
    answers[a.item] = std::move(a);
  }
  s.answers = std::move(answers);
  s.current = c.get<std::size_t>();
  s.submitted = sub == 1;
  return errors;
}

json assignment_session_json(const AssignmentSession& s) {
  const Assignment& a = s.assignment;
  const AssignmentGrade g = grade_session(s);
  json items = json::array(), interactions = json::array(), answers = json::array();
  for (std::size_t i = 0; i < a.items.size(); ++i) {
    const AssignmentItem& item = a.items[i];
    const ItemGrade& r = g.items[i];
    const std::optional<AssignmentAnswer>& ans = s.answers[i];
    const std::string id = "item-" + std::to_string(i + 1);
    const unsigned used = ans ? ans->tries : 0;
    const std::optional<unsigned> left = tries_left(s, i);
    const bool final_answer = left && *left == 0;
    json j{{"index", i}, {"id", id}, {"kind", assignment_item_kind_name(item.kind)}, {"title", item.title},
           {"points", item.points}, {"status", item_status(s, r)}, {"score", r.points}, {"max", r.max_points},
           {"tries", used}, {"tries_allowed", item.tries ? json(*item.tries) : json(nullptr)},
           {"tries_left", left ? json(*left) : json(nullptr)}, {"tries_text", tries_text(item, used)}};
    // SCORM keeps no count of tries: a reviewer reads it in the description (2004).
    json interaction{{"id", id}, {"description", item.title + (used ? " (" + tries_count(used) + ")" : "")},
                     {"weighting", item.points}, {"result", !r.attempted ? "neutral" : r.correct ? "correct" : "incorrect"}};
    std::string feedback;
    switch (item.kind) {
      case AssignmentItemKind::Exercise: {
        const Exercise e = assignment_exercise(a, i, s.learner);
        j["problem"] = item.problem;
        j["prompt"] = e.prompt;
        j["format_hint"] = e.format_hint;
        j["seed"] = e.seed;
        j["answer"] = ans ? json(ans->text) : json(nullptr);
        interaction["type"] = e.answer_format == "notation" ? "fill-in" : "numeric";
        interaction["learner_response"] = ans ? ans->text : "";
        if (s.submitted) interaction["correct_response"] = expected_text(r.expected);
        if (s.submitted) j["expected_text"] = exercise_answer_text(e);
        // Before submission: right or not, and why an answer could not be read; never the answer.
        if (ans) feedback = r.correct ? "Right." : r.attempted ? (final_answer ? "Not right." : "Not right yet.") : r.explanation;
        if (ans) answers.push_back({{"item", i}, {"answer", ans->text}});
        break;
      }
      case AssignmentItemKind::Explore:
        j["prompt"] = item.prompt;
        j["lesson"] = item.lesson;
        j["answer"] = ans ? json(true) : json(nullptr);
        interaction["type"] = "other";
        interaction["learner_response"] = ans ? "visited" : "";
        if (s.submitted) interaction["correct_response"] = "visited";
        if (ans) feedback = "Visited.";
        if (ans) answers.push_back({{"item", i}, {"visited", true}});
        break;
      case AssignmentItemKind::Task:
        j["prompt"] = item.prompt;
        j["lesson"] = item.lesson;
        j["check_text"] = state_condition_text(item.check);
        j["answer"] = ans ? ans->state : json(nullptr);
        interaction["type"] = "other";
        interaction["learner_response"] = ans ? task_response(item, ans->state) : "";
        if (s.submitted) interaction["correct_response"] = r.expected;
        if (ans) feedback = r.explanation;  // the student was told the condition: no secret in it
        if (ans) answers.push_back({{"item", i}, {"state", ans->state}});
        break;
    }
    if (used) answers.back()["tries"] = used;
    // With a limit, what is left is part of the answer's feedback: "Not right yet." has a "yet".
    // A task's grade says "Not done: " (a grade is of a final answer); while it can still be
    // checked again, "Not yet: ".
    if (item.kind == AssignmentItemKind::Task && !final_answer && feedback.rfind("Not done: ", 0) == 0)
      feedback.replace(0, 10, "Not yet: ");
    if (item.tries && ans && !s.submitted)
      feedback += final_answer ? " No tries left: this answer is final." : " " + tries_count(*left) + " left.";
    j["feedback"] = feedback;
    if (s.submitted) {
      j["expected"] = r.expected;
      j["explanation"] = r.explanation;  // an exercise's worked solution
    }
    items.push_back(std::move(j));
    interactions.push_back(std::move(interaction));
  }
  json out{{"title", a.title},
           {"description", a.description},
           {"learner", s.learner},
           {"pass", a.pass},
           {"current", s.current},
           {"submitted", s.submitted},
           {"items", items},
           {"grade", {{"raw", g.raw}, {"min", g.min}, {"max", g.max}, {"scaled", g.scaled}, {"completed", g.completed},
                      {"passed", g.passed}}},
           {"interactions", interactions},
           {"answers", {{"learner", s.learner}, {"answers", answers}}},
           {"suspend", session_suspend(s)}};
  return out;
}

}  // namespace csl
