#include "core/teaching/volume_questions.hpp"

#include <cmath>
#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/base/text.hpp"
#include "core/checking/scene_text.hpp"
#include "core/robots/robot.hpp"
#include "core/teaching/notation.hpp"

namespace csl {

namespace {

bool is_arm(const Scene& scene) { return std::holds_alternative<ArmRobot>(scene.robot); }

void require_lesson_robot(const Scene& scene) {
  const auto* a = std::get_if<ArmRobot>(&scene.robot);
  if (!std::holds_alternative<PolygonRobot>(scene.robot) && !(a && a->links() == 3))
    throw std::invalid_argument("the 3-D questions are about a polygon robot or a 3-link arm");
}

Space space_of(const Scene& scene) { return robot_space(scene.robot, scene.workspace_min, scene.workspace_max); }

// The robot as the notation lesson describes it: a polygon slides and turns in the plane; the arm
// is bolted down with revolute joints.
RobotDescription description_of(const Scene& scene) {
  RobotDescription d;
  if (is_arm(scene)) d.joints = std::string(static_cast<std::size_t>(std::get<ArmRobot>(scene.robot).links()), 'R');
  else d.base = RobotDescription::Base::PlanarMobile;
  return d;
}

// The coordinate of the block's vertical axis, the one the lesson's plane cuts.
int cut_axis(const Scene& scene) { return is_arm(scene) ? 0 : 2; }

int glued_pairs(const Space& space) {
  int n = 0;
  for (int i = 0; i < space.dim(); ++i) n += space.coordinate(i).angular;
  return n;
}

// Whether the short way from p to q leaves the block through a glued face: along some angle,
// p's angle plus the short difference passes +-pi.
bool crosses_seam(const Space& space, const Config& p, const Config& q) {
  const Config d = space.difference(p, q);
  for (int i = 0; i < space.dim(); ++i) {
    if (!space.coordinate(i).angular) continue;
    const double end = wrap_angle(p[i]) + d[i];
    if (end > kPi || end < -kPi) return true;
  }
  return false;
}

std::string angle_name(const Scene& scene) { return is_arm(scene) ? "θ₁" : "θ"; }

const char* const kGluedKeys[] = {"none", "top-bottom", "sides", "all"};

ExerciseCheck unreadable(const std::string& why) {
  ExerciseCheck c;
  c.readable = false;
  c.explanation = why;
  return c;
}

}  // namespace

const std::vector<std::string>& volume_question_ids() {
  static const std::vector<std::string> ids = {"name", "dimension", "glued", "seam", "free"};
  return ids;
}

std::vector<Config> seam_question_configs(const Scene& scene) {
  require_lesson_robot(scene);
  std::vector<Config> out(3, scene.start);
  const int axis = cut_axis(scene);
  out[0][axis] = 2.8;
  out[1][axis] = -2.9;
  out[2][axis] = 0.5;
  return out;
}

VolumeQuestion volume_question(const std::string& id, const Scene& scene) {
  require_lesson_robot(scene);
  VolumeQuestion q;
  q.id = id;
  const bool arm = is_arm(scene);
  const std::string robot = arm ? "the 3-link arm" : "the polygon robot";
  if (id == "name") {
    q.prompt = "Which space is Q for " + robot + "? Write it in the course's notation.";
    q.answer_format = "notation";
    q.format_hint = "powers with ^, products with x";
  } else if (id == "dimension") {
    q.prompt = "How many numbers fix a configuration of " + robot + " (the dimension of Q)?";
    q.answer_format = "integer";
    q.format_hint = "a whole number";
  } else if (id == "glued") {
    q.prompt = "Which faces of the block are glued (a path leaving through one comes back through its twin)?";
    q.answer_format = "choice";
    q.choices = {{kGluedKeys[0], "none: every face is a wall"},
                 {kGluedKeys[1], "one pair: the top and the bottom"},
                 {kGluedKeys[2], "two pairs: the four sides"},
                 {kGluedKeys[3], "all three pairs"}};
  } else if (id == "seam") {
    const std::vector<Config> c = seam_question_configs(scene);
    q.prompt = "A = " + config_text(c[0]) + ", B = " + config_text(c[1]) + ", C = " + config_text(c[2]) +
               " (" + (arm ? "θ₁, θ₂, θ₃" : "x, y, θ") + "). The short straight way from A to which of them leaves "
               "the block through a glued face?";
    q.answer_format = "choice";
    q.choices = {{"B", "B"}, {"C", "C"}, {"both", "both"}, {"neither", "neither"}};
  } else if (id == "free") {
    q.prompt = "What percentage of Q is free of collisions in this scene (at the lab's resolution)?";
    q.answer_format = "number";
    q.format_hint = "a percentage, e.g. 42.5; within 0.5";
  } else {
    throw std::invalid_argument("unknown question \"" + printable(id, 40) + "\" (name, dimension, glued, seam, free)");
  }
  return q;
}

ExerciseCheck check_volume_question(const std::string& id, const Scene& scene, double free_fraction,
                                    const std::string& answer) {
  const VolumeQuestion q = volume_question(id, scene);  // throws for an unknown id
  const Space space = space_of(scene);
  const std::string text = trim(answer);
  if (text.empty()) return unreadable("write an answer first");
  ExerciseCheck c;
  if (id == "name") {
    const RobotDescription robot = description_of(scene);
    const AnswerCheck a = check_answer(text, robot);
    c.correct = a.correct;
    c.readable = a.readable;  // "((" is no attempt at a name, as an unreadable number is none
    c.expected = configuration_space(robot).notation;
    c.explanation = a.explanation;
    // The lesson says "not an answer: " before an unreadable one: not "could not read" twice.
    constexpr std::string_view kUnread = "could not read the answer: ";
    if (!a.readable && c.explanation.rfind(kUnread, 0) == 0) c.explanation.erase(0, kUnread.size());
    return c;
  }
  if (id == "dimension") {
    const std::optional<double> n = parse_answer_number(text);
    if (!n || *n != std::floor(*n)) return unreadable("\"" + printable(text, 40) + "\" is not a whole number");
    c.expected = space.dim();
    c.correct = *n == static_cast<double>(space.dim());  // a double: 1e300 typed is no int
    c.explanation = (c.correct ? "Right: " : "No: ") + std::to_string(space.dim()) + " numbers, " +
                    (is_arm(scene) ? "one angle per joint (θ₁, θ₂, θ₃)" : "where it is (x, y) and how it is turned (θ)") +
                    "; the block has one axis for each.";
    return c;
  }
  if (id == "glued" || id == "seam") {
    bool known = false;
    for (const auto& choice : q.choices) known = known || choice.first == text;
    if (!known) return unreadable("\"" + printable(text, 40) + "\" is not one of the choices");
  }
  if (id == "glued") {
    const int pairs = glued_pairs(space);
    const std::string key = kGluedKeys[pairs];
    c.expected = key;
    c.correct = text == key;
    c.explanation = std::string(c.correct ? "Right: " : "No: ") +
                    (is_arm(scene) ? "all three coordinates are angles, and an angle of π is the angle -π, so every "
                                     "face is glued to the opposite one (T³)."
                                   : "only θ is an angle: θ = π is θ = -π, so the top and the bottom are glued; x and "
                                     "y end at the walls of the workspace.");
    return c;
  }
  if (id == "seam") {
    const std::vector<Config> p = seam_question_configs(scene);
    const bool b = crosses_seam(space, p[0], p[1]), cc = crosses_seam(space, p[0], p[2]);
    const std::string key = b && cc ? "both" : b ? "B" : cc ? "C" : "neither";
    const int axis = cut_axis(scene);
    const auto way = [&](const Config& to) {
      return significant(space.difference(p[0], to)[axis], 3);
    };
    c.expected = key;
    c.correct = text == key;
    c.explanation = std::string(c.correct ? "Right: " : "No: ") + "the short way turns " + angle_name(scene) + " by " +
                    way(p[1]) + " to B and " + way(p[2]) + " to C; from " + angle_name(scene) + " = 2.8 a turn past π (" +
                    significant(kPi, 4) + ") leaves through the " + (is_arm(scene) ? "face" : "top") +
                    " and comes back through its twin.";
    return c;
  }
  // "free": a percentage (a trailing % is fine)
  std::string number = text;
  if (!number.empty() && number.back() == '%') number = trim(number.substr(0, number.size() - 1));
  const std::optional<double> v = parse_answer_number(number);
  if (!v) return unreadable("\"" + printable(text, 40) + "\" is not a number");
  const double want = 100.0 * free_fraction;
  c.expected = std::round(want * 10) / 10;
  c.correct = std::fabs(*v - want) <= 0.5;
  c.explanation = std::string(c.correct ? "Right: " : "No: ") + significant(want, 3) + "% of the cells are free";
  if (!c.correct && std::fabs(100.0 * *v - want) <= 0.5) c.explanation += " (you wrote it as a fraction, not a percentage)";
  c.explanation += ", counted at the centres of the panel's cells.";
  return c;
}

}  // namespace csl
