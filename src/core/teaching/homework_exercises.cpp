// The exercises of homework.hpp, one generator per problem: numbers drawn from the seed, the
// answer from the lab's core functions, the worked solution and the typical wrong answers.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/base/rng.hpp"
#include "core/checking/collision.hpp"
#include "core/checking/edge_check.hpp"
#include "core/fields/potential.hpp"
#include "core/geometry/geometry.hpp"
#include "core/scene/scene.hpp"
#include "core/teaching/analysis.hpp"
#include "core/teaching/homework.hpp"
#include "core/teaching/notation.hpp"

namespace csl {

using json = nlohmann::json;

namespace {

// What the student reads is exactly what is computed with: two decimals (+ 0.0: never -0.00).
double round2(double v) { return std::round(v * 100.0) / 100.0 + 0.0; }
double draw2(Rng& rng, double lo, double hi) { return round2(rng.uniform(lo, hi)); }
// x before y: the order of a constructor's arguments is unspecified (GCC and Clang differ), and
// the CLI and the browser must draw the same numbers.
Vec2 draw_point(Rng& rng, double lo, double hi) {
  const double x = draw2(rng, lo, hi);
  const double y = draw2(rng, lo, hi);
  return Vec2(x, y);
}

std::string num(double v, int decimals = 2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}
std::string sig(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", std::fabs(v) < 1e-12 ? 0.0 : v);  // no 2.776e-15 for a zero
  return buf;
}
// p and eta as written: 0.001, not 1e-03.
std::string number_text_exact(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}
std::string point_text(const Vec2& p) { return "(" + num(p.x()) + ", " + num(p.y()) + ")"; }
json point_json(const Vec2& p) { return json::array({round2(p.x()), round2(p.y())}); }  // all given on the 0.01 grid

template <std::size_t N>
const char* pick(Rng& rng, const char* const (&options)[N]) {
  return options[rng.below(N)];
}

// ---- P1-P7: C-space notation -------------------------------------------------------------

// Its examples are no exercise's answer.
const char* const kNotationHint = "Q in the course's notation, e.g. SE(3) x T^2 or R^3 x (S^1)^4 (x or \xC3\x97, ^ or superscripts)";

Exercise notation_exercise(const std::string& id, const std::string& text, const std::string& robot) {
  Exercise e;
  e.prompt = text + " Write its configuration space Q.";
  e.given = {{"robot", text}};
  e.answer_format = "notation";
  set_format_hint(e, kNotationHint, "");
  e.robot = robot;
  const ConfigSpaceInfo info = configuration_space(parse_robot_description(robot));
  std::string worked = "Q = " + info.notation + ", dimension " + std::to_string(info.dimension) + ":";
  for (const NotationFactor& f : info.factors) worked += "\n - " + f.reason;
  e.worked = worked;
  (void)id;
  return e;
}

std::string joint_words(const std::string& joints) {
  std::string out;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    out += i == 0 ? "" : ", then ";
    out += joints[i] == 'R' ? "revolute" : "prismatic";
  }
  return out;
}

Exercise arm_exercise(const std::string& id, Rng& rng, int links) {
  std::string joints;
  for (int i = 0; i < links; ++i) joints += rng.below(3) == 0 ? 'P' : 'R';
  const std::string text = "An arm bolted to the floor with " + std::to_string(links) + " links; its joints, from the base: " +
                           joint_words(joints) + " (revolute joints turn, prismatic joints slide).";
  return notation_exercise(id, text, "joints=" + joints);
}

Exercise p1(Rng& rng) {
  static const char* const kRobots[] = {
      "A robot vacuum cleaner: it drives anywhere on the floor and turns on the spot.",
      "A warehouse robot on omnidirectional wheels: it slides over the floor in any direction and turns.",
      "A puck on an air-hockey table that can also spin about its centre.",
      "A lawn-mowing robot, seen from above: it moves over the flat lawn and turns."};
  return notation_exercise("P1", pick(rng, kRobots), "base=planar");
}

Exercise p6(Rng& rng) {
  static const char* const kMounts[] = {"bolted to the floor", "hanging from the ceiling", "bolted to a workbench"};
  return notation_exercise("P6",
                           std::string("A six-link arm ") + pick(rng, kMounts) +
                               ": three revolute joints (waist, shoulder, elbow), then a spherical wrist whose "
                               "three revolute joints turn the hand about axes meeting in one point.",
                           "joints=RRR wrist=spherical");
}

Exercise p7(Rng& rng) {
  static const char* const kBases[] = {"a mobile base that drives and turns on a flat floor",
                                       "a cart that slides in any direction over the floor and turns"};
  return notation_exercise("P7",
                           std::string("The six-link arm with a spherical wrist (three revolute joints, then the "
                                       "wrist's three) mounted on ") +
                               pick(rng, kBases) + ".",
                           "base=planar joints=RRR wrist=spherical");
}

// ---- P8: tiling all of [0,1]^d -----------------------------------------------------------

Exercise p8(Rng& rng) {
  static const double kTargets[] = {0.1, 0.05, 0.01, 0.001};
  const int d = 2 + static_cast<int>(rng.below(2));
  const double r = draw2(rng, 0.05, 0.25);
  const double p = kTargets[rng.below(4)];
  const double per_axis = std::ceil(std::max(2.0, std::sqrt(static_cast<double>(d))) / r);
  const double m = std::pow(per_axis, d);
  const double sigma = unit_ball_volume(d) / std::pow(2.0, d);
  const double rate = sigma * std::pow(r, d);
  const double n = std::ceil(std::log(m / p) / rate);
  Exercise e;
  e.prompt = "F = [0,1]^" + std::to_string(d) + ", clearance r = " + num(r) +
             ". Tile all of F with balls of radius r/2 centred on a grid of N points per axis, N = ceil(max(2, "
             "sqrt(d)) / r), so that neighbouring centres are at most r/2 apart and the balls cover F. Using the "
             "handout's bound with m balls, m e^(-sigma r^d n), how many samples n make it at most p = " +
             number_text_exact(p) + "?";
  e.given = {{"d", d}, {"r", r}, {"p", p}};
  e.answer_format = "integer";
  set_format_hint(e, "a whole number of samples", "0.5%");
  e.answer = n;
  e.tolerance = std::max(1.0, std::floor(0.005 * n));
  e.worked = "N = ceil(" + num(std::max(2.0, std::sqrt(static_cast<double>(d))), 3) + " / " + num(r) + ") = " +
             num(per_axis, 0) + " per axis, m = N^" + std::to_string(d) + " = " + num(m, 0) + ". sigma = mu(B_1) / 2^d = " +
             sig(sigma) + ", sigma r^d = " + sig(rate) + ". m e^(-sigma r^d n) <= p gives n >= ln(m/p) / (sigma r^d) = " +
             num(std::log(m / p) / rate, 2) + ", so n = " + num(n, 0) +
             ". A path of length L needs only ceil(L/(r/2)) balls: tiling everything multiplies the count by about "
             "(2/r)^(d-1) / L, and n grows with its logarithm.";
  const double one_ball = std::ceil(std::log(1.0 / p) / rate);
  const double refined = std::ceil(whole_space_tiling_bound(r, d, 0).samples_for(p));
  e.traps = {{one_ball, "That is the n for a single ball (m = 1): the bound multiplies by the number of balls m."},
             {std::ceil(std::log(m / p) / (unit_ball_volume(d) * std::pow(r, d))),
              "That uses mu(B_1) r^d, the volume of a ball of radius r: the balls have radius r/2, so sigma has the "
              "2^d in it."},
             {refined, "That is the refined bound's n, which counts the balls sticking out of the cube at the lower rate "
                       "they are hit with: the exercise asks for the handout's m e^(-sigma r^d n), as the Cube (P8) tab "
                       "shows first."}};
  return e;
}

// ---- P9: visibility through the gap ------------------------------------------------------

Exercise p9(Rng& rng) {
  const double x = draw2(rng, 0.05, 0.45), y = draw2(rng, 0.05, 0.95), d = draw2(rng, 0.05, 0.3);
  const double prob = visibility_probability(x, y, d);
  Exercise e;
  e.prompt = "Q = [0,1] x [0,1] with a wall at x = 1/2 and an opening of height d = " + num(d) +
             " in its middle. From (x1, y1) = (" + num(x) + ", " + num(y) +
             "), what is the probability that a uniformly sampled configuration is visible?";
  e.given = {{"x", x}, {"y", y}, {"d", d}};
  e.answer_format = "number";
  set_format_hint(e, "a probability, to three decimals", "0.002");
  e.answer = prob;
  e.tolerance = 0.002;
  e.worked = "The left half is convex, so all of it is visible: 1/2. On the right, the visible part is the cone from (" +
             num(x) + ", " + num(y) + ") through the gap's ends (1/2, " + num(0.5 - d / 2, 3) + ") and (1/2, " +
             num(0.5 + d / 2, 3) + "), cut off by the square's edges: its area is " + num(prob - 0.5, 4) +
             ". Total " + num(prob, 4) + ". The Visibility tab names the case and puts these numbers into its formula.";
  e.traps = {{0.5, "That is the left half alone: the point also sees part of the right half through the gap."},
             {prob - 0.5, "That is the right half's visible part alone: all of the left half is visible too."}};
  return e;
}

// ---- P10: distance on S^1 ----------------------------------------------------------------

Exercise p10(Rng& rng) {
  const double q1 = draw2(rng, 0.0, kTwoPi), q2 = draw2(rng, rng.below(4) == 0 ? -kPi : 0.0, kTwoPi);
  const double dist = s1_distance(q1, q2);
  const double raw = std::fabs(q1 - q2);
  Exercise e;
  e.prompt = "Two configurations of a revolute joint, q1 = " + num(q1) + " and q2 = " + num(q2) +
             " (radians). What is the distance between them on S^1?";
  e.given = {{"q1", q1}, {"q2", q2}};
  e.answer_format = "number";
  set_format_hint(e, "radians, e.g. 1.57 or pi/2", "0.005");
  e.answer = dist;
  e.tolerance = 0.005;
  const double m = std::fmod(raw, kTwoPi);
  e.worked = "|q1 - q2| = " + num(raw, 4) + "; mod 2 pi: " + num(m, 4) + "; the shorter way round is min(" + num(m, 4) +
             ", 2 pi - " + num(m, 4) + ") = " + num(dist, 4) + ". The same from the rotations: arccos(cos q1 cos q2 + "
             "sin q1 sin q2) = arccos(" + num(std::cos(q1 - q2), 4) + ") = " + num(dist, 4) + ".";
  if (std::fabs(raw - dist) > 0.01) e.traps.push_back({raw, "That is |q1 - q2|, once round without wrapping: angles 2 pi apart are the same configuration, so take the difference mod 2 pi and then the shorter way."});
  if (std::fabs(kTwoPi - dist - dist) > 0.01) e.traps.push_back({kTwoPi - dist, "That is the longer way round the circle: the distance is the shorter arc, at most pi."});
  return e;
}

// ---- P11: segment to disk ----------------------------------------------------------------

Exercise p11(Rng& rng) {
  // Every special case comes up: the seed picks one and points are drawn until it holds.
  const int want = static_cast<int>(rng.below(5));  // 0 inside, 1 at p1, 2 at p2, 3 degenerate, 4 meeting
  Vec2 p1, p2, q;
  double r = 0, t_raw = 0, centre = 0;
  for (int tries = 0; tries < 1000; ++tries) {
    p1 = draw_point(rng, 0.05, 0.95);
    p2 = want == 3 ? p1 : draw_point(rng, 0.05, 0.95);
    q = draw_point(rng, 0.05, 0.95);
    r = draw2(rng, 0.03, 0.2);
    const Vec2 d = p2 - p1;
    const double len2 = squared_length(d);
    if (want != 3 && len2 < 0.04) continue;  // a visible segment
    t_raw = len2 > 0 ? (q - p1).dot(d) / len2 : 0.0;
    centre = point_segment_distance(q, p1, p2);
    const bool meets = centre <= r;
    const int got = want == 3 ? 3 : meets ? 4 : t_raw <= 0 ? 1 : t_raw >= 1 ? 2 : 0;
    if (got == want && (want == 4 || centre - r > 0.02)) break;
  }
  const double dist = std::max(0.0, centre - r);
  Exercise e;
  e.prompt = "A segment from p1 = " + point_text(p1) + " to p2 = " + point_text(p2) + " and a disk of radius r = " + num(r) +
             " centred at q = " + point_text(q) + ". What is the distance between the segment and the disk (0 if they meet)?";
  e.given = {{"p1", point_json(p1)}, {"p2", point_json(p2)}, {"q", point_json(q)}, {"r", r}};
  e.answer_format = "number";
  set_format_hint(e, "a distance", "0.005");
  e.answer = dist;
  e.tolerance = 0.005;
  const double t = std::clamp(t_raw, 0.0, 1.0);
  const Vec2 c = p1 + t * (p2 - p1);
  std::string how = want == 3 ? "p1 = p2: the segment is a single point, no projection: the closest point is p1"
                              : "t* = (q - p1).(p2 - p1) / |p2 - p1|^2 = " + num(t_raw, 4) +
                                    (t_raw <= 0   ? ", before p1: clamped to 0, the closest point is p1"
                                     : t_raw >= 1 ? ", past p2: clamped to 1, the closest point is p2"
                                                  : ", inside [0, 1]: the closest point is p1 + t*(p2 - p1)");
  e.worked = how + " = (" + num(c.x(), 4) + ", " + num(c.y(), 4) + "). |q - closest| = " + num(centre, 4) +
             ", minus r: " + num(centre - r, 4) +
             (centre <= r ? " <= 0: the segment meets the disk, distance 0." : ".") +
             " (The lab's collision checker keeps the sign, |q - closest| - r, as the clearance eta: negative means how deep.)";
  if (std::fabs(centre - dist) > 0.01) e.traps.push_back({centre, "That is the distance to the disk's centre q: subtract the radius r."});
  const double line = t_raw == t ? centre : (want == 3 ? centre : std::fabs(orient(p1, p2, q)) / length(p2 - p1));
  if (std::fabs(line - r - dist) > 0.01)
    e.traps.push_back({std::max(0.0, line - r), "That uses the whole line through p1 and p2: the projection parameter must be clamped to [0, 1], the segment's ends."});
  if (centre < r) e.traps.push_back({centre - r, "That is the signed value the lab uses for clearance: the distance the problem asks for is 0 when they meet."});
  return e;
}

// ---- P12: the smallest N of the fixed-resolution check -----------------------------------

// Whether some configuration t = i/(N-1), N <= max_n, lies within 1e-7 of the circle: there
// "inside" hangs on rounding (0.25 - 0.21 is not 0.04 in doubles), so the exercise is drawn again.
bool grazes(const Vec2& centre, double radius, int max_n) {
  for (int n = 2; n <= max_n; ++n)
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / (n - 1);
      if (std::fabs(std::hypot(t - centre.x(), centre.y()) - radius) < 1e-7) return true;
    }
  return false;
}

Exercise p12(Rng& rng) {
  double radius = 0;
  Vec2 centre(0, 0);
  for (int tries = 0; tries < 1000; ++tries) {
    radius = draw2(rng, 0.03, 0.15);
    const double cx = draw2(rng, 0.1, 0.9);
    centre = Vec2(cx, round2(rng.uniform(-0.8, 0.8) * radius));
    // p and q free, with room (the handout's edge joins two free configurations).
    const bool ends_free = length(centre) > radius + 0.02 && length(centre - Vec2(1.0, 0.0)) > radius + 0.02;
    if (ends_free && !grazes(centre, radius, 64)) break;
  }
  const Vec2 p(0.0, 0.0), q(1.0, 0.0);
  Scene scene;
  scene.workspace_min = Vec2(-0.5, -0.5);
  scene.workspace_max = Vec2(1.5, 0.5);
  scene.robot = PointRobot{};
  scene.obstacles = {Disk{centre, radius}};
  scene.start = config({p.x(), p.y()});
  scene.goal = config({q.x(), q.y()});
  const CollisionWorld world(scene);
  const std::optional<int> n = min_grid_resolution(world, scene.start, scene.goal, 100000);
  if (!n) throw std::logic_error("P12 exercise: the edge misses its disk");
  Exercise e;
  e.prompt = "A point robot moves in a straight line from p = (0, 0) to q = (1, 0); a disk of radius " + num(radius) +
             " sits at " + point_text(centre) + ". Checking N equally spaced configurations from p to q, both ends "
             "included (t = i/(N-1)), what is the smallest N that finds the collision?";
  e.given = {{"p", point_json(p)}, {"q", point_json(q)}, {"center", point_json(centre)}, {"radius", radius}};
  e.answer_format = "integer";
  set_format_hint(e, "a whole number N >= 2", "", "both ends counted");
  e.answer = *n;
  e.tolerance = 0;
  const double half = std::sqrt(radius * radius - centre.y() * centre.y());
  e.worked = "The line y = 0 is inside the disk for x in [" + num(centre.x() - half, 4) + ", " + num(centre.x() + half, 4) +
             "]. With N points, t = i/(N-1): N = " + std::to_string(*n) + " is the first with a point there (t = " +
             "i/" + std::to_string(*n - 1) + "); every smaller N steps over it. Counted without the ends (N interior "
             "points, t = i/(N+1)) the same grid is " + std::to_string(*n - 2) + ".";
  e.traps = {{static_cast<double>(*n - 2), "That counts only the points between p and q: this exercise counts both ends, t = i/(N-1)."},
             {static_cast<double>(*n - 1), "That is the number of intervals, N - 1: count the configurations, both ends included."}};
  return e;
}

// ---- P13: repulsion at a rectangle's vertices --------------------------------------------

Exercise p13(Rng& rng) {
  // A rectangle at (cx, cy) with no turn, and a box obstacle to its right, near enough that a
  // vertex is well inside rho0 (drawn again until one is) and none touches it.
  const Vec2 centre(0.4, 0.5);
  const double eta = 0.001;
  double a = 0, b = 0, rho0 = 0, x0 = 0, y0 = 0, h = 0;
  Polygon box;
  PotentialReport report;
  for (int tries = 0; tries < 1000; ++tries) {
    a = draw2(rng, 0.08, 0.15), b = draw2(rng, 0.04, 0.08);
    rho0 = draw2(rng, 0.08, 0.15);
    x0 = round2(centre.x() + a + draw2(rng, 0.02, rho0 * 0.8));
    y0 = round2(centre.y() + rng.uniform(-2.0, 0.5) * b), h = draw2(rng, 0.1, 0.3);
    box = {Vec2(x0, y0), Vec2(x0 + 0.2, y0), Vec2(x0 + 0.2, y0 + h), Vec2(x0, y0 + h)};
    Scene scene;
    scene.robot = make_polygon_robot({Vec2(-a, -b), Vec2(a, -b), Vec2(a, b), Vec2(-a, b)});
    scene.obstacles = {PolygonObstacle{box}};
    scene.start = config({centre.x(), centre.y(), 0.0});
    scene.goal = scene.start;
    const CollisionWorld world(scene);
    PotentialParams params;
    params.eta = eta;
    params.rho0 = rho0;
    report = PotentialField(world, scene.goal, params).evaluate(scene.start);
    double least = 1e9;
    for (const ControlPointReport& p : report.points) least = std::min(least, p.nearest.rho);
    if (least >= 0.01 && least <= 0.9 * rho0) break;
  }

  static const char* const kQuantities[] = {"rho", "force", "fx", "fy", "torque"};
  // The vertex asked about: one within rho0 for the force, any for rho.
  int vertex = static_cast<int>(rng.below(4));
  const std::size_t first = static_cast<std::size_t>(rng.below(5));
  double total = 0;  // sum of |F_rep| over the vertices: the scale of a net force
  for (const ControlPointReport& p : report.points) total += length(p.repulsive.F);
  std::string quantity, what;
  double answer = 0;
  // A net force or torque that cancels by symmetry (0 up to rounding) is a guess, not an
  // exercise: the next quantity is asked instead.
  for (std::size_t k = 0; k < 5; ++k) {
    quantity = kQuantities[(first + k) % 5];
    if (quantity == "force")
      for (int j = 0; j < 4 && report.points[static_cast<std::size_t>(vertex)].nearest.rho > rho0; ++j) vertex = (vertex + 1) % 4;
    const ControlPointReport& v = report.points[static_cast<std::size_t>(vertex)];
    const std::string at = "a" + std::to_string(vertex + 1);
    if (quantity == "rho") answer = v.nearest.rho, what = "rho(" + at + "), its distance to the obstacle";
    if (quantity == "force") answer = length(v.repulsive.F), what = "|F_rep(" + at + ")|, the length of the repulsive force at that vertex";
    if (quantity == "fx") answer = report.F_rep.x(), what = "the x component of the net repulsive workspace force (the sum over the four vertices)";
    if (quantity == "fy") answer = report.F_rep.y(), what = "the y component of the net repulsive workspace force (the sum over the four vertices)";
    if (quantity == "torque") answer = report.tau_rep[2], what = "the torque of the repulsive forces about the robot's centre (sum of (a_i - centre) x F_rep(a_i))";
    const double scale = quantity == "torque" ? total * b : total;
    if (quantity == "rho" || quantity == "force" || std::fabs(answer) >= 0.05 * scale) break;
  }

  json vertices = json::array(), obstacle = json::array();
  for (const ControlPointReport& p : report.points) vertices.push_back(point_json(p.position));
  for (const Vec2& p : box) obstacle.push_back(point_json(p));
  Exercise e;
  e.prompt = "A rectangle robot centred at " + point_text(centre) + " with vertices a1..a4 = " + point_text(report.points[0].position) +
             ", " + point_text(report.points[1].position) + ", " + point_text(report.points[2].position) + ", " +
             point_text(report.points[3].position) + "; a box obstacle [" + num(x0) + ", " + num(x0 + 0.2) + "] x [" + num(y0) + ", " +
             num(y0 + h) + "]; rho0 = " + num(rho0) + ", eta = " + number_text_exact(eta) +
             ". The repulsive force acts at the four vertices only (eq. 5.6). Find " + what + ".";
  e.given = {{"vertices", vertices}, {"center", point_json(centre)}, {"obstacle", obstacle}, {"rho0", rho0}, {"eta", eta},
             {"quantity", quantity}};
  if (quantity == "rho" || quantity == "force") e.given["vertex"] = vertex + 1;
  e.answer_format = "number";
  set_format_hint(e, "a number", "1%", "0 if no force acts");
  e.answer = answer;
  e.tolerance = std::max(1e-9, 0.01 * std::fabs(answer));
  std::string worked;
  for (std::size_t i = 0; i < report.points.size(); ++i) {
    const ControlPointReport& p = report.points[i];
    worked += "a" + std::to_string(i + 1) + ": rho = " + sig(p.nearest.rho);
    if (p.nearest.rho > rho0) {
      worked += " > rho0, no force\n";
    } else {
      worked += ", grad rho = (" + sig(p.nearest.grad.x()) + ", " + sig(p.nearest.grad.y()) + "), F_rep = eta (1/rho - 1/rho0) " +
                "(1/rho^2) grad rho = (" + sig(p.repulsive.F.x()) + ", " + sig(p.repulsive.F.y()) + ")\n";
    }
  }
  worked += "Sum F_rep = (" + sig(report.F_rep.x()) + ", " + sig(report.F_rep.y()) + "); torque about the centre = " +
            sig(report.tau_rep[2]) + " (J_i^T F_i summed: for a vertex at offset (dx, dy), dx F_y - dy F_x).";
  e.worked = worked;
  if (quantity == "fx" || quantity == "fy" || quantity == "torque") e.traps.push_back({-answer, "The sign is wrong: grad rho points from the obstacle to the vertex, and the repulsion pushes away from the obstacle."});
  return e;
}

}  // namespace

json exercise_tool_setup(const Exercise& e) {
  const json& g = e.given;
  // The analysis lesson tiles its scene's own space: a plane, so only d = 2 goes there.
  if (e.id == "P8")
    return g["d"] == 2 ? json{{"params", {{"tab", "tiling"}, {"clearance", g["r"]}, {"target", g["p"]}}}} : json(nullptr);
  if (e.id == "P9") return {{"params", {{"tab", "visibility"}, {"point", {g["x"], g["y"]}}, {"gap", g["d"]}}}};
  if (e.id == "P10") return {{"params", {{"tool", "s1"}, {"q1", g["q1"]}, {"q2", g["q2"]}}}};
  if (e.id == "P11")
    return {{"params", {{"tool", "segment"}, {"p1", g["p1"]}, {"p2", g["p2"]}, {"q", g["q"]}, {"r", g["r"]}}}};
  if (e.id == "P12")
    return {{"scene",
             {{"version", 1},
              {"name", "P12 exercise " + std::to_string(e.seed)},
              {"workspace", {{"min", {-0.1, -0.5}}, {"max", {1.1, 0.5}}}},
              {"robot", {{"type", "point"}}},
              {"obstacles", json::array({{{"type", "disk"}, {"center", g["center"]}, {"radius", g["radius"]}}})},
              {"start", g["p"]},
              {"goal", g["q"]}}},
            {"params", json::object()}};
  if (e.id == "P13") {
    // The body in the robot's frame, from the vertices where it stands (no turn).
    const json& v = g["vertices"];
    const double cx = g["center"][0].get<double>(), cy = g["center"][1].get<double>();
    json body = json::array();
    for (const json& p : v) body.push_back({round2(p[0].get<double>() - cx), round2(p[1].get<double>() - cy)});
    return {{"scene",
             {{"version", 1},
              {"name", "P13 exercise " + std::to_string(e.seed)},
              {"workspace", {{"min", {0, 0}}, {"max", {1, 1}}}},
              {"robot", {{"type", "polygon"}, {"vertices", body}}},
              {"obstacles", json::array({{{"type", "polygon"}, {"vertices", g["obstacle"]}}})},
              {"start", {cx, cy, 0}},
              {"goal", {0.15, 0.2, 0}}}},
            {"params", {{"rho0", g["rho0"]}, {"eta", g["eta"]}}}};
  }
  return nullptr;
}

Exercise make_exercise(const std::string& id, std::uint64_t seed) {
  const HomeworkProblem* problem = find_homework_problem(id);
  if (!problem) throw std::invalid_argument("no problem \"" + id.substr(0, 16) + "\" (P1 to P13)");
  if (seed > kMaxExerciseSeed) throw std::invalid_argument("seed: at most 2^53 - 1");
  const int index = std::stoi(problem->id.substr(1));
  Rng rng((static_cast<std::uint64_t>(index) << 56) ^ seed);
  Exercise e;
  switch (index) {
    case 1: e = p1(rng); break;
    case 2: e = arm_exercise("P2", rng, 3); break;
    case 3: e = arm_exercise("P3", rng, 2); break;
    case 4: e = arm_exercise("P4", rng, 2); break;
    case 5: e = arm_exercise("P5", rng, 3); break;
    case 6: e = p6(rng); break;
    case 7: e = p7(rng); break;
    case 8: e = p8(rng); break;
    case 9: e = p9(rng); break;
    case 10: e = p10(rng); break;
    case 11: e = p11(rng); break;
    case 12: e = p12(rng); break;
    default: e = p13(rng); break;
  }
  e.id = problem->id;
  e.seed = seed;
  return e;
}

}  // namespace csl
