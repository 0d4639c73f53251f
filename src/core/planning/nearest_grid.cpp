#include "core/planning/nearest_grid.hpp"

#include "core/planning/k_best.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace csl {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A cell is pruned only if its lower bound exceeds the k-th distance by this factor (squared
// distances), as the k-d tree prunes: rounding never drops a true neighbour.
constexpr double kPruneSafety = 1.0 + 1e-12;
// Measured on the PRM benchmark (k = 10): 2 points per cell beat 1, 1.5, 3 and 4.
constexpr double kPointsPerCell = 2.0;
// Uniform points at 2 per cell put at most ~10 in one cell for n up to 10^6.
constexpr int kCrowdedCell = 64;
// The selection by ranks (Grid::select_nearby) ranks the query point too, so k + 1 ranks up to
// 64 (a bit per rank), and looks at no more than this many points within its radius per query
// (its cost grows with their square).
constexpr int kMaxRankedK = 63;
constexpr int kMaxRanked = 256;
// The next query's radius, squared: the last query's k-th distance (squared) times this. The
// queries run in cell order, so the last one is a neighbour; 1.5 (the radius x 1.22) keeps about
// 1.5 k points in the disk, and too few for 9% of the queries. Measured at k = 10 against 1.2,
// 1.35, 1.7 and 2 (slower), and 1.3 and 1.4 (the same).
constexpr double kRadiusGrowth2 = 1.5;

// The first `count` entries of `row` into `out` (the rest of out's row keeps its padding).
void round_into(const std::vector<Neighbor>& row, std::size_t count, NearNeighbor* out) {
  for (std::size_t i = 0; i < count; ++i) out[i] = {row[i].index, static_cast<float>(row[i].squared_distance)};
}

// Whether a cell or region at least sqrt(gap2) from the query can be skipped.
inline bool beyond(const KBest& best, double gap2) { return gap2 > best.bound() * kPruneSafety; }

// One axis of the grid: `cells` cells of width `width` from `lo`; wraps on the torus.
struct Axis {
  double lo = 0.0, width = 1.0;
  double inverse = 1.0;  ///< 1 / width: the query box's cells (padded, so rounding is harmless)
  int cells = 1;
  int cell_of(double x) const {
    const double c = std::floor((x - lo) / width);
    if (!(c >= 0.0)) return 0;  // below (or NaN)
    return c >= cells ? cells - 1 : static_cast<int>(c);
  }
};

// kTorus: both coordinates angles with weight 1 (distance: wrapped differences); otherwise
// both linear with weight 1. Distances are computed exactly as Space::squared_distance does.
template <bool kTorus>
class Grid {
 public:
  Grid(const std::vector<Config>& points, Axis ax, Axis ay) : ax_(ax), ay_(ay) {
    const std::size_t n = points.size();
    start_.assign(static_cast<std::size_t>(ax.cells) * static_cast<std::size_t>(ay.cells) + 1, 0);
    std::vector<int> cell(n);
    for (std::size_t i = 0; i < n; ++i) {
      finite_ = finite_ && std::isfinite(points[i][0]) && std::isfinite(points[i][1]);
      cell[i] = cell_index(ax.cell_of(points[i][0]), ay.cell_of(points[i][1]));
      ++start_[static_cast<std::size_t>(cell[i]) + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) {
      max_per_cell_ = std::max(max_per_cell_, start_[c]);
      start_[c] += start_[c - 1];
    }
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    xs_.resize(n);
    ys_.resize(n);
    ids_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {  // in index order: each cell's points by index
      const auto at = static_cast<std::size_t>(fill[static_cast<std::size_t>(cell[i])]++);
      xs_[at] = points[i][0];
      ys_[at] = points[i][1];
      ids_[at] = static_cast<int>(i);
    }
    // A hair of slack on every gap: a point may sit a rounding error outside its cell.
    const double scale = std::fabs(ax.lo) + std::fabs(ay.lo) + ax.width * ax.cells + ay.width * ay.cells;
    slack_ = 1e-9 * std::min(ax.width, ay.width) + 1e-14 * scale;
  }

  /// Whether some cell holds far more points than uniform points would put in one (a cluster):
  /// the grid would then compare most pairs in it, and a k-d tree is the better index.
  bool crowded() const { return max_per_cell_ > kCrowdedCell; }

  void all_k_nearest(int k, std::vector<NearNeighbor>& out, KNearestStats& stats) const {
    const auto uk = static_cast<std::size_t>(k);
    // The ring search sorts in a row of its own (it stays in cache), then rounds it into `out`.
    std::vector<Neighbor> row(uk);
    Nearby near;
    const bool ranked = finite_ && k <= kMaxRankedK && ids_.size() > uk;
    if (ranked) near.reserve(uk);
    // The first radius: the disk that holds k + 1 points on average, at the points' density.
    const double area = ax_.width * ax_.cells * ay_.width * ay_.cells;
    const double typical2 = (k + 1.0) * area / (kPi * static_cast<double>(ids_.size()));
    double reach2 = kRadiusGrowth2 * typical2;
    // Queried in cell order, so the cells around consecutive queries stay in cache.
    for (std::size_t at = 0; at < ids_.size(); ++at) {
      const int id = ids_[at];
      NearNeighbor* o = &out[static_cast<std::size_t>(id) * uk];
      const double qx = xs_[at], qy = ys_[at];
      if (ranked && select_nearby(qx, qy, static_cast<int>(at), k, reach2, near, o)) {
        // A selected row's distances are distinct and above 0 (0 would tie with q's own rank);
        // all the same, the radius stays above a tenth of the typical one.
        reach2 = std::max(kRadiusGrowth2 * static_cast<double>(o[k - 1].squared_distance), 0.01 * typical2);
        ++stats.selected;
        continue;
      }
      KBest best{row.data(), row.size(), id};
      query(qx, qy, best);
      round_into(row, best.count, o);
      ++stats.searched;
    }
  }

 private:
  // Scratch of select_nearby, sized once: the points within its radius (squared distances,
  // their floats, positions in xs_/ys_/ids_, ranks), and which of them has each rank up to k
  // (a spare slot for the others).
  struct Nearby {
    std::vector<double> d2;
    std::vector<float> key;
    std::vector<int> at, rank, slot;
    void reserve(std::size_t k) {
      d2.resize(kMaxRanked);
      key.resize(kMaxRanked + 4);
      at.resize(kMaxRanked);
      rank.resize(kMaxRanked + 4);
      slot.resize(k + 2);
    }
  };

  // The k nearest of q (the point at position `self` in xs_/ys_) by selection rather than
  // search: every point within sqrt(reach2) of q (a box of cells around that disk, scanned
  // without branches), q itself included, then each one's rank among them by the floats of the
  // squared distances (counted without branches, vectorised). That is the exact answer when
  // the ranks 0 .. k are taken once each and rank 0 is q: q is at 0, alone (a duplicate of q
  // would share it), no two of the others share a float, and no point outside has a float as
  // small (it would share a rank), so ranks 1 .. k are the k nearest in exact order (rounding
  // to float keeps order, and distinct floats come from distinct doubles), and all points
  // farther than the radius are farther still. Returns false where it cannot say (fewer than
  // k others within the radius grown twice, more than kMaxRanked, ties, q not among them,
  // which only an angle outside the chart can cause): the ring search answers those. (q is
  // ranked rather than left out of the scan: a test of every point against q's index cost
  // more than one rank more.)
  bool select_nearby(double qx, double qy, int self, int k, double reach2, Nearby& s, NearNeighbor* out) const {
    int count = 0;
    for (int attempt = 0;; ++attempt) {
      count = 0;
      if (!gather(qx, qy, reach2, s, count)) return false;
      if (count > k) break;
      if (attempt == 2) return false;
      // Too few within: a disk for k + 1 at the density just seen, with a margin (about 9% of
      // the queries; growing 4-fold instead cost 5% more in all, rescanning 4 times the area).
      const int others = count - 1;
      reach2 *= 1.3 * (k + 1.0) / (others > 0 ? others : 1);
    }
    const int padded = (count + 3) & ~3;  // whole vectors of 4 floats
    for (int j = 0; j < count; ++j) s.key[static_cast<std::size_t>(j)] = static_cast<float>(s.d2[static_cast<std::size_t>(j)]);
    for (int j = count; j < padded; ++j) s.key[static_cast<std::size_t>(j)] = std::numeric_limits<float>::infinity();
    const float* key = s.key.data();
    int* rank = s.rank.data();
    for (int i = 0; i < padded; i += 4) {  // four ranks at once: one vector of counts
      int below[4] = {0, 0, 0, 0};
      for (int j = 0; j < count; ++j)
        for (int l = 0; l < 4; ++l) below[l] += key[j] < key[i + l] ? 1 : 0;
      for (int l = 0; l < 4; ++l) rank[i + l] = below[l];
    }
    // slot[r]: which of them has rank r <= k (slot[k + 1] takes all the others).
    const int ranks = k + 1;
    int* slot = s.slot.data();
    std::uint64_t ranks_seen = 0;
    int entered = 0;
    // Without a branch: about a third of the points are beyond rank k, in no order (written as
    // conditionals, the compiler branched, and mispredicted).
    for (int i = 0; i < count; ++i) {
      const int r = rank[i];
      const int in = static_cast<int>(r < ranks);
      const int to = std::min(r, ranks);
      slot[to] = i;
      entered += in;
      ranks_seen |= (std::uint64_t{1} << (to & 63)) & (std::uint64_t{0} - static_cast<std::uint64_t>(in));
    }
    const std::uint64_t all = ranks == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << ranks) - 1;
    if (entered != ranks || ranks_seen != all || s.at[static_cast<std::size_t>(slot[0])] != self) return false;
    for (int r = 1; r <= k; ++r) {
      const int j = slot[r];
      out[r - 1] = {ids_[static_cast<std::size_t>(s.at[static_cast<std::size_t>(j)])], key[j]};
    }
    return true;
  }

  // Every point within sqrt(reach2) of q (and some a little farther) into s, `count` of them;
  // false if there would be more than kMaxRanked.
  bool gather(double qx, double qy, double reach2, Nearby& s, int& count) const {
    // The box's half-width, padded: a point rounded into the next cell is still in the box.
    const double reach = std::sqrt(reach2) * (1.0 + 1e-9) + slack_;
    int x0, x1, y0, y1;
    box_cells(ax_, qx, reach, x0, x1);
    box_cells(ay_, qy, reach, y0, y1);
    for (int y = y0; y <= y1; ++y) {
      int cy = y;
      if constexpr (kTorus) cy += cy < 0 ? ay_.cells : (cy >= ay_.cells ? -ay_.cells : 0);
      // On the torus the run x0..x1 may cross the seam: two pieces.
      int runs[2][2] = {{x0, x1}, {1, 0}};
      if constexpr (kTorus) {
        if (x0 < 0) runs[0][0] = 0, runs[1][0] = x0 + ax_.cells, runs[1][1] = ax_.cells - 1;
        if (x1 >= ax_.cells) runs[0][1] = ax_.cells - 1, runs[1][0] = 0, runs[1][1] = x1 - ax_.cells;
      }
      for (const auto& run : runs) {
        if (run[0] > run[1]) continue;
        const int begin = start_[static_cast<std::size_t>(cell_index(run[0], cy))];
        const int end = start_[static_cast<std::size_t>(cell_index(run[1], cy)) + 1];
        if (count + (end - begin) > kMaxRanked) return false;
        double* d2 = s.d2.data();
        int* where = s.at.data();
        int kept = count;  // a local: `where` could alias `count` for the compiler
        for (int at = begin; at < end; ++at) {  // kept or not, written: no branch
          const double d = squared_distance(qx, qy, static_cast<std::size_t>(at));
          d2[kept] = d;
          where[kept] = at;
          kept += static_cast<int>(d <= reach2);
        }
        count = kept;
      }
    }
    return true;
  }

  // The cells [c0, c1] of axis a that the interval [q - reach, q + reach] meets: clamped to the
  // grid in the plane; on the torus unwrapped (c0 may be < 0, c1 >= cells), the whole axis
  // once when the interval is as long as the axis.
  void box_cells(const Axis& a, double q, double reach, int& c0, int& c1) const {
    const long long lo = floor_clamped((q - reach - a.lo) * a.inverse), hi = floor_clamped((q + reach - a.lo) * a.inverse);
    if constexpr (kTorus) {
      const bool whole = !(hi - lo + 1 < a.cells);
      c0 = whole ? 0 : static_cast<int>(lo);
      c1 = whole ? a.cells - 1 : static_cast<int>(hi);
    } else {
      c0 = static_cast<int>(std::max(lo, 0LL));
      c1 = static_cast<int>(std::min(hi, static_cast<long long>(a.cells) - 1));
    }
  }

  // floor(v) for box_cells, clamped to +-2^40 (NaN to the low end): both callers' uses clamp
  // to the grid, or take a whole axis, long before that. Truncation corrected below zero: with
  // SSE2 alone, std::floor's inline form converted to an integer and back (7% of the search).
  static long long floor_clamped(double v) {
    constexpr double kFar = 0x1p40;
    v = v >= -kFar ? (v <= kFar ? v : kFar) : -kFar;
    const auto t = static_cast<long long>(v);
    return t - static_cast<long long>(v < static_cast<double>(t));
  }

  int cell_index(int ix, int iy) const { return iy * ax_.cells + ix; }

  double squared_distance(double qx, double qy, std::size_t at) const {
    double dx, dy;
    if constexpr (kTorus) {
      dx = angle_difference(qx, xs_[at]);
      dy = angle_difference(qy, ys_[at]);
    } else {
      dx = xs_[at] - qx;
      dy = ys_[at] - qy;
    }
    return dx * dx + dy * dy;
  }

  // Lower bound on the distance along one axis from q (in cell `home`, whose low edge is
  // `edge`) to the cell `offset` cells away; on the torus the offset's image nearest q.
  double gap(const Axis& a, double q, double edge, int offset) const {
    double g = 0.0;
    if (offset > 0) g = edge + offset * a.width - q;
    if (offset < 0) g = q - (edge + (offset + 1) * a.width);
    g -= slack_;
    return g > 0.0 ? g : 0.0;
  }

  // Points of the cells c0..c1 of row cy: contiguous in memory (cells are stored row by row).
  void scan(double qx, double qy, int cy, int c0, int c1, KBest& best) const {
    if (c0 > c1) return;
    const int end = start_[static_cast<std::size_t>(cell_index(c1, cy)) + 1];
    for (int at = start_[static_cast<std::size_t>(cell_index(c0, cy))]; at < end; ++at)
      best(ids_[static_cast<std::size_t>(at)], squared_distance(qx, qy, static_cast<std::size_t>(at)));
  }

  // The run of cells dx0..dx1 (offsets from home) in the row dy offsets away: one loop over
  // their points rather than one per cell (two where a run crosses the torus's seam).
  void visit_run(double qx, double qy, int ix, int iy, int dx0, int dx1, int dy, double ex, double ey,
                 KBest& best) const {
    int cy = iy + dy;
    if constexpr (kTorus) {  // |offset| < cells: at most one turn (no division)
      cy += cy < 0 ? ay_.cells : (cy >= ay_.cells ? -ay_.cells : 0);
    } else {
      if (cy < 0 || cy >= ay_.cells) return;
    }
    const double gx = dx0 > 0 ? gap(ax_, qx, ex, dx0) : (dx1 < 0 ? gap(ax_, qx, ex, dx1) : 0.0);
    const double gy = gap(ay_, qy, ey, dy);
    if (beyond(best, gx * gx + gy * gy)) return;
    int c0 = ix + dx0, c1 = ix + dx1;
    if constexpr (kTorus) {  // a run is at most `cells` long: its pieces do not overlap
      const int g = ax_.cells;
      if (c0 < 0) {  // the part before the seam, wrapped
        scan(qx, qy, cy, c0 + g, std::min(c1, -1) + g, best);
        c0 = 0;
      }
      if (c1 >= g) {  // the part after it
        scan(qx, qy, cy, std::max(c0, g) - g, c1 - g, best);
        c1 = g - 1;
      }
    } else {
      c0 = std::max(c0, 0);
      c1 = std::min(c1, ax_.cells - 1);
    }
    scan(qx, qy, cy, c0, c1, best);
  }

  void query(double qx, double qy, KBest& best) const {
    const int ix = ax_.cell_of(qx), iy = ay_.cell_of(qy);
    const double ex = ax_.lo + ix * ax_.width, ey = ay_.lo + iy * ay_.width;  // home cell's low edges
    const int rings = std::max(ax_.cells, ay_.cells);
    for (int r = 1; r <= rings; ++r) {
      if (kTorus && 2 * r + 1 > std::min(ax_.cells, ay_.cells)) break;  // every cell seen once
      if (r == 1) {  // the 3 x 3 block around home, home's row first
        visit_run(qx, qy, ix, iy, -1, 1, 0, ex, ey, best);
        visit_run(qx, qy, ix, iy, -1, 1, -1, ex, ey, best);
        visit_run(qx, qy, ix, iy, -1, 1, 1, ex, ey, best);
      } else {  // ring r: its top and bottom rows, then its sides cell by cell
        visit_run(qx, qy, ix, iy, -r, r, -r, ex, ey, best);
        visit_run(qx, qy, ix, iy, -r, r, r, ex, ey, best);
        for (int dy = -r + 1; dy <= r - 1; ++dy) {
          visit_run(qx, qy, ix, iy, -r, -r, dy, ex, ey, best);
          visit_run(qx, qy, ix, iy, r, r, dy, ex, ey, best);
        }
      }
      // Every point not yet seen lies outside the block of cells within r of home: at least
      // the distance from q to the block's nearest side that still has cells beyond it.
      double side = kInf;
      const auto consider = [&](bool cells_beyond, double g) {
        if (kTorus || cells_beyond) side = std::min(side, g);
      };
      consider(ix - r > 0, qx - (ex - r * ax_.width));
      consider(ix + r < ax_.cells - 1, ex + (r + 1) * ax_.width - qx);
      consider(iy - r > 0, qy - (ey - r * ay_.width));
      consider(iy + r < ay_.cells - 1, ey + (r + 1) * ay_.width - qy);
      if (side == kInf) break;  // the block covers the grid
      side -= slack_;
      if (side > 0.0 && beyond(best, side * side)) break;
    }
  }

  Axis ax_, ay_;
  std::vector<int> start_;  // per cell: its first point in xs_/ys_/ids_ (one more entry at the end)
  std::vector<double> xs_, ys_;  // points sorted by cell: x, y
  std::vector<int> ids_;    // their indices in the input
  double slack_ = 0.0;
  int max_per_cell_ = 0;
  bool finite_ = true;  // every coordinate finite (select_nearby needs it: NaN has no rank)
};

// An axis of `cells` cells over [lo, hi]; a zero-width extent gets one cell.
Axis axis_over(double lo, double hi, int cells) {
  Axis a;
  a.lo = lo;
  a.cells = hi > lo ? std::max(cells, 1) : 1;
  a.width = hi > lo ? (hi - lo) / a.cells : 1.0;
  a.inverse = 1.0 / a.width;
  return a;
}

void with_tree(const Space& space, const std::vector<Config>& points, int k, std::vector<NearNeighbor>& out,
               KNearestStats& stats) {
  stats.searched += points.size();
  NeighborIndex index(space);
  index.build(points);
  std::vector<Neighbor> row;
  // In the tree's leaf order (cache-friendly); the answers do not depend on the order.
  for (int v : index.leaf_order()) {
    index.k_nearest(points[static_cast<std::size_t>(v)], k, v, row);
    round_into(row, row.size(), &out[static_cast<std::size_t>(v) * static_cast<std::size_t>(k)]);
  }
}

}  // namespace

void all_k_nearest(const Space& space, const std::vector<Config>& points, int k, std::vector<NearNeighbor>& out,
                   KNearestStats* stats_out) {
  KNearestStats ignored;
  KNearestStats& stats = stats_out ? *stats_out : ignored;
  stats = {};
  const std::size_t n = points.size();
  out.assign(n * static_cast<std::size_t>(std::max(k, 0)), NearNeighbor{-1, 0.0f});
  if (k <= 0 || n == 0) return;
  bool plain = space.dim() == 2, torus = space.dim() == 2;
  for (int a = 0; a < space.dim(); ++a) {
    plain = plain && !space.coordinate(a).angular && space.coordinate(a).weight == 1.0;
    torus = torus && space.coordinate(a).angular && space.coordinate(a).weight == 1.0;
  }
  if (!plain && !torus) return with_tree(space, points, k, out, stats);
  const double cells = std::max(1.0, static_cast<double>(n) / kPointsPerCell);
  if (torus) {
    // Square cells over the chart [-pi, pi)^2, an odd number per side (at least 3), so that
    // the rings around a cell meet each other cell exactly once.
    int side = static_cast<int>(std::ceil(std::sqrt(cells)));
    side = std::max(3, side | 1);
    const Grid<true> grid(points, axis_over(-kPi, kPi, side), axis_over(-kPi, kPi, side));
    if (grid.crowded()) return with_tree(space, points, k, out, stats);
    grid.all_k_nearest(k, out, stats);
    return;
  }
  // The points' bounding box, cut into cells as square as the box allows (each side capped
  // at n + 1 cells, so a box thin as a line stays a few cells).
  double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
  for (const Config& q : points)
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::min(lo[a], q[a]);
      hi[a] = std::max(hi[a], q[a]);
    }
  const double w = hi[0] - lo[0], h = hi[1] - lo[1];
  if (!std::isfinite(w) || !std::isfinite(h)) return with_tree(space, points, k, out, stats);
  const double size = w > 0 && h > 0 ? std::sqrt(w * h / cells) : std::max(w, h) / cells;
  const auto count = [&](double extent) {
    if (!(size > 0.0)) return 1;
    return static_cast<int>(std::min(std::ceil(extent / size), static_cast<double>(n) + 1.0));
  };
  const Grid<false> grid(points, axis_over(lo[0], hi[0], count(w)), axis_over(lo[1], hi[1], count(h)));
  if (grid.crowded()) return with_tree(space, points, k, out, stats);
  grid.all_k_nearest(k, out, stats);
}

std::size_t mark_pairs_seen(const std::vector<NearNeighbor>& rows, int k, std::vector<unsigned char>& seen) {
  seen.assign(rows.size(), 0);
  if (k <= 0) return 0;
  const auto uk = static_cast<std::size_t>(k);
  const std::size_t n = rows.size() / uk;
  // q's row is sorted: p is in it if p is nearer than its last entry, or is that entry. p's
  // distance to q is the same double as q's to p (a difference changes sign exactly, and
  // wrap_angle is odd), and rounding to float keeps order, so the floats decide unless equal.
  // The comparison keeps a margin all the same, and trusts only floats of full precision: a
  // distance that were not exactly symmetric (a future formula) cannot mark a pair wrongly.
  // Whatever falls within, ties included, looks through q's row.
  // Each row's last entry, side by side (the test reads the rows of random earlier points, and
  // this array, 12 bytes a point, stays in cache where the rows do not), with the bounds its
  // float sets: a distance below `below` is in the row, above `above` is not (the margins;
  // -inf and +inf where the float is not normal, so that neither test passes and the row is
  // read).
  struct Last {
    int index;
    float below, above;
  };
  constexpr float kBelow = 1.0f - 1e-6f, kAbove = 1.0f + 1e-6f;  // float rounding is 6e-8
  constexpr float kInfF = std::numeric_limits<float>::infinity();
  std::vector<Last> last_entries(n);
  for (std::size_t v = 0; v < n; ++v) {
    const NearNeighbor& e = rows[v * uk + uk - 1];
    const bool normal = std::isnormal(e.squared_distance);
    last_entries[v] = {e.index, normal ? e.squared_distance * kBelow : -kInfF,
                       normal ? e.squared_distance * kAbove : kInfF};
  }
  std::size_t pairs = 0;
  // Every test is computed and combined without a branch (whether q < p, and which way the
  // floats decide, follow no pattern a branch predictor could learn); only the rare pair the
  // floats leave open looks through q's row.
  // Through raw pointers held in locals: a store to an unsigned char may alias anything, so
  // the vectors' own pointers were read again after every flag (wasm: 3x native's time).
  const NearNeighbor* const all = rows.data();
  const Last* const last = last_entries.data();
  unsigned char* const flags = seen.data();
  for (std::size_t p = 0; p < n; ++p) {
    const std::size_t row = p * uk;
    for (std::size_t i = 0; i < uk && all[row + i].index >= 0; ++i) {
      const auto q = static_cast<std::size_t>(all[row + i].index);
      const Last theirs = last[q];
      const float d2 = all[row + i].squared_distance;
      // q's row holds every other point, or ends with p.
      const bool whole = (theirs.index < 0) | (static_cast<std::size_t>(theirs.index) == p);
      const bool nearer = d2 < theirs.below;
      const bool farther = d2 > theirs.above;
      bool in_theirs = whole | nearer;
      if ((q < p) & !(whole | nearer | farther))
        for (std::size_t j = 0; j < uk && !in_theirs; ++j) in_theirs = all[q * uk + j].index == static_cast<int>(p);
      const bool marked = (q < p) & in_theirs;
      flags[row + i] = static_cast<unsigned char>(marked);
      pairs += marked ? 0 : 1;
    }
  }
  return pairs;
}

}  // namespace csl
