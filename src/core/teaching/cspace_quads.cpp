#include "core/teaching/cspace_quads.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/base/angles.hpp"

namespace csl {
namespace {

// How far a paired interval end may move across a strip before the pairing is not trusted (an
// interval that ends while another begins would pair the two).
constexpr double kMaxShift = 1.0 / 24.0;  // of a turn
constexpr int kMaxHalvings = 3;

// The ends of the blocked intervals at u as v in [0, 1], with 0 and 1 around them: the spans
// between consecutive entries alternate free, blocked, free, ...
std::vector<double> cuts(const ArmCSpaceMap& map, double u, std::vector<AngleInterval>& scratch) {
  map.blocked_theta2(wrap_angle(-kPi + kTwoPi * u), scratch);
  std::vector<double> v{0.0};
  for (const AngleInterval& b : scratch) {
    v.push_back((b.lo + kPi) / kTwoPi);
    v.push_back((b.hi + kPi) / kTwoPi);
  }
  v.push_back(1.0);
  return v;
}

bool paired(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(std::fabs(a[k] - b[k]) <= kMaxShift)) return false;  // NaN too
  return true;
}

// Cuts a and b made equal in length where they differ by pieces that begin or end inside the
// strip: an interval at one edge with none overlapping it at the other ends there in a point at
// its middle (the tip of a C-obstacle's piece). False where an interval at one edge overlaps
// two at the other (pieces that merge or split) or a paired end moves too far.
bool pair_with_tips(const std::vector<double>& a, const std::vector<double>& b, std::vector<double>& ta,
                    std::vector<double>& tb) {
  struct Interval {
    double lo, hi;
  };
  const auto intervals = [](const std::vector<double>& cuts) {
    std::vector<Interval> out;
    for (std::size_t k = 1; k + 2 < cuts.size(); k += 2) out.push_back({cuts[k], cuts[k + 1]});
    return out;
  };
  const std::vector<Interval> A = intervals(a), B = intervals(b);
  const auto overlap = [](const Interval& x, const Interval& y) { return x.lo <= y.hi && y.lo <= x.hi; };
  ta.assign(1, 0.0);
  tb.assign(1, 0.0);
  const auto push = [&](const Interval& x, const Interval& y) {
    ta.insert(ta.end(), {x.lo, x.hi});
    tb.insert(tb.end(), {y.lo, y.hi});
  };
  std::size_t i = 0, j = 0;
  while (i < A.size() || j < B.size()) {
    if (i < A.size() && j < B.size() && overlap(A[i], B[j])) {
      if ((i + 1 < A.size() && overlap(A[i + 1], B[j])) || (j + 1 < B.size() && overlap(A[i], B[j + 1]))) return false;
      if (!(std::fabs(A[i].lo - B[j].lo) <= kMaxShift && std::fabs(A[i].hi - B[j].hi) <= kMaxShift)) return false;
      push(A[i++], B[j++]);
    } else if (j == B.size() || (i < A.size() && A[i].hi < B[j].lo)) {  // A[i] ends inside the strip
      if (!(A[i].hi - A[i].lo <= 2.0 * kMaxShift)) return false;  // its ends would move too far
      const double m = 0.5 * (A[i].lo + A[i].hi);
      push(A[i++], {m, m});
    } else {  // B[j] begins inside it
      if (!(B[j].hi - B[j].lo <= 2.0 * kMaxShift)) return false;
      const double m = 0.5 * (B[j].lo + B[j].hi);
      push({m, m}, B[j++]);
    }
  }
  ta.push_back(1.0);
  tb.push_back(1.0);
  return true;
}

struct Builder {
  const ArmCSpaceMap& map;
  int rows;
  std::vector<CSpaceQuad> out;
  std::vector<AngleInterval> scratch;

  // The strip [u0, u1] with cuts a at u0 and b at u1 (paired): each span in pieces.
  void emit(double u0, double u1, const std::vector<double>& a, const std::vector<double>& b) {
    for (std::size_t s = 0; s + 1 < a.size(); ++s) {
      const double wa = a[s + 1] - a[s], wb = b[s + 1] - b[s];
      if (!(wa > 0.0) && !(wb > 0.0)) continue;  // empty at both edges (a closed interval's point)
      if (!std::isfinite(wa + wb)) continue;      // no NaN into the count of pieces
      const int pieces = std::max(1, static_cast<int>(std::ceil(std::max(wa, wb) * rows)));
      for (int p = 0; p < pieces; ++p) {
        const double f0 = static_cast<double>(p) / pieces, f1 = static_cast<double>(p + 1) / pieces;
        // The last piece ends on the next cut exactly (no gap from rounding).
        const double ea = p + 1 == pieces ? a[s + 1] : a[s] + f1 * wa, eb = p + 1 == pieces ? b[s + 1] : b[s] + f1 * wb;
        out.push_back({u0, u1, a[s] + f0 * wa, b[s] + f0 * wb, ea, eb, s % 2 == 1});
      }
    }
  }

  void strip(double u0, double u1, const std::vector<double>& a, const std::vector<double>& b, int halvings) {
    if (paired(a, b)) return emit(u0, u1, a, b);
    std::vector<double> ta, tb;
    if (pair_with_tips(a, b, ta, tb)) return emit(u0, u1, ta, tb);
    const double um = 0.5 * (u0 + u1);
    const std::vector<double> m = cuts(map, um, scratch);
    if (halvings == kMaxHalvings) return emit(u0, u1, m, m);
    strip(u0, um, a, m, halvings + 1);
    strip(um, u1, m, b, halvings + 1);
  }
};

}  // namespace

std::vector<CSpaceQuad> cspace_quads(const ArmCSpaceMap& map, int columns, int rows) {
  if (columns < 1 || rows < 1) throw std::invalid_argument("cspace_quads: columns and rows must be >= 1");
  Builder b{map, rows, {}, {}};
  std::vector<double> left = cuts(map, 0.0, b.scratch);
  for (int i = 0; i < columns; ++i) {
    const double u0 = static_cast<double>(i) / columns, u1 = static_cast<double>(i + 1) / columns;
    std::vector<double> right = cuts(map, u1, b.scratch);
    b.strip(u0, u1, left, right, 0);
    left = std::move(right);
  }
  return std::move(b.out);
}

}  // namespace csl
