// cspacelab assignment validate|grade|exercises: an instructor's assignment file checked, a
// student's answers graded, and what a student's page shows, with the core's
// core/teaching/assignment.hpp and assignment_grade.hpp (the page grades with the same code).
#include "cli/commands.hpp"
#include "core/base/text.hpp"
#include "core/teaching/assignment.hpp"
#include "core/teaching/assignment_grade.hpp"

namespace csl::cli {
namespace {

using json = nlohmann::json;

// Every error on one line: "PATH: 3 problems: a; b; c".
std::string joined(const std::string& path, const std::vector<std::string>& errors) {
  std::string out = path + ": " + (errors.size() == 1 ? "" : std::to_string(errors.size()) + " problems: ");
  for (std::size_t i = 0; i < errors.size(); ++i) out += (i ? "; " : "") + errors[i];
  return out;
}

Assignment load_assignment(const std::string& path) {
  AssignmentParse parsed = parse_assignment_text(read_file(path));
  if (!parsed.assignment) throw UsageError(joined(path, parsed.errors));
  return std::move(*parsed.assignment);
}

std::string take_learner(Args& args) {
  const auto learner = args.take("learner");
  if (!learner) return "";
  if (std::string p = learner_id_problem(*learner); !p.empty()) throw UsageError("--learner: " + p);
  return *learner;
}

int run_validate(Args& args, std::ostream& os) {
  const std::string path = args.take_positional("the assignment file");
  args.finish();
  const AssignmentParse parsed = parse_assignment_text(read_file(path));
  // Every problem, on the one line of an error (exit status 2 leaves stdout empty, as for
  // every command): an author fixes them all in one round.
  if (!parsed.assignment) throw UsageError(joined(path, parsed.errors));
  const Assignment& a = *parsed.assignment;
  json kinds{{"exercise", 0}, {"explore", 0}, {"task", 0}};
  for (const AssignmentItem& item : a.items) kinds[assignment_item_kind_name(item.kind)] = kinds[assignment_item_kind_name(item.kind)].get<int>() + 1;
  print_json(os, {{"valid", true},
                  {"title", a.title},
                  {"items", a.items.size()},
                  {"kinds", kinds},
                  {"max_points", a.max_points()},
                  {"pass", a.pass},
                  {"assignment", assignment_to_json(a)}});
  return 0;
}

int run_grade(Args& args, std::ostream& os) {
  const auto answers_path = args.take("answers");
  const auto learner_option = args.take("learner");
  const std::string path = args.take_positional("the assignment file");
  args.finish();
  if (!answers_path) throw UsageError("--answers FILE is required (the student's answers)");
  if (learner_option)
    if (std::string p = learner_id_problem(*learner_option); !p.empty()) throw UsageError("--learner: " + p);
  const Assignment a = load_assignment(path);
  AnswerSheetParse parsed = parse_answer_sheet_text(read_file(*answers_path), a);
  if (!parsed.sheet) throw UsageError(joined(*answers_path, parsed.errors));
  const AnswerSheet& sheet = *parsed.sheet;
  // Two different ids would grade one student's answers with another's numbers.
  if (learner_option && sheet.learner && *sheet.learner != *learner_option)
    throw UsageError("--learner '" + printable(*learner_option, 40) + "' and the answers' learner '" +
                     printable(*sheet.learner, 40) + "' differ");
  const std::string learner = learner_option ? *learner_option : sheet.learner.value_or("");
  print_json(os, assignment_grade_to_json(a, grade_assignment(a, sheet, learner)));
  return 0;
}

int run_exercises(Args& args, std::ostream& os) {
  const std::string learner = take_learner(args);
  const std::string path = args.take_positional("the assignment file");
  args.finish();
  print_json(os, assignment_student_view(load_assignment(path), learner));
  return 0;
}

int run_assignment(Args& args, std::ostream& os) {
  const std::string sub = args.take_positional("a subcommand: validate, grade or exercises");
  if (sub == "validate") return run_validate(args, os);
  if (sub == "grade") return run_grade(args, os);
  if (sub == "exercises") return run_exercises(args, os);
  throw UsageError("unknown subcommand '" + printable(sub, 40) + "' (validate, grade, exercises)");
}

}  // namespace

const Command kAssignmentCommand{
    "assignment", "check an assignment file, grade answers, show a learner's exercises",
    "Usage: cspacelab assignment validate FILE\n"
    "       cspacelab assignment grade FILE --answers ANSWERS [--learner ID]\n"
    "       cspacelab assignment exercises FILE [--learner ID]\n\n"
    "An assignment is a JSON file an instructor writes (example: docs/assignment-example.json):\n"
    "  {\"format\": \"cspacelab-assignment\", \"version\": 1,\n"
    "   \"title\": \"Week 3\",          required, 1 to 200 characters\n"
    "   \"description\": \"...\",       optional, at most 4000 characters\n"
    "   \"pass\": 0.6,                optional: the scaled score that passes, in [0, 1], default 0.6\n"
    "   \"seed_key\": \"week3\",        optional: what per-learner seeds derive from, default the\n"
    "                               title (keep it when you edit the title: students keep their numbers)\n"
    "   \"items\": [ITEM, ...]}       1 to 100 items\n"
    "Every item may have \"title\" (1 to 200 characters) and \"points\" (a number in [0, 1000]);\n"
    "an exercise or a task \"tries\": how many times the student may check it in the page, an\n"
    "integer in [1, 100] (default: any number). Every check the page can grade is counted either\n"
    "way (an unreadable answer, or the answer last recorded checked again, is not); used up, the\n"
    "answer is final. An unreadable answer never replaces a readable one on the record. The\n"
    "page keeps the limit: a student who edits the page's saved data can\n"
    "undo it. In an LMS the record is SCORM's: each check adds an interaction of its own\n"
    "(item-K-try-N, with its answer, result and time) that later checks leave as it was, and\n"
    "SCORM 2004 reports the count in each item's interaction description.\n"
    "ITEM is one of\n"
    "  {\"kind\": \"exercise\", \"problem\": \"P10\", \"seed\": 7, \"points\": 2, \"tolerance\": 0.01}\n"
    "      a homework exercise (cspacelab exercise P10). seed: an integer in [0, 2^53 - 1], the\n"
    "      same numbers for everyone, or \"learner\" (the default): each learner their own, the\n"
    "      same on every reload. tolerance: accepted |typed - answer|, a finite number >= 0, for\n"
    "      P8-P13 only (P1-P7 are answered in notation); default the exercise's own. Title default:\n"
    "      the problem's. Points default 1.\n"
    "  {\"kind\": \"explore\", \"title\": \"...\", \"prompt\": \"...\", \"lesson\": \"step-prm\",\n"
    "   \"scene\": {...}, \"params\": {...}, \"points\": 0}\n"
    "      a lab state to look at: lesson (cspacelab link --list names them), an optional scene\n"
    "      (schema v1, inline: cspacelab help validate; no bundled names) and parameters, checked\n"
    "      as a link's are. The points are for visiting it. Title and prompt (1 to 2000\n"
    "      characters) required. Points default 0.\n"
    "  {\"kind\": \"task\", \"title\": \"...\", \"prompt\": \"...\", \"lesson\": \"step-prm\",\n"
    "   \"scene\": {...}, \"params\": {...}, \"points\": 1, \"check\": CONDITION, \"tries\": 5}\n"
    "      done when the lesson's state (cspacelab.state() in the page) meets CONDITION when the\n"
    "      student checks the lab (Check my lab records that state). Title and prompt required.\n"
    "      Points default 1. A hidden answer\n"
    "      (hide=) is not in the state: a check on its field fails.\n"
    "CONDITION is one of\n"
    "  {\"pointer\": \"/solved\", \"equals\": true}     the value there is this string, number,\n"
    "                                             true, false or null\n"
    "  {\"pointer\": \"/nodes\", \"min\": 10, \"max\": 50} a number in [min, max] (either may be left out)\n"
    "  {\"all\": [CONDITION, ...]}                  every one holds (1 to 20 of them)\n"
    "  {\"any\": [CONDITION, ...]}                  at least one holds (at most 4 levels of all/any)\n"
    "  The pointer is a JSON pointer (RFC 6901) into the state; a value missing there fails.\n"
    "  Step PRM's state has e.g. /solved, /nodes, /edges, /components, /path_length and\n"
    "  /params/samples: \"a path with at most 50 samples\" is\n"
    "  {\"all\": [{\"pointer\": \"/solved\", \"equals\": true}, {\"pointer\": \"/params/samples\", \"max\": 50}]}.\n"
    "Unknown fields are errors. Per-learner seeds: FNV-1a of seed_key, the item's index and\n"
    "problem and the learner id, mixed by splitmix64, cut to 53 bits. Without a learner id the\n"
    "id is \"\": everyone without one gets the same numbers.\n\n"
    "validate FILE prints {\"valid\": true, \"title\", \"items\": N, \"kinds\": {exercise, explore,\n"
    "  task}, \"max_points\", \"pass\", \"assignment\": {...normalised, defaults filled in...}}.\n"
    "  An invalid file is one line on stderr with every problem found, each naming the item and\n"
    "  the field, e.g. FILE: 2 problems: items[2] (\"Find a path\"): points: a number in [0, 1000],\n"
    "  got -1; items[4] (P10): seed: ... Exit status 2, nothing on stdout. grade and exercises\n"
    "  refuse an invalid file the same way.\n"
    "exercises FILE [--learner ID] prints what the student's page shows: {\"title\", \"pass\",\n"
    "  \"max_points\", \"learner\", \"items\": [{item, kind, title, points, ...}]}: an exercise with\n"
    "  problem, seed_from (fixed or learner), seed, prompt, given, answer_format, format_hint (no\n"
    "  answer); explore and task items with prompt, lesson, scene?, params; a task with its check\n"
    "  and check_text (the condition in words).\n"
    "grade FILE --answers ANSWERS [--learner ID] grades a student's answers:\n"
    "  ANSWERS: {\"learner\": ID (optional), \"answers\": [{\"item\": 0, \"answer\": \"pi/2\"},\n"
    "            {\"item\": 1, \"visited\": true}, {\"item\": 2, \"state\": {...the lesson's state...}}]}\n"
    "  an exercise is answered with what the student typed, an explore item with visited, a\n"
    "  task with the state; each item at most once. An exercise's or task's answer may add\n"
    "  \"tries\": N >= 1 (the page's count, in its assignment_state's answers): reported beside\n"
    "  the item's own limit, not graded. --learner and the file's learner must agree where\n"
    "  both are given. Prints {\"learner\", \"items\": [{item, kind, title, attempted, correct,\n"
    "  points, max_points, expected, explanation, seed?, tries?, tries_allowed?}],\n"
    "  \"score\": {raw, min, max, scaled}, \"completed\", \"passed\", \"pass\"}: an item earns all\n"
    "  its points when correct; raw is their sum, min 0, max the sum of the items' points,\n"
    "  scaled = raw / max (with max 0: 1 once completed); completed: every item attempted (an\n"
    "  unreadable answer is not an attempt); passed: scaled >= pass. Wrong answers are not\n"
    "  errors: exit status 0.\n"
    "Files are strict JSON of at most 16 MB; a learner id has at most 4000 bytes.\n",
    run_assignment};

}  // namespace csl::cli
