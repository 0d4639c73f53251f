// cspacelab homework / exercise: the handout's problems P1-P13 and their seeded exercises, the
// same JSON the lab's homework map and its JS API give (core/teaching/homework.hpp).
#include <stdexcept>

#include "cli/commands.hpp"
#include "core/base/text.hpp"
#include "core/teaching/homework.hpp"

namespace csl::cli {
namespace {

using json = nlohmann::json;

int run_homework(Args& args, std::ostream& os) {
  args.finish();
  json out = json::array();
  for (const HomeworkProblem& p : homework_problems())
    out.push_back({{"id", p.id}, {"title", p.title}, {"lesson", p.lesson}, {"task", p.task}});
  print_json(os, out);
  return 0;
}

int run_exercise(Args& args, std::ostream& os) {
  const auto seed_text = args.take("seed");
  const auto answer = args.take("check");
  const std::string id = args.take_positional("ID (P1 to P13)");
  args.finish();
  const std::uint64_t seed =
      seed_text ? static_cast<std::uint64_t>(parse_count(*seed_text, "--seed", static_cast<long long>(kMaxExerciseSeed))) : 1;
  if (!find_homework_problem(id)) throw UsageError("no problem '" + printable(id, 20) + "' (P1 to P13, see cspacelab homework)");
  const Exercise e = make_exercise(id, seed);
  json out = exercise_to_json(e);
  if (answer) out.update(exercise_check_to_json(check_exercise(e, *answer)));
  print_json(os, out);
  return 0;
}

}  // namespace

const Command kHomeworkCommand{
    "homework", "the handout's problems P1-P13: where the lab shows each",
    "Usage: cspacelab homework\n\n"
    "Prints the homework's thirteen problems, in order:\n"
    "  [{\"id\": \"P1\", \"title\": \"...\", \"lesson\": \"notation\", \"task\": \"...\"}, ...]\n"
    "  id      P1 ... P13, as the handout numbers them\n"
    "  title   one line on what the problem asks\n"
    "  lesson  the lab's lesson that shows it (the page opens it with ?problem=P10)\n"
    "  task    what to try in that lesson\n"
    "Each problem has a checked exercise: cspacelab exercise ID.\n",
    run_homework};

const Command kExerciseCommand{
    "exercise", "a problem's exercise with its own numbers; --check ANSWER checks one",
    "Usage: cspacelab exercise ID [--seed S] [--check ANSWER]\n\n"
    "ID: P1 ... P13 (also p10 or 10). S: an integer in [0, 2^53 - 1], default 1; the same ID\n"
    "and seed give the same exercise here and in the lab (cspacelab.exercise(ID, S)).\n\n"
    "Prints {\"id\", \"seed\", \"prompt\", \"given\", \"answer_format\", \"format_hint\"}:\n"
    "  given          the numbers by the handout's names: P8 {d, r, p}, P9 {x, y, d},\n"
    "                 P10 {q1, q2} (radians), P11 {p1, p2, q, r}, P12 {p, q, center, radius},\n"
    "                 P13 {vertices, center, obstacle, rho0, eta, quantity, vertex?};\n"
    "                 P1-P7 {robot}: the robot in words (P2-P5 describe a robot like the\n"
    "                 textbook figure's)\n"
    "  answer_format  \"number\", \"integer\" or \"notation\" (Q in the course's notation)\n"
    "  format_hint    how to write the answer, and the tolerance\n"
    "No answer is printed. --check ANSWER (what a student types: a number, also pi/2 or\n"
    "3pi/4; an integer; or Q such as SE(2) x T^3, R^2 \xC3\x97 S^1, R\xC2\xB2) adds\n"
    "  \"correct\": bool, \"expected\": the answer (number, integer or Q),\n"
    "  \"explanation\": why, with the worked solution,\n"
    "  \"feedback\": what the lab's card tells a wrong try: what went wrong, not the answer\n"
    "  (for a right or unreadable answer, the explanation's first line).\n"
    "A wrong answer is not an error: exit status 0.\n",
    run_exercise};

}  // namespace csl::cli
