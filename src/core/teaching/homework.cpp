#include "core/teaching/homework.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
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
  return {{"correct", c.correct}, {"expected", c.expected}, {"explanation", c.explanation}};
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

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::optional<double> parse_answer_number(const std::string& text) {
  if (text.size() > 64) return std::nullopt;
  const std::string t = trim(text);
  if (t.empty()) return std::nullopt;
  // a / b, either side a number or a multiple of pi.
  const auto term = [](const std::string& s) -> std::optional<double> {
    const std::string u = trim(s);
    if (u.empty()) return std::nullopt;
    if (auto k = pi_multiple(u)) return *k * kPi;
    return parse_decimal(u);
  };
  std::optional<double> v;
  if (const std::size_t slash = t.find('/'); slash != std::string::npos) {
    const auto a = term(t.substr(0, slash)), b = term(t.substr(slash + 1));
    if (a && b && *b != 0.0) v = *a / *b;
  } else {
    v = term(t);
  }
  if (!v || !std::isfinite(*v)) return std::nullopt;
  return v;
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
    c.correct = a.correct;
    c.readable = a.correct || a.explanation.rfind("could not read", 0) != 0;
    c.expected = configuration_space(robot).notation;
    c.explanation = a.explanation + (e.worked.empty() ? "" : "\n" + e.worked);
    return c;
  }
  const bool integer = e.answer_format == "integer";
  c.expected = integer ? json(static_cast<long long>(std::llround(e.answer))) : json(e.answer);
  const std::optional<double> v = parse_answer_number(answer);
  if (!v) {
    c.readable = false;
    c.explanation = (trim(answer).empty() ? std::string("Type an answer first: ")
                                          : "\"" + printable(trim(answer), 40) + "\" is not a number the lab can read: ") +
                    e.format_hint + ".";
    return c;
  }
  c.correct = std::fabs(*v - e.answer) <= e.tolerance;
  if (c.correct) {
    c.explanation = "Right: " + number_text(e.answer) + ".\n" + e.worked;
    return c;
  }
  std::string why;
  for (const Exercise::Trap& t : e.traps)
    if (std::fabs(*v - t.value) <= std::max(e.tolerance, 1e-9 * std::fabs(t.value))) {
      why = t.why;
      break;
    }
  c.explanation = "Not quite: you wrote " + number_text(*v) + ", the answer is " + number_text(e.answer) +
                  (e.tolerance > 0 ? " (within " + number_text(e.tolerance) + ")" : "") + "." +
                  (why.empty() ? "" : " " + why) + "\n" + e.worked;
  return c;
}

}  // namespace csl
