#include "core/teaching/homework.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <utility>
#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/base/text.hpp"
#include "core/teaching/notation.hpp"

namespace csl {

using json = nlohmann::json;

const std::vector<HomeworkProblem>& homework_problems() {
  static const std::vector<HomeworkProblem> all = [] {
    const json build = {{"mode", "build"}, {"description", "joints=R"}};
    const std::string notation_task =
        "Build the robot with the controls (base, joints, wrist) and read its Q with the reason for every "
        "factor; then write Q yourself in the exercise below.";
    const std::string figure_task =
        "The handout's robot is in the textbook's figure. Build it here joint by joint (revolute joints turn, "
        "prismatic joints slide) and read its Q; the exercise describes a robot of this size in words.";
    return std::vector<HomeworkProblem>{
        {"P1", "Q of a mobile robot that slides and turns in the plane", "notation", "", build, notation_task},
        {"P2", "Q of a three-link arm (textbook figure)", "notation", "", build, figure_task},
        {"P3", "Q of a two-link arm (textbook figure)", "notation", "", build, figure_task},
        {"P4", "Q of another two-link arm (textbook figure)", "notation", "", build, figure_task},
        {"P5", "Q of another three-link arm (textbook figure)", "notation", "", build, figure_task},
        {"P6", "Q of a six-link arm with a spherical wrist", "notation", "", build, notation_task},
        {"P7", "Q of that arm on a base that slides and turns", "notation", "", build, notation_task},
        {"P8", "Tile all of F = [0,1]^d with balls: the failure bound", "analysis", "", {{"tab", "tiling"}},
         "Compare the bound from tiling one path with the bound from tiling the whole cube: the number of "
         "balls m, the rate sigma r^d, and the samples n each needs for a failure probability you choose."},
        {"P9", "Visibility in the square with a wall and a gap", "analysis", "", {{"tab", "visibility"}},
         "Drag the point in the left half: the lab shades what it sees through the gap, names the case and "
         "puts the numbers into its formula; a Monte Carlo count checks the exact value."},
        {"P10", "Distance between two angles on S^1", "distances", "", {{"tool", "s1"}},
         "Drag the two angles round the circle (or type them): the distance is computed both ways the "
         "handout suggests, by the modulus and by the rotations' dot product, with the shorter arc drawn."},
        {"P11", "Distance from a segment to a disk", "distances", "", {{"tool", "segment"}},
         "Drag p1, p2 and the disk: the lab shows the projection parameter, its clamping to the segment, "
         "the closest point and which special case holds."},
        {"P12", "Collision checking: N points against exact bisection", "collision", "p12", json::object(),
         "The handout's point robot, disk and edge from (0,0) to (1,0): find the smallest N of the "
         "fixed-resolution check that sees the disk, then step the exact check midpoint by midpoint."},
        {"P13", "Potential field at the vertices of a rectangle robot", "potential", "p13", json::object(),
         "The rectangle among two polygons, rho0 chosen so the regions of influence do not overlap: read "
         "rho, grad rho and F_rep at each vertex, their sum, and the force and torque on the robot."},
    };
  }();
  return all;
}

const HomeworkProblem* find_homework_problem(const std::string& id) {
  std::string key = id;
  if (!key.empty() && (key[0] == 'p' || key[0] == 'P')) key = key.substr(1);
  if (key.empty() || key.size() > 2 || !std::isdigit(static_cast<unsigned char>(key[0])) ||
      (key.size() == 2 && !std::isdigit(static_cast<unsigned char>(key[1]))))
    return nullptr;
  for (const HomeworkProblem& p : homework_problems())
    if (p.id == "P" + key) return &p;
  return nullptr;
}

json exercise_to_json(const Exercise& e) {
  return {{"id", e.id},           {"seed", e.seed},
          {"prompt", e.prompt},   {"given", e.given},
          {"answer_format", e.answer_format}, {"format_hint", e.format_hint}};
}

json exercise_check_to_json(const ExerciseCheck& c) {
  return {{"correct", c.correct}, {"expected", c.expected}, {"explanation", c.explanation}, {"feedback", c.feedback}};
}

namespace {

// "pi", "2pi", "2 pi", "2*pi", "0.5pi" -> the factor in front of pi, or nullopt.
std::optional<double> pi_multiple(std::string t) {
  for (const char* name : {"\xCF\x80", "pi", "PI", "Pi"}) {
    const std::string n = name;
    if (t.size() >= n.size() && t.compare(t.size() - n.size(), n.size(), n) == 0) {
      t.erase(t.size() - n.size());
      while (!t.empty() && (t.back() == ' ' || t.back() == '*')) t.pop_back();
      if (t.empty()) return 1.0;
      if (t == "-") return -1.0;
      return parse_decimal(t);
    }
  }
  return std::nullopt;
}

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::optional<double> parse_answer_number(const std::string& text) {
  if (text.size() > 64) return std::nullopt;
  std::string t = trim(text);
  // "2.903 rad": the unit the hints ask for, written out.
  for (const std::string unit : {"radians", "radian", "rad"})
    if (t.size() > unit.size() && t.compare(t.size() - unit.size(), unit.size(), unit) == 0) {
      t = trim(t.substr(0, t.size() - unit.size()));
      break;
    }
  // "2,90": a decimal comma, as much of the world writes it (one comma, no point). Not "6,127",
  // which may be a thousands separator as well (the check's message says how to write it).
  if (const std::size_t comma = t.find(','); comma != std::string::npos && t.find(',', comma + 1) == std::string::npos &&
                                              t.find('.') == std::string::npos) {
    // Ambiguous: 1 to 3 digits (not a leading 0), the comma, 3 digits ("6,127", "0 + 6,127e0").
    const auto digit = [&](std::size_t i) { return i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); };
    std::size_t lead = comma, tail = comma + 1;
    while (lead > 0 && digit(lead - 1)) --lead;
    while (digit(tail)) ++tail;
    const std::size_t before = comma - lead, after = tail - comma - 1;
    if (before >= 1 && before <= 3 && t[lead] != '0' && after == 3)
      return std::nullopt;
    t[comma] = '.';
  }
  if (t.empty()) return std::nullopt;
  // a / b, either side a number or a multiple of pi.
  const auto term = [](const std::string& s) -> std::optional<double> {
    const std::string u = trim(s);
    if (u.empty()) return std::nullopt;
    if (auto k = pi_multiple(u)) return *k * kPi;
    return parse_decimal(u);
  };
  const auto quotient = [&](const std::string& q) -> std::optional<double> {
    if (const std::size_t slash = q.find('/'); slash != std::string::npos) {
      const auto a = term(q.substr(0, slash)), b = term(q.substr(slash + 1));
      if (a && b && *b != 0.0) return *a / *b;
      return std::nullopt;
    }
    return term(q);
  };
  // A sum of those, "2pi - 3.38" or "pi/2 + 0.1": split at a + or - that is not a sign (the
  // first character, or after another operator) nor an exponent's (1e-3).
  double sum = 0.0, sign = 1.0;
  std::size_t from = 0;
  for (std::size_t i = 0; i <= t.size(); ++i) {
    if (i < t.size()) {
      if (t[i] != '+' && t[i] != '-') continue;
      std::size_t k = i;
      while (k > from && t[k - 1] == ' ') --k;
      if (k == from || t[k - 1] == '/' || t[k - 1] == '*') continue;  // a sign ("-1", "1/-2")
      if ((t[k - 1] == 'e' || t[k - 1] == 'E') && k >= 2 && std::isdigit(static_cast<unsigned char>(t[k - 2])) && k == i)
        continue;  // 1e-3
    }
    const auto v = quotient(t.substr(from, i - from));
    if (!v) return std::nullopt;
    sum += sign * *v;
    if (i < t.size()) sign = t[i] == '-' ? -1.0 : 1.0;
    from = i + 1;
  }
  if (!std::isfinite(sum)) return std::nullopt;
  return sum;
}

void set_format_hint(Exercise& e, std::string form, std::string within, std::string note) {
  e.answer_form = std::move(form);
  e.within = std::move(within);
  e.hint_note = std::move(note);
  std::string brackets = e.within.empty() ? "" : "within " + e.within;
  if (!e.hint_note.empty()) brackets += (brackets.empty() ? "" : "; ") + e.hint_note;
  e.format_hint = e.answer_form + (brackets.empty() ? "" : " (" + brackets + ")");
}

std::string exercise_answer_text(const Exercise& e) {
  if (e.answer_format == "notation") return configuration_space(parse_robot_description(e.robot)).notation;
  if (e.answer_format == "integer")  // P8 accepts a band of whole numbers, P12 one in an assignment
    return std::to_string(std::llround(e.answer)) + (e.tolerance >= 1 ? " (within " + number_text(e.tolerance) + ")" : "");
  return number_text(e.answer) + (e.tolerance > 0 ? " (within " + number_text(e.tolerance) + ")" : "");
}

ExerciseCheck check_exercise(const Exercise& e, const std::string& answer) {
  ExerciseCheck c;
  if (e.answer_format == "notation") {
    const RobotDescription robot = parse_robot_description(e.robot);
    const AnswerCheck a = check_answer(answer.substr(0, kMaxNotationText), robot);
    const ConfigSpaceInfo info = configuration_space(robot);
    c.correct = a.correct;
    c.readable = a.readable;
    c.expected = info.notation;
    // Its first line says what is right or wrong (Q itself only in the lines below it), led by a
    // verdict as a number's is: a reader without the card's colours hears which it is.
    std::string first = a.explanation.substr(0, a.explanation.find('\n'));
    const std::string rest = a.explanation.substr(first.size());
    if (a.correct && first.rfind("correct: ", 0) == 0) first = "Right: " + first.substr(9);
    else if (!a.correct && c.readable) first = "Not quite: " + first;
    // An answer the checker could not read is no try: it is told what was unreadable, not Q.
    c.explanation = c.readable ? first + rest + (e.worked.empty() ? "" : "\n" + e.worked) : first;
    // The checker's reasons name the factors it expected ("expected R^3"): a wrong try is told
    // only how its dimension compares.
    const std::string n = std::to_string(info.dimension);
    c.feedback = a.correct || !c.readable ? first
                 : a.dimension != info.dimension
                     ? "Not quite: this robot's Q has dimension " + n + ", yours " + std::to_string(a.dimension) +
                           ": count the numbers that fix a configuration."
                     : "Not quite: the dimension, " + n + ", is right, the kinds of factor are not: which joints "
                       "turn (S^1), which slide (R), and how the base moves.";
    return c;
  }
  const bool integer = e.answer_format == "integer";
  c.expected = integer ? json(static_cast<long long>(std::llround(e.answer))) : json(e.answer);
  const std::optional<double> v = parse_answer_number(answer);
  if (!v) {
    c.readable = false;
    const std::string typed = trim(answer);
    std::string how = e.format_hint + ".";
    if (typed.find(',') != std::string::npos) how += " A decimal point or comma, and no thousands separators: 2.5 or 2,5, 6127.";
    // "166.3°": an angle in degrees, where the answer is in radians.
    for (const std::string deg : {"\xC2\xB0", "degrees", "deg"})
      if (e.format_hint.find("radians") != std::string::npos && typed.size() > deg.size() &&
          typed.compare(typed.size() - deg.size(), deg.size(), deg) == 0) {
        if (const auto d = parse_answer_number(typed.substr(0, typed.size() - deg.size())))
          how = "answers here are in radians: " + number_text(*d) + " degrees is " + number_text(*d * kPi / 180.0) + ".";
        break;
      }
    c.explanation = (typed.empty() ? std::string("Type an answer first: ")
                                   : "\"" + printable(typed, 40) + "\" is not a number the lab can read: ") + how;
    c.feedback = c.explanation;
    return c;
  }
  c.correct = std::fabs(*v - e.answer) <= e.tolerance;
  if (c.correct) {
    c.feedback = "Right: " + number_text(e.answer) + ".";
    c.explanation = c.feedback + "\n" + e.worked;
    return c;
  }
  std::string why;
  for (const Exercise::Trap& t : e.traps)
    if (std::fabs(*v - t.value) <= std::max(e.tolerance, 1e-9 * std::fabs(t.value))) {
      why = t.why;
      break;
    }
  c.explanation = "Not quite: you wrote " + number_text(*v) + ", the answer is " + exercise_answer_text(e) + "." +
                  (why.empty() ? "" : " " + why) + "\n" + e.worked;
  c.feedback = "Not quite: you wrote " + number_text(*v) + "." + (why.empty() ? "" : " " + why);
  c.typical_mistake = !why.empty();
  return c;
}

}  // namespace csl
