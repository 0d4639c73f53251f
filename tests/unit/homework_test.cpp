// The homework companion (homework P1-P13): the problem list, and for every problem 300 seeded
// exercises whose answers are checked against formulas written again here from the handout
// (never the lab's geometry, analysis or potential code), and the checker on exact answers,
// answers just outside the tolerance, typical mistakes and garbage.
//
// The oracles:
//   P1-P7  the dimension and a right answer built from the robot's description, read here
//   P8     n = ceil(ln(m/p) / (sigma r^d)), N = ceil(2/r) per axis in integer hundredths
//   P9     the visible area, piecewise linear in x2, integrated exactly between its kinks
//          (and by a midpoint rule as a check on the kinks)
//   P10    min over turns of |q1 - q2 + 2 pi k|, and acos of the rotations' dot product
//   P11    the clamped projection, and brute force over 200001 points of the segment
//   P12    brute force over N in exact integer arithmetic (the givens are hundredths)
//   P13    point-to-convex-polygon distance and the handout's F_rep, summed by hand
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/teaching/homework.hpp"
#include "core/teaching/notation.hpp"

using json = nlohmann::json;

namespace {

constexpr double kPiHere = 3.14159265358979323846;
constexpr int kSeeds = 300;

// ---------------------------------------------------------------------------------------------
// Text and JSON helpers.

std::string fixed12(double v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.12f", v);
  return buf;
}

std::string g17(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string g6(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Whether v, as JSON prints it (what the student reads), has at most two decimals and no
// exponent.
bool two_decimals(double v) {
  const std::string s = json(v).dump();
  if (s.find_first_of("eE") != std::string::npos) return false;
  const std::size_t dot = s.find('.');
  return dot == std::string::npos || s.size() - dot - 1 <= 2;
}

// Every number anywhere in `j`, with its path for messages.
void numbers_in(const json& j, const std::string& path, std::vector<std::pair<std::string, double>>& out) {
  if (j.is_number()) {
    out.emplace_back(path, j.get<double>());
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) numbers_in(j[i], path + "[" + std::to_string(i) + "]", out);
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) numbers_in(it.value(), path + "." + it.key(), out);
  }
}

// Whether any object in `j` (at any depth) has one of the keys that would give the answer away.
// ("robot" is allowed: P1-P7 give the robot in words; its description is checked separately.)
bool has_answer_key(const json& j) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      for (const char* k : {"answer", "tolerance", "worked", "expected", "traps", "description"})
        if (it.key() == k) return true;
      if (has_answer_key(it.value())) return true;
    }
  } else if (j.is_array()) {
    for (const json& e : j)
      if (has_answer_key(e)) return true;
  }
  return false;
}

double num(const json& given, const char* key) {
  REQUIRE_MESSAGE(given.contains(key), "given has no ", key, ": ", given.dump());
  REQUIRE(given.at(key).is_number());
  return given.at(key).get<double>();
}

struct P2 {
  double x = 0, y = 0;
};
P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
P2 operator*(double s, P2 a) { return {s * a.x, s * a.y}; }
double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }
double cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
double norm(P2 a) { return std::sqrt(dot(a, a)); }

P2 point(const json& j) {
  REQUIRE_MESSAGE((j.is_array() && j.size() == 2 && j[0].is_number() && j[1].is_number()), j.dump());
  return {j[0].get<double>(), j[1].get<double>()};
}

P2 point_at(const json& given, const char* key) {
  REQUIRE_MESSAGE(given.contains(key), "given has no ", key, ": ", given.dump());
  return point(given.at(key));
}

// ---------------------------------------------------------------------------------------------
// Checks every exercise gets, whatever its problem.

void check_common(const csl::Exercise& e, const std::string& id, std::uint64_t seed, const char* format) {
  CHECK(e.id == id);
  CHECK(e.seed == seed);
  CHECK(e.answer_format == format);
  CHECK_FALSE(e.prompt.empty());
  CHECK_FALSE(e.format_hint.empty());
  CHECK(e.given.is_object());
  CHECK(std::isfinite(e.answer));
  CHECK(std::isfinite(e.tolerance));
  CHECK(e.tolerance >= 0.0);

  // The exercise as the student gets it: these keys and nothing that gives the answer away.
  const json j = csl::exercise_to_json(e);
  REQUIRE(j.is_object());
  std::set<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.insert(it.key());
  CHECK(keys == std::set<std::string>{"id", "seed", "prompt", "given", "answer_format", "format_hint"});
  CHECK_FALSE(has_answer_key(j));
  CHECK(j.at("id") == id);
  CHECK(j.at("seed") == seed);
  CHECK(j.at("given") == e.given);
  // The robot's description (the notation answer follows from it mechanically) is not in it.
  if (!e.robot.empty()) CHECK_FALSE(contains(j.dump(), e.robot));

  // Same problem and seed: the same exercise, to the bit.
  const csl::Exercise again = csl::make_exercise(id, seed);
  CHECK(csl::exercise_to_json(again).dump() == j.dump());
  CHECK(again.answer == e.answer);
  CHECK(again.tolerance == e.tolerance);
  CHECK(again.robot == e.robot);
  CHECK(again.worked == e.worked);
}

// Numeric problems: the givens are printed with at most two decimals (what the student reads is
// what the answer was computed from), and the answer's digits appear nowhere in the JSON.
void check_given_and_no_leak(const csl::Exercise& e) {
  std::vector<std::pair<std::string, double>> nums;
  numbers_in(e.given, "given", nums);
  for (const auto& item : nums) {  // no structured binding: clang 14 (wasm) cannot capture one in INFO
    const std::string& path = item.first;
    const double v = item.second;
    // P8's target p and P13's eta are constants from a short list (0.001 among them), not
    // drawn: the prompt writes them exactly as they are.
    if (path == "given.p" || path == "given.eta") {
      CHECK_MESSAGE(contains(e.prompt, json(v).dump()), e.id, " seed ", e.seed, ": ", path, " = ", json(v).dump(),
                    " is not written as such in the prompt");
      continue;
    }
    CHECK_MESSAGE(two_decimals(v), e.id, " seed ", e.seed, ": ", path, " = ", json(v).dump());
    // A zero is written 0, not -0.0 (JSON) or -0.00 (the prompt).
    CHECK_MESSAGE(!(v == 0.0 && std::signbit(v)), e.id, " seed ", e.seed, ": ", path, " is -0");
  }

  const std::string text = csl::exercise_to_json(e).dump();
  const bool whole = std::fabs(e.answer - std::round(e.answer)) == 0.0;
  if (e.answer_format == "number" && !two_decimals(e.answer)) {
    // Its shortest spelling, and the six digits a message would print.
    CHECK_MESSAGE(!contains(text, json(e.answer).dump()), e.id, " seed ", e.seed, " leaks ", json(e.answer).dump());
    const std::string six = g6(e.answer);
    if (six.size() >= 5) CHECK_MESSAGE(!contains(text, six), e.id, " seed ", e.seed, " leaks ", six);
  } else if (e.answer_format == "integer" && whole && std::fabs(e.answer) >= 10000) {
    const std::string digits = std::to_string(std::llround(e.answer));
    CHECK_MESSAGE(!contains(text, digits), e.id, " seed ", e.seed, " leaks ", digits);
  }
}

// The checker on numeric answers: the exact answer (several spellings) is right, one just
// outside the tolerance is wrong, and garbage is wrong with a message, never an exception.
void check_checker_numeric(const csl::Exercise& e) {
  const bool integer = e.answer_format == "integer";
  const double a = e.answer, tol = e.tolerance;
  INFO(e.id, " seed ", e.seed, " answer ", g17(a), " tolerance ", g17(tol));

  const auto verdict = [&](const std::string& typed) {
    csl::ExerciseCheck c;
    CHECK_NOTHROW(c = csl::check_exercise(e, typed));
    CHECK_FALSE(c.explanation.empty());
    return c;
  };

  if (integer) {
    REQUIRE(a == std::round(a));
    const long long n = std::llround(a);
    const csl::ExerciseCheck c = verdict(std::to_string(n));
    CHECK_MESSAGE(c.correct, std::to_string(n));
    REQUIRE(c.expected.is_number_integer());
    CHECK(c.expected.get<long long>() == n);
    CHECK(verdict(std::to_string(n) + ".0").correct);  // a whole decimal is read as one
    CHECK(verdict(" " + std::to_string(n) + " ").correct);
    // Just outside: one more than the tolerance allows, both ways.
    const long long off = static_cast<long long>(std::floor(tol)) + 1;
    CHECK_FALSE(verdict(std::to_string(n + off)).correct);
    CHECK_FALSE(verdict(std::to_string(n - off)).correct);
    // Inside, at the edge: |typed - answer| == floor(tol) is accepted.
    const long long in = static_cast<long long>(std::floor(tol));
    CHECK(verdict(std::to_string(n + in)).correct);
    CHECK(verdict(std::to_string(n - in)).correct);
  } else {
    const csl::ExerciseCheck c = verdict(fixed12(a));
    CHECK_MESSAGE(c.correct, fixed12(a));
    REQUIRE(c.expected.is_number());
    CHECK(c.expected.get<double>() == a);
    CHECK_MESSAGE(verdict(g17(a)).correct, g17(a));
    CHECK(verdict(fixed12(a / kPiHere) + "*pi").correct);  // a multiple of pi, as the format allows
    CHECK(verdict(fixed12(a + 0.5 * tol)).correct);
    CHECK(verdict(fixed12(a - 0.5 * tol)).correct);
    const double off = 2.0 * tol + 1e-6 * std::max(1.0, std::fabs(a));
    CHECK_FALSE(verdict(fixed12(a + off)).correct);
    CHECK_FALSE(verdict(fixed12(a - off)).correct);
  }
  for (const char* garbage : {"", "   ", "abc", "1e999", "-1e999", "nan", "inf", "1/0", "pi/0", "0x10", "1,5,0",
                              "2 3", "pi pi", "--1", "\x01\xff"}) {
    const csl::ExerciseCheck c = verdict(garbage);
    CHECK_MESSAGE(!c.correct, "garbage '", garbage, "' was accepted");
  }
  CHECK_FALSE(verdict(std::string(100000, '9')).correct);
  CHECK_FALSE(verdict(std::string(5000, '(')).correct);
}

// Per problem: typical mistakes checked, and how many of them got an explanation of their own
// (longer than the one for a far-off number: the checker recognised the mistake). Reported.
std::map<std::string, std::pair<int, int>> g_mistake_explanations;

// A typical mistake: wrong, with an explanation. Only asked when the mistake really is outside
// the tolerance (it can coincide with the answer for some seeds). Returns whether it was asked.
bool check_mistake(const csl::Exercise& e, double wrong, const char* what) {
  if (!std::isfinite(wrong) || std::fabs(wrong - e.answer) <= 1.5 * e.tolerance + 1e-9) return false;
  const std::string typed = e.answer_format == "integer" ? std::to_string(std::llround(wrong)) : fixed12(wrong);
  if (e.answer_format == "integer" && std::fabs(std::round(wrong) - e.answer) <= e.tolerance) return false;
  csl::ExerciseCheck c;
  CHECK_NOTHROW(c = csl::check_exercise(e, typed));
  CHECK_MESSAGE(!c.correct, e.id, " seed ", e.seed, ": the mistake '", what, "' (", typed, ") was accepted, answer ",
                g17(e.answer));
  CHECK_FALSE(c.explanation.empty());
  const double far = e.answer + 1000.0 * std::max(1.0, e.tolerance) + 0.123;
  const std::string far_typed =
      e.answer_format == "integer" ? std::to_string(std::llround(far)) : fixed12(far);
  const csl::ExerciseCheck generic = csl::check_exercise(e, far_typed);
  auto& counts = g_mistake_explanations[e.id];
  ++counts.first;
  counts.second += c.explanation.size() > generic.explanation.size() + 15;
  return true;
}

std::string mistake_report(const std::string& id) {
  const auto& counts = g_mistake_explanations[id];
  return std::to_string(counts.first) + " typical mistakes checked, " + std::to_string(counts.second) +
         " with an explanation of their own";
}

// ---------------------------------------------------------------------------------------------
// P1-P7: the robot's description, read here (key=value tokens, spaces or commas).

struct RobotHere {
  std::string base = "fixed";
  std::string joints;
  bool wrist = false;

  int revolute() const { return static_cast<int>(std::count(joints.begin(), joints.end(), 'R')) + (wrist ? 3 : 0); }
  int prismatic() const { return static_cast<int>(std::count(joints.begin(), joints.end(), 'P')); }
  int base_dim() const {
    if (base == "planar") return 3;
    if (base == "planar-translating") return 2;
    if (base == "spatial") return 6;
    if (base == "spatial-translating") return 3;
    return 0;
  }
  int dimension() const { return base_dim() + static_cast<int>(joints.size()) + (wrist ? 3 : 0); }
};

RobotHere read_robot(const std::string& description) {
  std::string t;
  for (char ch : description) t += ch == ',' ? ' ' : ch;
  // "key = value" -> "key=value"
  for (std::size_t i; (i = t.find(" =")) != std::string::npos;) t.erase(i, 1);
  for (std::size_t i; (i = t.find("= ")) != std::string::npos;) t.erase(i + 1, 1);
  RobotHere r;
  std::size_t pos = 0;
  while (pos < t.size()) {
    while (pos < t.size() && t[pos] == ' ') ++pos;
    std::size_t end = t.find(' ', pos);
    if (end == std::string::npos) end = t.size();
    const std::string token = t.substr(pos, end - pos);
    pos = end;
    if (token.empty()) continue;
    const std::size_t eq = token.find('=');
    REQUIRE_MESSAGE(eq != std::string::npos, "not key=value: ", token);
    const std::string key = token.substr(0, eq), value = token.substr(eq + 1);
    if (key == "base") {
      r.base = value;
    } else if (key == "joints") {
      r.joints = value;
    } else if (key == "wrist") {
      REQUIRE((value == "spherical" || value == "none"));
      r.wrist = value == "spherical";
    } else {
      FAIL("unknown key ", key);
    }
  }
  REQUIRE(r.joints.find_first_not_of("RP") == std::string::npos);
  return r;
}

std::string superscript(int n) {
  static const char* digits[] = {"\xE2\x81\xB0", "\xC2\xB9", "\xC2\xB2", "\xC2\xB3", "\xE2\x81\xB4",
                                 "\xE2\x81\xB5", "\xE2\x81\xB6", "\xE2\x81\xB7", "\xE2\x81\xB8", "\xE2\x81\xB9"};
  std::string s;
  for (char ch : std::to_string(n)) s += digits[ch - '0'];
  return s;
}

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + parts[i];
  return s;
}

// Right answers for the robot, in the handout's notation and the spellings a student may use.
std::vector<std::string> right_answers(const RobotHere& r) {
  const int k = r.revolute(), j = r.prismatic();
  const std::string K = std::to_string(k), J = std::to_string(j);
  std::vector<std::string> ascii, unicode, spelled_out, merged;
  int reals = 0;
  if (r.base == "planar") {
    ascii.push_back("SE(2)");
    unicode.push_back("SE(2)");
    spelled_out.push_back("R^2 x S^1");
  } else if (r.base == "spatial") {
    ascii.push_back("SE(3)");
    unicode.push_back("SE(3)");
    spelled_out.push_back("R^3 x SO(3)");
  } else if (r.base == "planar-translating") {
    ascii.push_back("R^2");
    unicode.push_back("R" + superscript(2));
    spelled_out.push_back("R^2");
  } else if (r.base == "spatial-translating") {
    ascii.push_back("R^3");
    unicode.push_back("R" + superscript(3));
    spelled_out.push_back("R^3");
  }
  if (r.base == "planar" || r.base == "planar-translating") reals = 2;
  if (r.base == "spatial" || r.base == "spatial-translating") reals = 3;
  if (k > 0) {
    ascii.push_back("T^" + K);
    unicode.push_back(k == 1 ? "S" + superscript(1) : "T" + superscript(k));
    spelled_out.push_back(k == 1 ? "SO(2)" : "(S^1)^" + K);
  }
  if (j > 0) {
    ascii.push_back(j == 1 ? "R" : "R^" + J);
    unicode.push_back(j == 1 ? "R" : "R" + superscript(j));
    spelled_out.push_back("R^" + J);
  }
  // Everything merged: R^(reals + j) x T^(circles) x SO(3)?
  const int circles = k + (r.base == "planar" ? 1 : 0);
  if (reals + j > 0) merged.push_back("R^" + std::to_string(reals + j));
  if (circles > 0) merged.push_back("T^" + std::to_string(circles));
  if (r.base == "spatial") merged.push_back("SO(3)");

  std::vector<std::string> out;
  out.push_back(join(ascii, " x "));
  out.push_back("Q = " + join(ascii, " x "));
  out.push_back(join(unicode, " \xC3\x97 "));  // ×
  std::reverse(spelled_out.begin(), spelled_out.end());
  out.push_back(join(spelled_out, " * "));
  out.push_back(join(merged, " x "));
  if (k >= 2) {  // the torus written as k circles
    std::vector<std::string> circles_out(ascii.begin(), ascii.end());
    for (std::string& f : circles_out)
      if (f == "T^" + K) {
        std::vector<std::string> s1(static_cast<std::size_t>(k), "S^1");
        f = join(s1, " x ");
      }
    out.push_back(join(circles_out, " x "));
  }
  return out;
}

// The examples of a format hint: what follows "e.g. ", up to " (" or the end, split at " or ".
std::vector<std::string> hint_examples(const std::string& hint) {
  std::vector<std::string> out;
  const std::size_t eg = hint.find("e.g. ");
  if (eg == std::string::npos) return out;
  std::string rest = hint.substr(eg + 5);
  rest = rest.substr(0, rest.find(" ("));
  for (std::size_t start = 0;;) {
    const std::size_t sep = rest.find(" or ", start);
    out.push_back(rest.substr(start, sep == std::string::npos ? std::string::npos : sep - start));
    if (sep == std::string::npos) break;
    start = sep + 4;
  }
  return out;
}

// The robot each problem describes (the handout's wording, checked on the description).
void check_problem_robot(const std::string& id, const RobotHere& r) {
  if (id == "P1") {
    CHECK(r.base == "planar");
    CHECK(r.joints.empty());
    CHECK_FALSE(r.wrist);
    CHECK(r.dimension() == 3);
  } else if (id == "P6" || id == "P7") {
    CHECK(r.base == (id == "P6" ? "fixed" : "planar"));
    CHECK(r.joints == "RRR");
    CHECK(r.wrist);
    CHECK(r.dimension() == (id == "P6" ? 6 : 9));
  } else {
    const std::size_t joints = (id == "P2" || id == "P5") ? 3 : 2;
    CHECK(r.base == "fixed");
    CHECK(r.joints.size() == joints);
    CHECK_FALSE(r.wrist);
    CHECK(r.dimension() == static_cast<int>(joints));
  }
}

// Wrong answers students write, each wrong for this robot.
std::vector<std::string> wrong_answers(const RobotHere& r) {
  const int k = r.revolute(), dim = r.dimension();
  std::vector<std::string> out;
  if (k >= 2 && r.prismatic() == 0 && r.base == "fixed") out.push_back("S^" + std::to_string(k));  // a sphere
  if (k >= 1 || r.base == "planar" || r.base == "spatial") out.push_back("R^" + std::to_string(dim));
  if (r.prismatic() > 0 || r.base_dim() > 0) out.push_back("T^" + std::to_string(dim));
  if (dim != 2) out.push_back("T^2");
  if (r.base == "planar") {
    out.push_back("R^2" + (k ? " x T^" + std::to_string(k) : std::string()));  // forgot the base turns
    out.push_back("SE(3)" + (k ? " x T^" + std::to_string(k) : std::string()));
  }
  if (r.wrist) out.push_back("T^3");  // forgot the wrist
  out.push_back("R^" + std::to_string(dim + 1));
  return out;
}

// ---------------------------------------------------------------------------------------------
// P8.

double unit_ball(int d) {
  if (d == 2) return kPiHere;
  if (d == 3) return 4.0 * kPiHere / 3.0;
  if (d == 4) return kPiHere * kPiHere / 2.0;
  FAIL("P8: d = ", d, " outside 2..4");
  return 0;
}

long long hundredths(double v) {
  const double h = v * 100.0;
  REQUIRE_MESSAGE(std::fabs(h - std::round(h)) < 1e-6, g17(v), " is not in hundredths");
  return std::llround(h);
}

// ---------------------------------------------------------------------------------------------
// P9: the visible area right of the wall, exactly: the visible height at x2 is
// max(0, min(1, yh) - max(0, yl)) with yl, yh the lines from (x, y) through the gap's ends; it
// is linear between the x2 where yl or yh crosses 0 or 1, so trapezoids there are exact.

struct Cone {
  double x, y, lo, hi;
  double s(double x2) const { return (x2 - x) / (0.5 - x); }
  double yl(double x2) const { return y + (lo - y) * s(x2); }
  double yh(double x2) const { return y + (hi - y) * s(x2); }
  double height(double x2) const { return std::max(0.0, std::min(1.0, yh(x2)) - std::max(0.0, yl(x2))); }
};

double visible_right_exact(const Cone& c) {
  std::vector<double> xs = {0.5, 1.0};
  for (double end : {c.lo, c.hi})
    for (double level : {0.0, 1.0})
      if (end != c.y) {
        const double x2 = c.x + (0.5 - c.x) * (level - c.y) / (end - c.y);
        if (x2 > 0.5 && x2 < 1.0) xs.push_back(x2);
      }
  std::sort(xs.begin(), xs.end());
  double area = 0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    area += 0.5 * (xs[i + 1] - xs[i]) * (c.height(xs[i]) + c.height(xs[i + 1]));
  return area;
}

double visible_right_midpoint(const Cone& c, int steps) {
  double area = 0;
  for (int i = 0; i < steps; ++i) area += c.height(0.5 + 0.5 * (i + 0.5) / steps);
  return area * 0.5 / steps;
}

// ---------------------------------------------------------------------------------------------
// P11 / P13: points, segments and convex polygons.

// The point of segment ab nearest p, and its parameter (clamped to [0, 1]; 0 when a == b).
P2 nearest_on_segment(P2 p, P2 a, P2 b, double* parameter = nullptr) {
  const P2 ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(p - a, ab) / len2 : 0.0;
  if (parameter) *parameter = t;
  t = std::min(1.0, std::max(0.0, t));
  return a + t * ab;
}

// Distance from a to the closed convex polygon (0 inside), and the nearest point b.
double polygon_distance(P2 a, const std::vector<P2>& poly, P2* nearest) {
  const std::size_t n = poly.size();
  double sign = 0;
  bool inside = true;
  for (std::size_t i = 0; i < n; ++i) {
    const double c = cross(poly[(i + 1) % n] - poly[i], a - poly[i]);
    if (c != 0 && sign == 0) sign = c > 0 ? 1 : -1;
    if (c * sign < 0) inside = false;
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const P2 b = nearest_on_segment(a, poly[i], poly[(i + 1) % n]);
    if (norm(a - b) < best) {
      best = norm(a - b);
      *nearest = b;
    }
  }
  if (inside) {
    *nearest = a;
    return 0.0;
  }
  return best;
}

bool convex(const std::vector<P2>& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  int sign = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double c = cross(poly[(i + 1) % n] - poly[i], poly[(i + 2) % n] - poly[(i + 1) % n]);
    if (c == 0) return false;
    const int s = c > 0 ? 1 : -1;
    if (sign == 0) sign = s;
    if (s != sign) return false;
  }
  return true;
}

// F_rep at a vertex: eta (1/rho - 1/rho0) (1/rho^2) grad rho inside the region of influence.
struct Repulsion {
  double rho = 0;
  P2 force;
};
Repulsion repulsion(P2 a, const std::vector<P2>& poly, double rho0, double eta) {
  Repulsion out;
  P2 b;
  out.rho = polygon_distance(a, poly, &b);
  if (out.rho <= rho0 && out.rho > 0) {
    const P2 grad = (1.0 / out.rho) * (a - b);
    out.force = (eta * (1.0 / out.rho - 1.0 / rho0) / (out.rho * out.rho)) * grad;
  }
  return out;
}

}  // namespace

// =============================================================================================

TEST_CASE("homework: the problem list, P1 to P13 in order, found by any spelling") {
  const auto& problems = csl::homework_problems();
  REQUIRE(problems.size() == 13);
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const csl::HomeworkProblem& p = problems[i];
    CHECK(p.id == "P" + std::to_string(i + 1));
    CHECK_FALSE(p.title.empty());
    CHECK_FALSE(p.lesson.empty());
    CHECK_FALSE(p.task.empty());
    CHECK(p.params.is_object());
  }
  const csl::HomeworkProblem* p10 = csl::find_homework_problem("P10");
  REQUIRE(p10 != nullptr);
  CHECK(p10->id == "P10");
  CHECK(csl::find_homework_problem("p10") == p10);
  CHECK(csl::find_homework_problem("10") == p10);
  CHECK(csl::find_homework_problem("P1") == &problems[0]);
  CHECK(csl::find_homework_problem("13") == &problems[12]);
  for (const char* bad : {"P0", "P14", "x", "", "P", "p", "0", "14", "P1x", "P-1", "P 1", "PP1", "100", "P100"})
    CHECK_MESSAGE(csl::find_homework_problem(bad) == nullptr, "found '", bad, "'");
}

TEST_CASE("homework: make_exercise refuses unknown problems and seeds past 2^53 - 1") {
  for (const char* bad : {"P0", "P14", "x", "", "p0"})
    CHECK_THROWS_AS(csl::make_exercise(bad, 0), std::invalid_argument);
  CHECK_THROWS_AS(csl::make_exercise("P10", csl::kMaxExerciseSeed + 1), std::invalid_argument);
  CHECK_THROWS_AS(csl::make_exercise("P1", std::numeric_limits<std::uint64_t>::max()), std::invalid_argument);
  CHECK(csl::kMaxExerciseSeed == 9007199254740991ULL);
  // The last seed works, and the id is read as find_homework_problem reads it.
  for (const auto& p : csl::homework_problems()) {
    const csl::Exercise e = csl::make_exercise(p.id, csl::kMaxExerciseSeed);
    CHECK(e.id == p.id);
    CHECK(e.seed == csl::kMaxExerciseSeed);
    CHECK(csl::exercise_to_json(e).at("seed").get<std::uint64_t>() == csl::kMaxExerciseSeed);
  }
  CHECK(csl::make_exercise("p10", 7).id == "P10");
  CHECK(csl::exercise_to_json(csl::make_exercise("10", 7)).dump() ==
        csl::exercise_to_json(csl::make_exercise("P10", 7)).dump());
}

TEST_CASE("homework: parse_answer_number reads decimals, multiples and fractions of pi, fractions") {
  const auto near = [](const char* text, double want) {
    const auto v = csl::parse_answer_number(text);
    REQUIRE_MESSAGE(v.has_value(), text);
    CHECK_MESSAGE(std::fabs(*v - want) <= 1e-15 * std::max(1.0, std::fabs(want)), text, " -> ", g17(*v));
  };
  near("1.5", 1.5);
  near("-0.25", -0.25);
  near(" 2 ", 2.0);
  near("pi", kPiHere);
  near("pi/2", kPiHere / 2);
  near("3pi/4", 3 * kPiHere / 4);
  near("0.5*pi", kPiHere / 2);
  near("2 pi", 2 * kPiHere);
  near("1/3", 1.0 / 3.0);
  near("\xCF\x80/3", kPiHere / 3);  // π/3
  // As students wrote them in a walk through the lab: a sum, a unit, a decimal comma.
  near("2*pi - 3.38", 2 * kPiHere - 3.38);
  near("pi - 0.2385", kPiHere - 0.2385);
  near("pi/2 + 0.1", kPiHere / 2 + 0.1);
  near("-1 - -2", 1.0);
  near("1e-3", 0.001);
  near("2.5E+2 - 1", 249.0);
  near("2.903 rad", 2.903);
  near("1 radian", 1.0);
  near("2,90", 2.9);
  near("0,741", 0.741);
  near("-12,5", -12.5);
  near("1/-2", -0.5);
  near("pi/-4", -kPiHere / 4);
  for (const char* bad : {"", "abc", "1e999", "nan", "inf", "1/0", "pi/", "/2", "1//2", "0x1p3", "+1",
                          "1 +", "1 - ", "- ", "1,2,3", "2.5,1", "6,127", "0 + 6,127", "6,127e0", "6,127 rad", "rad", "1 + abc"})
    CHECK_MESSAGE(!csl::parse_answer_number(bad).has_value(), "read '", bad, "'");
}

TEST_CASE("homework: an unreadable answer is told how to write it") {
  const csl::Exercise p10 = csl::make_exercise("P10", 7);
  csl::ExerciseCheck c = csl::check_exercise(p10, "166.3\xC2\xB0");
  CHECK_FALSE(c.readable);
  // 166.3 degrees in radians, by hand: 166.3 * 3.14159265 / 180 = 2.9024825.
  CHECK(c.explanation == "\"166.3\xC2\xB0\" is not a number the lab can read: answers here are in radians: 166.3 degrees is 2.90248.");
  c = csl::check_exercise(csl::make_exercise("P8", 3), "6,127");
  CHECK_FALSE(c.readable);
  CHECK(c.explanation.find("no thousands separators") != std::string::npos);
  // A distance (P11) has no radians: degrees there get the general hint.
  c = csl::check_exercise(csl::make_exercise("P11", 3), "30 deg");
  CHECK(c.explanation.find("radians") == std::string::npos);
}

TEST_CASE("homework: P1-P7, Q in notation: the robot each problem describes, right and wrong answers") {
  for (int problem = 1; problem <= 7; ++problem) {
    const std::string id = "P" + std::to_string(problem);
    std::set<std::string> robots;
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
      const csl::Exercise e = csl::make_exercise(id, seed);
      INFO(id, " seed ", seed, " robot '", e.robot, "'");
      check_common(e, id, seed, "notation");
      REQUIRE_FALSE(e.robot.empty());
      robots.insert(e.robot);
      const RobotHere r = read_robot(e.robot);
      check_problem_robot(id, r);
      // The lab reads the description as this file does.
      const csl::RobotDescription lab = csl::parse_robot_description(e.robot);
      CHECK(lab.joints == r.joints);
      CHECK(lab.spherical_wrist == r.wrist);

      // The expected answer the checker reveals afterwards: right, and not in the exercise.
      const std::string canonical = right_answers(r).front();
      const csl::ExerciseCheck shown = csl::check_exercise(e, canonical);
      REQUIRE(shown.expected.is_string());
      const std::string expected = shown.expected.get<std::string>();
      CHECK_FALSE(expected.empty());
      CHECK(csl::check_exercise(e, expected).correct);
      CHECK_MESSAGE(!contains(e.prompt, expected), "the prompt gives away ", expected);
      CHECK_MESSAGE(!contains(e.given.dump(), expected), "the given gives away ", expected);
      // The hint's examples ("e.g. A or B (...)") must not be right answers themselves.
      for (const std::string& example : hint_examples(e.format_hint))
        CHECK_MESSAGE(!csl::check_exercise(e, example).correct, "the format hint's example '", example,
                      "' is a right answer");

      for (const std::string& right : right_answers(r)) {
        csl::ExerciseCheck c;
        CHECK_NOTHROW(c = csl::check_exercise(e, right));
        CHECK_MESSAGE(c.correct, "rejected the right answer '", right, "': ", c.explanation);
        CHECK_FALSE(c.explanation.empty());
      }
      for (const std::string& wrong : wrong_answers(r)) {
        csl::ExerciseCheck w;
        CHECK_NOTHROW(w = csl::check_exercise(e, wrong));
        CHECK_MESSAGE(!w.correct, "accepted the wrong answer '", wrong, "'");
        CHECK_FALSE(w.explanation.empty());
      }
      if (seed < 5) {  // garbage, a few seeds (the parser is the same for all)
        for (const std::string& garbage : {std::string(""), std::string("abc"), std::string("1e999"),
                                           std::string("nan"), std::string(5000, '('), std::string(100000, 'T'),
                                           std::string("T^99999999999999999999"), std::string("\x01\xff")}) {
          csl::ExerciseCheck g;
          CHECK_NOTHROW(g = csl::check_exercise(e, garbage));
          CHECK_FALSE(g.correct);
          CHECK_FALSE(g.explanation.empty());
        }
      }
    }
    MESSAGE(id, ": ", robots.size(), " different robots over ", kSeeds, " seeds");
  }
}

TEST_CASE("homework: P3 and P4, two revolute joints: T^2, never S^2") {
  for (const char* id : {"P3", "P4"})
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
      const csl::Exercise e = csl::make_exercise(id, seed);
      if (read_robot(e.robot).joints != "RR") continue;
      CHECK(csl::check_exercise(e, "T^2").correct);
      CHECK(csl::check_exercise(e, "S^1 x S^1").correct);
      CHECK(csl::check_exercise(e, "(S^1)^2").correct);
      CHECK(csl::check_exercise(e, "T\xC2\xB2").correct);
      CHECK_FALSE(csl::check_exercise(e, "S^2").correct);
      CHECK_FALSE(csl::check_exercise(e, "R^2").correct);
      CHECK_FALSE(csl::check_exercise(e, "SO(3)").correct);
    }
}

TEST_CASE("homework: P8, the whole-cube tiling: n = ceil(ln(m/p) / (sigma r^d)), m = ceil(2/r)^d") {
  std::set<std::string> givens;
  std::map<int, int> dims;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const csl::Exercise e = csl::make_exercise("P8", seed);
    INFO("P8 seed ", seed, " given ", e.given.dump());
    check_common(e, "P8", seed, "integer");
    check_given_and_no_leak(e);
    givens.insert(e.given.dump());
    REQUIRE(e.given.at("d").is_number_integer());
    const int d = e.given.at("d").get<int>();
    const double r = num(e.given, "r"), p = num(e.given, "p");
    ++dims[d];
    REQUIRE((r > 0 && r < 1));
    REQUIRE((p > 0 && p < 1));
    // N = ceil(max(2, sqrt d) / r) = ceil(200 / (100 r)) for d <= 4, in integers.
    REQUIRE((d >= 2 && d <= 4));
    const long long rh = hundredths(r);
    const long long per_axis = (200 + rh - 1) / rh;
    const double m = std::pow(static_cast<double>(per_axis), d);
    const double sigma = unit_ball(d) / std::pow(2.0, d);
    const double rate = sigma * std::pow(r, d);
    const double n = std::ceil(std::log(m / p) / rate);
    CHECK_MESSAGE(e.answer == n, "answer ", g17(e.answer), " expected ", g17(n), " (N = ", per_axis, ")");
    // Within 0.5%: the whole numbers accepted are those within max(1, 0.005 n) (the lab may
    // keep the tolerance as its floor; it accepts the same integers).
    CHECK(std::floor(e.tolerance) == std::floor(std::max(1.0, 0.005 * n)));
    CHECK(e.tolerance <= std::max(1.0, 0.005 * n));
    check_checker_numeric(e);
    // Typical mistakes: the balls instead of samples, forgetting m, balls of radius r, not r/2.
    check_mistake(e, m, "m, the number of balls");
    check_mistake(e, std::ceil(std::log(1.0 / p) / rate), "ln(1/p): m forgotten");
    check_mistake(e, std::ceil(std::log(m / p) / (unit_ball(d) * std::pow(r, d))), "sigma without 2^d");
    check_mistake(e, std::ceil(std::log(m / p) / (sigma * std::pow(r / 2, d))), "r/2 in place of r");
  }
  MESSAGE("P8: ", givens.size(), " different exercises over ", kSeeds, " seeds; d=2: ", dims[2], " d=3: ", dims[3],
          " d=4: ", dims[4], "; ", mistake_report("P8"));
  CHECK(givens.size() > 100);
}

TEST_CASE("homework: P9, visibility through the gap: the exact area, every case of the cone") {
  std::set<std::string> givens;
  int clipped_top = 0, clipped_bottom = 0, clipped_both = 0, unclipped = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const csl::Exercise e = csl::make_exercise("P9", seed);
    INFO("P9 seed ", seed, " given ", e.given.dump());
    check_common(e, "P9", seed, "number");
    check_given_and_no_leak(e);
    givens.insert(e.given.dump());
    const double x = num(e.given, "x"), y = num(e.given, "y"), d = num(e.given, "d");
    REQUIRE((x >= 0 && x < 0.5));
    REQUIRE((y >= 0 && y <= 1));
    REQUIRE((d > 0 && d <= 1));
    const Cone cone{x, y, 0.5 - d / 2, 0.5 + d / 2};
    const double right = visible_right_exact(cone);
    CHECK(std::fabs(right - visible_right_midpoint(cone, 10000)) < 1e-6);
    const double expected = 0.5 + right;
    CHECK_MESSAGE(std::fabs(e.answer - expected) <= 1e-9, "answer ", g17(e.answer), " expected ", g17(expected));
    CHECK(e.tolerance == doctest::Approx(0.002));
    CHECK(expected >= 0.5);
    CHECK(expected <= 1.0);
    check_checker_numeric(e);

    const bool top = cone.yh(1.0) > 1.0, bottom = cone.yl(1.0) < 0.0;
    clipped_top += top && !bottom;
    clipped_bottom += bottom && !top;
    clipped_both += top && bottom;
    unclipped += !top && !bottom;
    // Typical mistakes: the left half alone, the right half's share alone, the cone unclipped,
    // the gap's height.
    const double unclipped_cone = 0.5 * 0.5 * ((cone.yh(0.5) - cone.yl(0.5)) + (cone.yh(1.0) - cone.yl(1.0)));
    check_mistake(e, 0.5, "the left half only");
    check_mistake(e, right, "the right half's part only");
    check_mistake(e, 0.5 + unclipped_cone, "the cone not clipped to the square");
    check_mistake(e, d, "the gap's height");
  }
  MESSAGE("P9: ", givens.size(), " different exercises; cone clipped at the top only: ", clipped_top,
          ", bottom only: ", clipped_bottom, ", both: ", clipped_both, ", neither: ", unclipped,
          "; ", mistake_report("P9"));
  CHECK(givens.size() > 200);
  CHECK(unclipped > 0);
  CHECK(clipped_top + clipped_bottom + clipped_both > 0);
}

TEST_CASE("homework: P10, the distance on S^1 by the modulus and by the dot product") {
  std::set<std::string> givens;
  int wrapped = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const csl::Exercise e = csl::make_exercise("P10", seed);
    INFO("P10 seed ", seed, " given ", e.given.dump());
    check_common(e, "P10", seed, "number");
    check_given_and_no_leak(e);
    givens.insert(e.given.dump());
    const double q1 = num(e.given, "q1"), q2 = num(e.given, "q2");
    double by_turns = std::numeric_limits<double>::infinity();
    for (int k = -3; k <= 3; ++k) by_turns = std::min(by_turns, std::fabs(q1 - q2 + 2 * kPiHere * k));
    const double cos_d = std::max(-1.0, std::min(1.0, std::cos(q1) * std::cos(q2) + std::sin(q1) * std::sin(q2)));
    const double by_dot = std::acos(cos_d);
    REQUIRE(std::fabs(q1 - q2) < 5 * kPiHere);  // k = -3..3 covers it
    CHECK(std::fabs(by_turns - by_dot) < 1e-6);
    CHECK_MESSAGE(std::fabs(e.answer - by_turns) <= 1e-12, "answer ", g17(e.answer), " expected ", g17(by_turns));
    CHECK(e.answer >= 0.0);
    CHECK(e.answer <= kPiHere);
    CHECK(e.tolerance == doctest::Approx(0.005));
    check_checker_numeric(e);
    wrapped += std::fabs(std::fabs(q1 - q2) - by_turns) > 0.01;
    check_mistake(e, std::fabs(q1 - q2), "|q1 - q2| without wrapping");
    check_mistake(e, 2 * kPiHere - by_turns, "the long way round");
    check_mistake(e, by_turns * 180 / kPiHere, "degrees");
    check_mistake(e, -by_turns, "a negative distance");
  }
  MESSAGE("P10: ", givens.size(), " different exercises; ", wrapped, " where |q1 - q2| is not the distance; ",
          mistake_report("P10"));
  CHECK(givens.size() > 200);
  CHECK(wrapped > 0);
}

TEST_CASE("homework: P11, segment to disk: the clamped projection and brute force, every special case") {
  std::set<std::string> givens;
  int interior = 0, at_p1 = 0, at_p2 = 0, degenerate = 0, intersecting = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const csl::Exercise e = csl::make_exercise("P11", seed);
    INFO("P11 seed ", seed, " given ", e.given.dump());
    check_common(e, "P11", seed, "number");
    check_given_and_no_leak(e);
    givens.insert(e.given.dump());
    const P2 p1 = point_at(e.given, "p1"), p2 = point_at(e.given, "p2"), q = point_at(e.given, "q");
    const double r = num(e.given, "r");
    REQUIRE(r >= 0);

    double t = 0;
    const P2 nearest = nearest_on_segment(q, p1, p2, &t);
    const double by_projection = norm(q - nearest);
    // Brute force: 200001 points of the segment.
    double best2 = std::numeric_limits<double>::infinity();
    const int steps = 200000;
    for (int i = 0; i <= steps; ++i) {
      const double s = static_cast<double>(i) / steps;
      const P2 diff = q - (p1 + s * (p2 - p1));
      best2 = std::min(best2, dot(diff, diff));
    }
    const double spacing = norm(p2 - p1) / steps;
    CHECK(std::sqrt(best2) >= by_projection - 1e-12);
    CHECK(std::sqrt(best2) <= by_projection + spacing / 2 + 1e-12);
    const double expected = std::max(0.0, by_projection - r);
    CHECK_MESSAGE(std::fabs(e.answer - expected) <= 1e-9, "answer ", g17(e.answer), " expected ", g17(expected));
    CHECK(e.tolerance == doctest::Approx(0.005));
    check_checker_numeric(e);

    const bool point = p1.x == p2.x && p1.y == p2.y;
    degenerate += point;
    at_p1 += !point && t <= 0;
    at_p2 += !point && t >= 1;
    interior += !point && t > 0 && t < 1;
    intersecting += by_projection <= r;
    // Typical mistakes: the centre's distance (r not subtracted), a negative distance when the
    // disk reaches the segment, the infinite line, the nearer endpoint.
    const P2 dir = p2 - p1;
    const double to_line = point ? norm(q - p1) : std::fabs(cross(dir, q - p1)) / norm(dir);
    check_mistake(e, by_projection, "r not subtracted");
    check_mistake(e, by_projection - r, "a negative distance");
    check_mistake(e, std::max(0.0, to_line - r), "the infinite line");
    check_mistake(e, std::max(0.0, std::min(norm(q - p1), norm(q - p2)) - r), "the nearer endpoint");
  }
  MESSAGE("P11: ", givens.size(), " different exercises; nearest point inside the segment: ", interior, ", at p1: ",
          at_p1, ", at p2: ", at_p2, ", p1 = p2: ", degenerate, ", the disk touches the segment: ", intersecting,
          "; ", mistake_report("P11"));
  CHECK(givens.size() > 200);
  CHECK(interior > 0);
  CHECK(at_p1 > 0);
  CHECK(at_p2 > 0);
  CHECK(degenerate > 0);
  CHECK(intersecting > 0);
}

namespace {

// P12 in integers: everything is in hundredths. Configuration i of N lies at
// (P (N-1) + i (Q - P)) / (N-1); it is in the closed disk when
// |P (N-1) + i (Q - P) - C (N-1)|^2 <= R^2 (N-1)^2.
struct P12Exact {
  long long px, py, qx, qy, cx, cy, r;
  bool inside(long long n, long long i) const {
    const long long m = n - 1;
    const long long x = px * m + i * (qx - px) - cx * m, y = py * m + i * (qy - py) - cy * m;
    return x * x + y * y <= r * r * m * m;
  }
  // The configurations next to the projection of the centre: if any configuration of N is in
  // the disk, one of these is (the line meets the disk in an interval around the projection).
  bool any_near_projection(long long n) const {
    const double dx = static_cast<double>(qx - px), dy = static_cast<double>(qy - py);
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? (static_cast<double>(cx - px) * dx + static_cast<double>(cy - py) * dy) / len2 : 0.0;
    const long long m = n - 1;
    const long long i0 = static_cast<long long>(std::floor(t * static_cast<double>(m)));
    for (long long i = i0 - 2; i <= i0 + 3; ++i)
      if (i >= 0 && i <= m && inside(n, i)) return true;
    return false;
  }
  bool any(long long n) const {
    for (long long i = 0; i < n; ++i)
      if (inside(n, i)) return true;
    return false;
  }
};

}  // namespace

TEST_CASE("homework: P12, the smallest N of the fixed-resolution check, by brute force in integers") {
  std::set<std::string> givens;
  std::map<long long, int> answers;
  int ties = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const csl::Exercise e = csl::make_exercise("P12", seed);
    INFO("P12 seed ", seed, " given ", e.given.dump());
    check_common(e, "P12", seed, "integer");
    check_given_and_no_leak(e);
    givens.insert(e.given.dump());
    const P2 p = point_at(e.given, "p"), q = point_at(e.given, "q"), c = point_at(e.given, "center");
    const double radius = num(e.given, "radius");
    REQUIRE(radius > 0);
    const P12Exact x{hundredths(p.x), hundredths(p.y), hundredths(q.x), hundredths(q.y),
                     hundredths(c.x), hundredths(c.y), hundredths(radius)};
    long long n = 2;
    while (n <= 1000000 && !x.any_near_projection(n)) ++n;
    REQUIRE_MESSAGE(n <= 1000000, "no N up to 10^6 sees the disk");
    if (n <= 400) {  // every configuration of every smaller N, no shortcut
      for (long long k = 2; k < n; ++k) CHECK_FALSE(x.any(k));
      CHECK(x.any(n));
    }
    CHECK_MESSAGE(e.answer == static_cast<double>(n), "answer ", g17(e.answer), " expected ", n);
    CHECK(e.tolerance == 0.0);
    check_checker_numeric(e);
    ++answers[n];
    // A configuration exactly on the circle at the answer: closed disk, it counts.
    for (long long i = 0; i < n; ++i) {
      const long long m = n - 1;
      const long long dx = x.px * m + i * (x.qx - x.px) - x.cx * m, dy = x.py * m + i * (x.qy - x.py) - x.cy * m;
      ties += dx * dx + dy * dy == x.r * x.r * m * m;
    }
    check_mistake(e, static_cast<double>(n - 1), "N - 1, the intervals");
    check_mistake(e, static_cast<double>(n + 1), "one more");
  }
  std::string spread;
  for (const auto& item : answers) spread += " " + std::to_string(item.first) + ":" + std::to_string(item.second);
  MESSAGE("P12: ", givens.size(), " different exercises; answers (N:count)", spread,
          "; configurations exactly on the circle at the answer: ", ties, "; ", mistake_report("P12"));
  CHECK(givens.size() > 200);
  CHECK(answers.size() > 3);
}

TEST_CASE("homework: P13, repulsion at the rectangle's vertices: rho, |F_rep|, the net force and torque") {
  std::set<std::string> givens;
  std::map<std::string, int> quantities;
  int in_influence = 0, out_of_influence = 0;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const csl::Exercise e = csl::make_exercise("P13", seed);
    INFO("P13 seed ", seed, " given ", e.given.dump());
    check_common(e, "P13", seed, "number");
    check_given_and_no_leak(e);
    givens.insert(e.given.dump());
    const json& g = e.given;
    REQUIRE((g.contains("vertices") && g.at("vertices").is_array() && g.at("vertices").size() == 4));
    std::vector<P2> a;
    for (const json& v : g.at("vertices")) a.push_back(point(v));
    const P2 center = point_at(g, "center");
    REQUIRE((g.contains("obstacle") && g.at("obstacle").is_array()));
    std::vector<P2> poly;
    for (const json& v : g.at("obstacle")) poly.push_back(point(v));
    REQUIRE(convex(poly));
    const double rho0 = num(g, "rho0"), eta = num(g, "eta");
    REQUIRE((rho0 > 0 && eta > 0));
    REQUIRE((g.contains("quantity") && g.at("quantity").is_string()));
    const std::string quantity = g.at("quantity").get<std::string>();
    ++quantities[quantity];

    std::vector<Repulsion> rep;
    P2 net;
    double torque = 0;
    for (const P2& v : a) {
      rep.push_back(repulsion(v, poly, rho0, eta));
      // A vertex inside the region of influence must be off the obstacle (F_rep is finite).
      CHECK_MESSAGE(rep.back().rho > 0, "a vertex touches the obstacle");
      (rep.back().rho <= rho0 ? in_influence : out_of_influence) += 1;
      net = net + rep.back().force;
      const P2 arm = v - center;
      torque += arm.x * rep.back().force.y - arm.y * rep.back().force.x;
    }
    double expected = 0;
    std::size_t k = 0;
    if (quantity == "rho" || quantity == "force") {
      REQUIRE(g.at("vertex").is_number_integer());
      const int vertex = g.at("vertex").get<int>();
      REQUIRE((vertex >= 1 && vertex <= 4));
      k = static_cast<std::size_t>(vertex - 1);
      expected = quantity == "rho" ? rep[k].rho : norm(rep[k].force);
    } else if (quantity == "fx") {
      expected = net.x;
    } else if (quantity == "fy") {
      expected = net.y;
    } else if (quantity == "torque") {
      expected = torque;
    } else {
      FAIL("unknown quantity ", quantity);
    }
    CHECK_MESSAGE(std::fabs(e.answer - expected) <= 1e-9 * std::max(1.0, std::fabs(expected)), "answer ", g17(e.answer),
                  " expected ", g17(expected), " (", quantity, ")");
    const double want_tolerance = std::max(1e-9, 0.01 * std::fabs(expected));
    CHECK_MESSAGE(std::fabs(e.tolerance - want_tolerance) <= 1e-6 * want_tolerance, "tolerance ", g17(e.tolerance));
    check_checker_numeric(e);

    // Typical mistakes: the sign of a force or torque, the distance to the nearest corner of
    // the obstacle instead of its boundary, F_rep without 1/rho^2, the torque about the origin.
    check_mistake(e, -e.answer, "the sign");
    if (quantity == "rho") {
      double corner = std::numeric_limits<double>::infinity();
      for (const P2& v : poly) corner = std::min(corner, norm(a[k] - v));
      check_mistake(e, corner, "the nearest corner, not the nearest point");
    } else if (quantity == "force" && rep[k].rho <= rho0) {
      check_mistake(e, eta * (1.0 / rep[k].rho - 1.0 / rho0), "1/rho^2 forgotten");
    } else if (quantity == "torque") {
      double about_origin = 0;
      for (std::size_t i = 0; i < 4; ++i) about_origin += a[i].x * rep[i].force.y - a[i].y * rep[i].force.x;
      check_mistake(e, about_origin, "the torque about the origin");
    }
  }
  std::string spread;
  for (const auto& item : quantities) spread += " " + item.first + ":" + std::to_string(item.second);
  MESSAGE("P13: ", givens.size(), " different exercises; quantities", spread, "; vertices within rho0: ",
          in_influence, ", beyond: ", out_of_influence, "; ", mistake_report("P13"));
  CHECK(givens.size() > 200);
  for (const char* q : {"rho", "force", "fx", "fy", "torque"}) CHECK_MESSAGE(quantities[q] > 0, "no exercise asks ", q);
  CHECK(in_influence > 0);
  CHECK(out_of_influence > 0);
}

TEST_CASE("homework: the answer as the review prints it, never a double's last bits") {
  // Built by hand, so the numbers are known here and not taken from the code under test.
  csl::Exercise e;
  e.answer_format = "number";
  e.answer = std::nextafter(1.44, 2.0);  // printed raw, this is what the review said: "1.4400000000000002"
  e.tolerance = 0.005;
  CHECK(csl::exercise_answer_text(e) == "1.44 (within 0.005)");
  e.answer = 2.0 / 3.0;
  e.tolerance = 0.0;
  CHECK(csl::exercise_answer_text(e) == "0.666667");
  e.answer = 12345678.0;  // six significant digits: the lab's, not a rounding the student cannot see
  CHECK(csl::exercise_answer_text(e) == "1.23457e+07");
  e.answer_format = "integer";
  e.answer = 6.9999999;
  CHECK(csl::exercise_answer_text(e) == "7");
  e.tolerance = 35.0;  // P8's band: a whole number's tolerance is said once it is a whole step
  CHECK(csl::exercise_answer_text(e) == "7 (within 35)");
  // Q in the course's notation for P1-P7: the notation checker's canonical form.
  const csl::Exercise p3 = csl::make_exercise("P3", 1);
  CHECK(csl::exercise_answer_text(p3) == csl::check_exercise(p3, "").expected.get<std::string>());
  // A wrong answer is told the same text: a whole number is not "7 (within 0.5)" there either.
  e.tolerance = 0.5;
  CHECK(csl::check_exercise(e, "9").explanation.rfind("Not quite: you wrote 9, the answer is 7.", 0) == 0);
  e.answer_format = "number";
  e.answer = 1.44;
  e.tolerance = 0.005;
  CHECK(csl::check_exercise(e, "2").explanation.rfind("Not quite: you wrote 2, the answer is 1.44 (within 0.005).", 0) == 0);
}

TEST_CASE("homework: a format hint is its form, its tolerance and its note, each said once") {
  csl::Exercise e;
  csl::set_format_hint(e, "radians, e.g. 1.57 or pi/2", "0.005");
  CHECK(e.format_hint == "radians, e.g. 1.57 or pi/2 (within 0.005)");
  csl::set_format_hint(e, "a whole number N >= 2", "", "both ends counted");
  CHECK(e.format_hint == "a whole number N >= 2 (both ends counted)");
  csl::set_format_hint(e, "a number", "1%", "0 if no force acts");
  CHECK(e.format_hint == "a number (within 1%; 0 if no force acts)");
  csl::set_format_hint(e, "Q", "");
  CHECK(e.format_hint == "Q");
  // Every problem's hint is made so: its tolerance is in the one place an assignment replaces.
  for (const csl::HomeworkProblem& p : csl::homework_problems()) {
    const csl::Exercise x = csl::make_exercise(p.id, 4);
    CHECK_MESSAGE(x.format_hint.rfind(x.answer_form, 0) == 0, p.id, ": ", x.format_hint);
    CHECK_MESSAGE((x.format_hint.find("within") != std::string::npos) == !x.within.empty(), p.id, ": ", x.format_hint);
  }
}

TEST_CASE("homework: a wrong try's feedback tells what went wrong, not the answer") {
  const auto typed = [](double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return std::string(text);
  };
  int numeric = 0, notation = 0;
  for (const csl::HomeworkProblem& p : csl::homework_problems()) {
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
      const csl::Exercise e = csl::make_exercise(p.id, seed);
      if (e.answer_format == "notation") {
        const std::string expected = csl::check_exercise(e, "").expected.get<std::string>();
        for (const char* wrong : {"R^7", "S^1", "SE(3) x R^5"}) {
          if (std::string(wrong).find(expected) != std::string::npos) continue;
          const csl::ExerciseCheck c = csl::check_exercise(e, wrong);
          if (c.correct) continue;
          ++notation;
          CHECK_MESSAGE(c.feedback.find(expected) == std::string::npos, p.id, " seed ", seed, ": ", c.feedback);
          CHECK(c.feedback.rfind("Not quite", 0) == 0);
          CHECK(c.explanation.rfind("Not quite: ", 0) == 0);  // the checker's reasons, then the solution
        }
        continue;
      }
      // Far off: beyond the tolerance and any typical mistake's value.
      const double off = e.answer + 7.0 * std::max({e.tolerance, 0.01 * std::fabs(e.answer), 1.0}) + 0.123;
      const csl::ExerciseCheck c = csl::check_exercise(e, typed(off));
      REQUIRE_FALSE(c.correct);
      ++numeric;
      CHECK_MESSAGE(c.feedback.find("the answer is") == std::string::npos, p.id, " seed ", seed, ": ", c.feedback);
      CHECK(c.feedback.rfind("Not quite: you wrote ", 0) == 0);
      CHECK_MESSAGE(c.explanation.find("the answer is " + csl::exercise_answer_text(e)) != std::string::npos, c.explanation);
      // Right: the feedback is the verdict line of the explanation, the worked solution follows.
      const csl::ExerciseCheck right = csl::check_exercise(e, typed(e.answer));
      CHECK(right.correct);
      CHECK(right.explanation.rfind(right.feedback + "\n", 0) == 0);
    }
  }
  CHECK(numeric >= 150);
  CHECK(notation >= 100);
  // A typical mistake is told its reason, and says so (the card counts its solution as shown).
  const csl::Exercise p10 = csl::make_exercise("P10", 7);
  REQUIRE_FALSE(p10.traps.empty());
  const csl::ExerciseCheck mistake = csl::check_exercise(p10, typed(p10.traps.front().value));
  CHECK_FALSE(mistake.correct);
  CHECK(mistake.typical_mistake);
  CHECK(mistake.feedback.find(p10.traps.front().why) != std::string::npos);
  CHECK_FALSE(csl::check_exercise(p10, typed(p10.answer + 0.5 * (p10.answer < 1 ? 1 : -1))).typical_mistake);
  // An empty or unreadable Q is no try: told what could not be read, never Q itself.
  const csl::Exercise p3 = csl::make_exercise("P3", 2);
  REQUIRE(p3.worked.rfind("Q = ", 0) == 0);  // the worked solution names Q first
  for (const char* unreadable : {"", "asdf", "R^"}) {
    const csl::ExerciseCheck u = csl::check_exercise(p3, unreadable);
    CHECK_FALSE(u.readable);
    CHECK_MESSAGE(u.explanation.find("Q = ") == std::string::npos, unreadable, ": ", u.explanation);
    CHECK(u.explanation == u.feedback);
  }
}
