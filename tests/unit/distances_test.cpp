// The worked derivations of P10 and P11 (core/teaching/distances.hpp) against oracles written here from
// scratch: the S^1 distance as the least |q2 - q1 + 2 pi k| over whole turns k, the rotation
// form with the C library's cos, sin and atan2 (not the lab's own), and the segment-to-disk
// distance as a minimum over 100001 points of the segment, its case from the law of cosines.
// Then every special case by hand. Runs natively and in wasm.
//
// Tolerances. Angles are at most 1000 rad, whose spacing as doubles is 1.1e-13: the modulus and
// the shifted differences err by a few of those, so 1e-11 (kAngleTol). The arccos form loses
// half the digits near 0 and pi (arccos(1 - e) ~ sqrt(2e)): its tolerance grows as 1 / sin d,
// capped at 1e-7. Segment coordinates are within 20 of each other: a few ulps of 20 (3.6e-15)
// each, so 1e-12 (kTol); the sampled minimum adds its bound (half a sample step) on top.
#include "core/teaching/distances.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/rng.hpp"
#include "core/geometry/geometry.hpp"

using csl::Vec2;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAngleTol = 1e-11;
constexpr double kTol = 1e-12;

// The S^1 distance by brute force: the shortest of q2 - q1 shifted by whole turns.
double s1_oracle(double q1, double q2) {
  double best = std::fabs(q2 - q1);
  for (int k = -400; k <= 400; ++k) best = std::min(best, std::fabs(q2 - q1 + 2.0 * kPi * k));
  return best;
}

// The angle between the unit vectors of q1 and q2 with the C library's functions.
double rotation_oracle(double q1, double q2) {
  const double c = std::cos(q1) * std::cos(q2) + std::sin(q1) * std::sin(q2);
  const double s = std::cos(q1) * std::sin(q2) - std::sin(q1) * std::cos(q2);
  return std::fabs(std::atan2(s, c));
}

double dist(const Vec2& a, const Vec2& b) {
  const double dx = a.x() - b.x(), dy = a.y() - b.y();
  return std::sqrt(dx * dx + dy * dy);
}

// The least distance from q to 100001 evenly spaced points of p1p2, and the parameter of the
// nearest sample. The true minimum is at most half a step (|p2 - p1| / 200000) below it.
struct Sampled {
  double distance;
  double s;
};
Sampled sampled(const Vec2& p1, const Vec2& p2, const Vec2& q) {
  constexpr int kN = 100000;
  Sampled best{dist(q, p1), 0.0};
  for (int i = 1; i <= kN; ++i) {
    const double s = static_cast<double>(i) / kN;
    const Vec2 x(p1.x() + s * (p2.x() - p1.x()), p1.y() + s * (p2.y() - p1.y()));
    const double d = dist(q, x);
    if (d < best.distance) best = {d, s};
  }
  return best;
}

// (b - a) x (c - a): 0 when c is on the line through a and b.
double orient_oracle(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

double sq(const Vec2& a, const Vec2& b) {
  return (a.x() - b.x()) * (a.x() - b.x()) + (a.y() - b.y()) * (a.y() - b.y());
}

}  // namespace

TEST_CASE("distances: P10 on random angles agrees with whole-turn brute force and the C library") {
  csl::Rng rng(20261);
  int general = 0, wraps = 0;
  for (int i = 0; i < 20000; ++i) {
    // Mostly within a few turns, a fifth anywhere in the lab's range of +-1000 rad.
    const double span = i % 5 == 0 ? 1000.0 : 8.0;
    const double q1 = rng.uniform(-span, span), q2 = rng.uniform(-span, span);
    const csl::S1DistanceReport r = csl::s1_distance_report(q1, q2);
    const double d = s1_oracle(q1, q2);
    CAPTURE(q1);
    CAPTURE(q2);
    CHECK(r.q1 == q1);
    CHECK(r.q2 == q2);
    // The shown value and both derivations.
    CHECK(std::fabs(r.distance - d) <= kAngleTol);
    CHECK(std::fabs(r.modular_distance - d) <= kAngleTol);
    CHECK(std::fabs(r.rotation_distance - rotation_oracle(q1, q2)) <= kAngleTol);
    CHECK(std::fabs(r.rotation_distance - d) <= kAngleTol);
    const double sine = std::sin(d);
    CHECK(std::fabs(r.arccos_distance - d) <= std::min(1e-7, kAngleTol + 4e-15 / std::max(sine, 1e-300)));
    // The steps of (a).
    CHECK(r.raw_difference == std::fabs(q1 - q2));
    CHECK(r.modulus >= 0.0);
    CHECK(r.modulus < 2.0 * kPi);
    CHECK(s1_oracle(r.modulus, r.raw_difference) <= kAngleTol);  // the same up to whole turns
    CHECK(std::fabs(r.modulus + r.other_way - 2.0 * kPi) <= kAngleTol);
    // The steps of (b).
    CHECK(std::fabs(r.cos1 - std::cos(q1)) <= 1e-13);
    CHECK(std::fabs(r.sin2 - std::sin(q2)) <= 1e-13);
    CHECK(std::fabs(r.dot - std::cos(d)) <= 1e-12);
    // The wrapped angles: in [0, 2pi), the same directions.
    CHECK(r.wrapped1 >= 0.0);
    CHECK(r.wrapped1 < 2.0 * kPi);
    CHECK(r.wrapped2 >= 0.0);
    CHECK(r.wrapped2 < 2.0 * kPi);
    CHECK(s1_oracle(r.wrapped1, q1) <= kAngleTol);
    CHECK(s1_oracle(r.wrapped2, q2) <= kAngleTol);
    // The shorter turn: as long as the distance, and it lands on q2.
    CHECK(std::fabs(std::fabs(r.signed_turn) - d) <= kAngleTol);
    CHECK(s1_oracle(q1 + r.signed_turn, q2) <= kAngleTol);
    // Case, and whether the short way passes 0: the wrapped angles more than pi apart.
    const double w1 = std::fmod(std::fmod(q1, 2.0 * kPi) + 2.0 * kPi, 2.0 * kPi);
    const double w2 = std::fmod(std::fmod(q2, 2.0 * kPi) + 2.0 * kPi, 2.0 * kPi);
    if (d > 1e-6 && d < kPi - 1e-6) {
      CHECK(r.kind == csl::S1Case::General);
      ++general;
      if (std::fabs(std::fabs(w1 - w2) - kPi) > 1e-6 && std::min(w1, w2) > 1e-6 && std::max(w1, w2) < 2 * kPi - 1e-6) {
        CHECK(r.wraps_around == (std::fabs(w1 - w2) > kPi));
        wraps += r.wraps_around;
      }
    }
  }
  CHECK(general > 19000);
  CHECK(wraps > 5000);  // both kinds were seen
}

TEST_CASE("distances: P10's special cases, by hand") {
  SUBCASE("the handout's picture: the short way crosses 0") {
    const csl::S1DistanceReport r = csl::s1_distance_report(0.5, 5.8);
    CHECK(r.kind == csl::S1Case::General);
    CHECK(std::string(csl::s1_case_name(r.kind)) == "general");
    CHECK(r.raw_difference == doctest::Approx(5.3).epsilon(1e-15));
    CHECK(r.modulus == doctest::Approx(5.3).epsilon(1e-15));
    CHECK(r.distance == doctest::Approx(2 * kPi - 5.3).epsilon(1e-14));
    CHECK(r.modular_distance == doctest::Approx(2 * kPi - 5.3).epsilon(1e-14));
    CHECK(r.signed_turn == doctest::Approx(-(2 * kPi - 5.3)).epsilon(1e-14));  // clockwise, through 0
    CHECK(r.wraps_around);
  }
  SUBCASE("no wrap: the plain difference is the distance") {
    const csl::S1DistanceReport r = csl::s1_distance_report(1.0, 2.5);
    CHECK(r.distance == doctest::Approx(1.5).epsilon(1e-15));
    CHECK(r.signed_turn == doctest::Approx(1.5).epsilon(1e-15));
    CHECK(!r.wraps_around);
  }
  SUBCASE("equal angles, also whole turns apart") {
    for (const auto& pair : {std::pair{0.7, 0.7}, std::pair{0.0, 2 * kPi}, std::pair{1.0, 1.0 + 4 * kPi},
                             std::pair{-3.0, -3.0 - 6 * kPi}, std::pair{0.0, 0.0}}) {
      const double a = pair.first, b = pair.second;  // not a structured binding: CAPTURE takes them in a lambda
      const csl::S1DistanceReport r = csl::s1_distance_report(a, b);
      CAPTURE(a);
      CAPTURE(b);
      CHECK(r.kind == csl::S1Case::Equal);
      CHECK(std::string(csl::s1_case_name(r.kind)) == "equal");
      CHECK(r.distance <= 1e-14);
      CHECK(r.modular_distance <= 1e-14);
      CHECK(r.rotation_distance <= 1e-14);
      CHECK(r.arccos_distance <= 5e-8);  // arccos(1 - rounding): about its square root
      CHECK(!r.wraps_around);
      CHECK(std::fabs(r.wrapped1 - r.wrapped2) <= 1e-14);
    }
  }
  SUBCASE("antipodal: d = pi, both arcs equally short") {
    for (const auto& pair : {std::pair{0.0, kPi}, std::pair{-kPi / 2, kPi / 2}, std::pair{0.3, 0.3 + 3 * kPi},
                             std::pair{5.0, 5.0 - kPi}}) {
      const double a = pair.first, b = pair.second;  // not a structured binding: CAPTURE takes them in a lambda
      const csl::S1DistanceReport r = csl::s1_distance_report(a, b);
      CAPTURE(a);
      CAPTURE(b);
      CHECK(r.kind == csl::S1Case::Antipodal);
      CHECK(std::string(csl::s1_case_name(r.kind)) == "antipodal");
      CHECK(r.distance == doctest::Approx(kPi).epsilon(1e-14));
      CHECK(r.other_way == doctest::Approx(kPi).epsilon(1e-13));
      CHECK(r.dot == doctest::Approx(-1.0).epsilon(1e-14));
      CHECK(r.arccos_distance == doctest::Approx(kPi).epsilon(1e-7));
      CHECK(std::fabs(r.signed_turn) == doctest::Approx(kPi).epsilon(1e-14));
    }
    // An exact half turn is -pi in the lab's chart: its straight line turns clockwise.
    CHECK(csl::s1_distance_report(0.0, kPi).signed_turn == -kPi);
    CHECK(csl::s1_distance_report(-kPi / 2, kPi / 2).signed_turn == -kPi);
  }
  SUBCASE("just off the special cases is general") {
    CHECK(csl::s1_distance_report(0.0, 1e-6).kind == csl::S1Case::General);
    CHECK(csl::s1_distance_report(0.0, kPi - 1e-6).kind == csl::S1Case::General);
    CHECK(csl::s1_distance_report(0.0, 1e-10).kind == csl::S1Case::Equal);
    CHECK(csl::s1_distance_report(0.0, kPi + 1e-10).kind == csl::S1Case::Antipodal);
  }
  SUBCASE("angles outside [0, 2pi) wrap") {
    const csl::S1DistanceReport r = csl::s1_distance_report(7.0, -1.0);
    CHECK(r.wrapped1 == doctest::Approx(7.0 - 2 * kPi).epsilon(1e-14));
    CHECK(r.wrapped2 == doctest::Approx(2 * kPi - 1.0).epsilon(1e-14));
    CHECK(r.raw_difference == 8.0);
    CHECK(r.modulus == doctest::Approx(8.0 - 2 * kPi).epsilon(1e-14));
    CHECK(r.distance == doctest::Approx(8.0 - 2 * kPi).epsilon(1e-14));
    CHECK(r.wraps_around);  // 0.717 back to 5.283 the short way passes 0
    // A direction a hair below 2pi is shown as 0, never as 2pi.
    const csl::S1DistanceReport z = csl::s1_distance_report(-1e-17, 0.0);
    CHECK(z.wrapped1 >= 0.0);
    CHECK(z.wrapped1 < 2 * kPi);
  }
}

TEST_CASE("distances: P11 on random segments and disks agrees with 100001 samples and the law of cosines") {
  csl::Rng rng(11011);
  int cases[4] = {0, 0, 0, 0};
  int meets = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 p1(rng.uniform(-10, 10), rng.uniform(-10, 10));
    // Some segments short, some a single point.
    Vec2 p2(rng.uniform(-10, 10), rng.uniform(-10, 10));
    if (i % 10 == 1) p2 = p1 + Vec2(rng.uniform(-1e-3, 1e-3), rng.uniform(-1e-3, 1e-3));
    if (i % 10 == 2) p2 = p1;
    const Vec2 q(rng.uniform(-10, 10), rng.uniform(-10, 10));
    const double r = i % 7 == 0 ? 0.0 : rng.uniform(0, 6);
    const csl::SegmentDiskReport s = csl::segment_disk_report(p1, p2, q, r);
    CAPTURE(i);
    const Sampled b = sampled(p1, p2, q);
    const double step = dist(p1, p2) / 100000;
    // The closest point is on the segment and at least as close as every sample, by at most
    // half a step less than the best of them; at one of the two samples around it.
    CHECK(s.centre_distance <= b.distance + kTol);
    CHECK(s.centre_distance >= b.distance - step / 2 - kTol);
    CHECK(std::fabs(dist(q, s.closest) - s.centre_distance) <= kTol);
    CHECK(s.t >= 0.0);
    CHECK(s.t <= 1.0);
    // (Near the minimum of a short segment the samples' distances differ by less than their
    // rounding: the nearest sample is then not well defined.)
    if (dist(p1, p2) > 1.0) CHECK(std::fabs(s.t - b.s) <= 1.0001e-5);
    if (p1 != p2) {
      CHECK(dist(s.closest, Vec2(p1.x() + s.t * (p2.x() - p1.x()), p1.y() + s.t * (p2.y() - p1.y()))) <= kTol);
    }
    // P11's answer, the signed value, and the lab's clearance function.
    const double want = std::max(0.0, b.distance - r);
    CHECK(s.distance <= want + kTol);
    CHECK(s.distance >= want - step / 2 - kTol);
    CHECK(s.signed_distance <= b.distance - r + kTol);
    CHECK(s.signed_distance >= b.distance - r - step / 2 - kTol);
    CHECK(std::fabs(s.lab_clearance - s.signed_distance) <= kTol);
    if (b.distance - r > step + kTol) CHECK(!s.meets);
    if (b.distance - r < -kTol) CHECK(s.meets);
    CHECK(s.meets == (s.distance == 0.0));
    meets += s.meets;
    // The projection: q - foot is perpendicular to the segment, and the foot is on its line.
    const Vec2 d = p2 - p1;
    CHECK(s.direction == d);
    CHECK(s.length_squared == doctest::Approx(d.x() * d.x() + d.y() * d.y()).epsilon(1e-15));
    if (p1 == p2) {
      CHECK(s.where == csl::SegmentDiskCase::Degenerate);
      CHECK(std::isnan(s.t_raw));
      CHECK(s.closest == p1);
      CHECK(s.centre_distance == doctest::Approx(dist(q, p1)).epsilon(1e-15));
      ++cases[3];
      continue;
    }
    const Vec2 off = q - s.foot;
    CHECK(std::fabs(off.x() * d.x() + off.y() * d.y()) <= 1e-9 * (1 + d.norm() * (dist(q, p1) + d.norm())));
    CHECK(std::fabs(orient_oracle(p1, p2, s.foot)) <= 1e-9 * (1 + d.squaredNorm() * (1 + std::fabs(s.t_raw))));
    // The case from the law of cosines: the angle at p1 (or p2) of the triangle p1 p2 q is
    // obtuse or right exactly when the nearest point is that endpoint.
    const double a1 = sq(q, p1), a2 = sq(q, p2), l = sq(p1, p2);
    const double margin = 1e-9 * (a1 + a2 + l);
    if (a2 > a1 + l + margin) {
      CHECK(s.where == csl::SegmentDiskCase::AtP1);
      CHECK(s.t == 0.0);
      CHECK(s.closest == p1);
    } else if (a1 > a2 + l + margin) {
      CHECK(s.where == csl::SegmentDiskCase::AtP2);
      CHECK(s.t == 1.0);
      CHECK(s.closest == p2);
    } else if (a2 < a1 + l - margin && a1 < a2 + l - margin) {
      CHECK(s.where == csl::SegmentDiskCase::Interior);
      CHECK(s.t == s.t_raw);
    }
    ++cases[static_cast<int>(s.where)];
  }
  for (int c : cases) CHECK(c > 150);  // each case many times
  CHECK(meets > 150);
  CHECK(meets < 1850);
}

TEST_CASE("distances: P11's special cases, by hand") {
  const Vec2 a(0, 0), b(2, 0);
  SUBCASE("the foot inside the segment") {
    const csl::SegmentDiskReport s = csl::segment_disk_report(a, b, Vec2(1, 1), 0.5);
    CHECK(s.where == csl::SegmentDiskCase::Interior);
    CHECK(std::string(csl::segment_disk_case_name(s.where)) == "interior");
    CHECK(s.dot == 2.0);
    CHECK(s.length_squared == 4.0);
    CHECK(s.t_raw == 0.5);
    CHECK(s.t == 0.5);
    CHECK(s.closest == Vec2(1, 0));
    CHECK(s.foot == Vec2(1, 0));
    CHECK(s.centre_distance == 1.0);
    CHECK(s.distance == 0.5);
    CHECK(s.signed_distance == 0.5);
    CHECK(s.lab_clearance == 0.5);
    CHECK(!s.meets);
  }
  SUBCASE("before p1: clamped to p1") {
    const csl::SegmentDiskReport s = csl::segment_disk_report(a, b, Vec2(-1, 1), 0.25);
    CHECK(s.where == csl::SegmentDiskCase::AtP1);
    CHECK(std::string(csl::segment_disk_case_name(s.where)) == "p1");
    CHECK(s.t_raw == -0.5);
    CHECK(s.t == 0.0);
    CHECK(s.foot == Vec2(-1, 0));
    CHECK(s.closest == a);
    CHECK(s.centre_distance == doctest::Approx(std::sqrt(2.0)).epsilon(1e-15));
    CHECK(s.distance == doctest::Approx(std::sqrt(2.0) - 0.25).epsilon(1e-15));
  }
  SUBCASE("beyond p2: clamped to p2") {
    const csl::SegmentDiskReport s = csl::segment_disk_report(a, b, Vec2(3, -1), 0.0);
    CHECK(s.where == csl::SegmentDiskCase::AtP2);
    CHECK(std::string(csl::segment_disk_case_name(s.where)) == "p2");
    CHECK(s.t_raw == 1.5);
    CHECK(s.t == 1.0);
    CHECK(s.closest == b);
    CHECK(s.distance == doctest::Approx(std::sqrt(2.0)).epsilon(1e-15));
  }
  SUBCASE("t* exactly 0 or 1 counts as the endpoint") {
    const csl::SegmentDiskReport s0 = csl::segment_disk_report(a, b, Vec2(0, 1), 0.0);
    CHECK(s0.where == csl::SegmentDiskCase::AtP1);
    CHECK(s0.t_raw == 0.0);
    CHECK(s0.distance == 1.0);
    const csl::SegmentDiskReport s1 = csl::segment_disk_report(a, b, Vec2(2, -1), 0.0);
    CHECK(s1.where == csl::SegmentDiskCase::AtP2);
    CHECK(s1.t_raw == 1.0);
    CHECK(s1.distance == 1.0);
  }
  SUBCASE("degenerate segment: the distance to p1") {
    const Vec2 p(1, 1);
    const csl::SegmentDiskReport s = csl::segment_disk_report(p, p, Vec2(4, 5), 2.0);
    CHECK(s.where == csl::SegmentDiskCase::Degenerate);
    CHECK(std::string(csl::segment_disk_case_name(s.where)) == "degenerate");
    CHECK(s.length_squared == 0.0);
    CHECK(std::isnan(s.t_raw));
    CHECK(s.t == 0.0);
    CHECK(s.closest == p);
    CHECK(s.centre_distance == 5.0);
    CHECK(s.distance == 3.0);
    CHECK(s.lab_clearance == 3.0);
    const csl::SegmentDiskReport inside = csl::segment_disk_report(p, p, Vec2(1, 1.5), 1.0);
    CHECK(inside.meets);
    CHECK(inside.distance == 0.0);
    CHECK(inside.signed_distance == -0.5);
  }
  SUBCASE("meeting the disk: distance 0, the signed value says how deep") {
    const csl::SegmentDiskReport s = csl::segment_disk_report(a, b, Vec2(1, 0.25), 0.5);
    CHECK(s.meets);
    CHECK(s.distance == 0.0);
    CHECK(s.signed_distance == -0.25);
    CHECK(s.lab_clearance == -0.25);
    // Touching is meeting: the disk is closed.
    const csl::SegmentDiskReport t = csl::segment_disk_report(a, b, Vec2(1, 0.5), 0.5);
    CHECK(t.meets);
    CHECK(t.distance == 0.0);
    CHECK(t.signed_distance == 0.0);
    // An endpoint inside the disk while the projection falls outside the segment.
    const csl::SegmentDiskReport e = csl::segment_disk_report(a, b, Vec2(-0.1, 0.05), 0.2);
    CHECK(e.where == csl::SegmentDiskCase::AtP1);
    CHECK(e.meets);
    CHECK(e.signed_distance == doctest::Approx(std::hypot(0.1, 0.05) - 0.2).epsilon(1e-15));
  }
  SUBCASE("r = 0: a point, met only on the segment itself") {
    CHECK(csl::segment_disk_report(a, b, Vec2(1.5, 0), 0.0).meets);
    CHECK(csl::segment_disk_report(a, b, Vec2(1.5, 0), 0.0).distance == 0.0);
    CHECK(!csl::segment_disk_report(a, b, Vec2(1.5, 1e-9), 0.0).meets);
  }
  SUBCASE("the lesson's default") {
    const csl::SegmentDiskReport s = csl::segment_disk_report(Vec2(0.2, 0.3), Vec2(0.8, 0.6), Vec2(0.55, 0.2), 0.1);
    CHECK(s.where == csl::SegmentDiskCase::Interior);
    CHECK(s.t_raw == doctest::Approx(0.4).epsilon(1e-14));
    CHECK(s.closest.x() == doctest::Approx(0.44).epsilon(1e-14));
    CHECK(s.closest.y() == doctest::Approx(0.42).epsilon(1e-14));
    CHECK(s.centre_distance == doctest::Approx(std::sqrt(0.0605)).epsilon(1e-14));
    CHECK(s.distance == doctest::Approx(std::sqrt(0.0605) - 0.1).epsilon(1e-14));
  }
}
