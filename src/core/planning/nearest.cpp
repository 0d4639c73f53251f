#include "core/planning/nearest.hpp"

#include "core/planning/k_best.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace csl {
namespace {

constexpr int kLeafSize = 16;  // measured: 16 beats 8 and 4 for k = 10 in 2-D
// Lower bounds are scaled up a hair before pruning, so rounding never prunes a true neighbour.
constexpr double kPruneSafety = 1.0 + 1e-12;
constexpr double kInf = std::numeric_limits<double>::infinity();

// s1_distance(a, b), the same bits, for a and b in the chart, without a branch: |b - a| or the
// way round, 2 pi - |b - a| (summed as wrap_angle sums it, so rounded alike), whichever is
// shorter. wrap_angle's test whether b - a leaves the chart goes wrong a quarter of the time in
// this, the search's innermost loop. (Checked bit for bit against s1_distance on 6e7 pairs:
// uniform, near the chart's ends, and near half a turn apart.)
inline double s1_distance_in_chart(double a, double b) {
  const double x = std::fabs(b - a);
  const double round = (kTwoPi - x) + kTwoPiLo;
  return round < x ? round : x;
}

}  // namespace

NeighborIndex::NeighborIndex(const Space& space) : space_(space) {
  dim_ = static_cast<std::size_t>(space_.dim());
  plain_ = torus_ = true;
  for (int a = 0; a < space_.dim(); ++a) {
    plain_ = plain_ && !space_.coordinate(a).angular && space_.coordinate(a).weight == 1.0;
    torus_ = torus_ && space_.coordinate(a).angular && space_.coordinate(a).weight == 1.0;
  }
}

void NeighborIndex::build(const std::vector<Config>& points) {
  count_ = points.size();
  ids_.resize(count_);
  std::iota(ids_.begin(), ids_.end(), 0);
  // Coordinates in input order here; build_tree() reorders them into leaf order.
  pts_.resize(count_ * dim_);
  for (std::size_t i = 0; i < count_; ++i)
    for (std::size_t a = 0; a < dim_; ++a) pts_[i * dim_ + a] = points[i][static_cast<Eigen::Index>(a)];
  trees_.clear();
  nodes_.clear();
  box_.clear();
  nodes_.reserve(2 * count_ / kLeafSize + 2);
  box_.reserve(nodes_.capacity() * 2 * dim_);
  buffer_begin_ = 0;
  build_tree(0);
}

void NeighborIndex::reserve(int n) {
  const auto count = static_cast<std::size_t>(std::max(n, 0));
  pts_.reserve(count * dim_);
  ids_.reserve(count);
}

int NeighborIndex::insert(const Config& q) {
  const int index = static_cast<int>(count_);
  for (std::size_t a = 0; a < dim_; ++a) pts_.push_back(q[static_cast<Eigen::Index>(a)]);
  ids_.push_back(index);
  ++count_;
  if (static_cast<int>(count_) - buffer_begin_ < kBufferSize) return index;
  // The full buffer becomes a tree with the trees behind it that are less than twice what is
  // merged so far: then each tree is at least twice the one behind it (O(log n) trees), and a
  // point that is rebuilt lands in a tree at least 1.5 times its old one (O(log n) rebuilds).
  // The trees behind are the last built, so their points and nodes are the arrays' tails.
  int begin = buffer_begin_;
  while (!trees_.empty() && begin - trees_.back().begin < 2 * (static_cast<int>(count_) - begin)) {
    begin = trees_.back().begin;
    nodes_.resize(static_cast<std::size_t>(trees_.back().root));
    box_.resize(nodes_.size() * 2 * dim_);
    trees_.pop_back();
  }
  build_tree(begin);
  return index;
}

void NeighborIndex::build_tree(int begin) {
  buffer_begin_ = static_cast<int>(count_);
  if (begin == buffer_begin_) return;
  trees_.push_back({begin, static_cast<int>(nodes_.size())});
  // perm: the positions in leaf order once built (nth_element permutes it, the points stay).
  std::vector<int> perm(count_ - static_cast<std::size_t>(begin));
  std::iota(perm.begin(), perm.end(), begin);
  std::vector<double> cell(2 * dim_);
  for (std::size_t a = 0; a < dim_; ++a) {
    const Coordinate& c = space_.coordinate(static_cast<int>(a));
    cell[a] = c.lo;
    cell[dim_ + a] = c.hi;
  }
  build_node(begin, static_cast<int>(count_), cell, perm, begin);
  // The points and their indices into leaf order.
  std::vector<double> ordered(perm.size() * dim_);
  std::vector<int> ids(perm.size());
  for (std::size_t i = 0; i < perm.size(); ++i) {
    std::copy_n(&pts_[static_cast<std::size_t>(perm[i]) * dim_], dim_, &ordered[i * dim_]);
    ids[i] = ids_[static_cast<std::size_t>(perm[i])];
  }
  std::copy(ordered.begin(), ordered.end(), pts_.begin() + static_cast<std::ptrdiff_t>(begin * dim_));
  std::copy(ids.begin(), ids.end(), ids_.begin() + begin);
}

int NeighborIndex::build_node(int begin, int end, std::vector<double>& cell, std::vector<int>& perm, int first) {
  // `cell` holds the region this node splits (dim_ lows, dim_ highs): its widest side, in
  // metric units, is the split axis. The node's tight bounding box, used for pruning, is built
  // bottom up from its children's, so building costs O(n log n). perm[i - first]: the position
  // (in pts_) of the point that goes to position i; positions break ties between equal keys.
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  box_.resize(box_.size() + 2 * dim_);
  Node node;
  node.begin = begin;
  node.end = end;
  if (end - begin > kLeafSize) {
    std::size_t axis = 0;
    double widest = -1.0;
    for (std::size_t a = 0; a < dim_; ++a) {
      const double w = (cell[dim_ + a] - cell[a]) * space_.coordinate(static_cast<int>(a)).weight;
      if (w > widest) {
        widest = w;
        axis = a;
      }
    }
    const int mid = begin + (end - begin) / 2;
    const auto key = [&](int idx) { return pts_[static_cast<std::size_t>(idx) * dim_ + axis]; };
    const auto at = [&](int i) { return perm.begin() + (i - first); };
    std::nth_element(at(begin), at(mid), at(end),
                     [&](int x, int y) { return key(x) < key(y) || (key(x) == key(y) && x < y); });
    const double split = key(*at(mid));
    node.axis = static_cast<int>(axis);
    node.split = split;
    const double saved_hi = cell[dim_ + axis], saved_lo = cell[axis];
    cell[dim_ + axis] = split;
    node.left = build_node(begin, mid, cell, perm, first);
    cell[dim_ + axis] = saved_hi;
    cell[axis] = split;
    node.right = build_node(mid, end, cell, perm, first);
    cell[axis] = saved_lo;
    double* box = &box_[static_cast<std::size_t>(id) * 2 * dim_];
    const double* l = &box_[static_cast<std::size_t>(node.left) * 2 * dim_];
    const double* r = &box_[static_cast<std::size_t>(node.right) * 2 * dim_];
    for (std::size_t a = 0; a < dim_; ++a) {
      box[a] = std::min(l[a], r[a]);
      box[dim_ + a] = std::max(l[dim_ + a], r[dim_ + a]);
    }
  } else {
    double* lo = &box_[static_cast<std::size_t>(id) * 2 * dim_];
    double* hi = lo + dim_;
    std::fill(lo, lo + dim_, kInf);
    std::fill(hi, hi + dim_, -kInf);
    for (int i = begin; i < end; ++i) {
      const double* p = &pts_[static_cast<std::size_t>(perm[static_cast<std::size_t>(i - first)]) * dim_];
      for (std::size_t a = 0; a < dim_; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
    }
  }
  nodes_[static_cast<std::size_t>(id)] = node;
  return id;
}

// On an angular axis the box is an arc [lo, hi] of the chart; outside it, the arc's nearest
// point is one of its ends, the shorter way round.
double NeighborIndex::box_lower_bound(int n, const double* q) const {
  const double* lo = &box_[static_cast<std::size_t>(n) * 2 * dim_];
  const double* hi = lo + dim_;
  double sum = 0.0;
  for (std::size_t a = 0; a < dim_; ++a) {
    if (q[a] >= lo[a] && q[a] <= hi[a]) continue;
    const Coordinate& c = space_.coordinate(static_cast<int>(a));
    double gap;
    if (c.angular) {
      const double to_lo = std::fabs(angle_difference(q[a], lo[a])), to_hi = std::fabs(angle_difference(q[a], hi[a]));
      gap = to_lo < to_hi ? to_lo : to_hi;
    } else {
      gap = q[a] < lo[a] ? lo[a] - q[a] : q[a] - hi[a];
    }
    gap *= c.weight;
    sum += gap * gap;
  }
  return sum;
}

// box_lower_bound() for a known metric and dimension (the same value: weights of 1 change
// nothing, gap * 1.0 == gap).
template <int kMetric, int kDim>
inline double NeighborIndex::box_bound(int n, const double* q) const {
  if constexpr (kMetric == 0 || kDim == 0) {
    return box_lower_bound(n, q);
  } else {
    const double* lo = &box_[static_cast<std::size_t>(n) * 2 * kDim];
    const double* hi = lo + kDim;
    double sum = 0.0;
    for (int a = 0; a < kDim; ++a) {
      if (q[a] >= lo[a] && q[a] <= hi[a]) continue;
      double gap;
      if constexpr (kMetric == 2) {
        const double to_lo = s1_distance_in_chart(q[a], lo[a]), to_hi = s1_distance_in_chart(q[a], hi[a]);
        gap = to_lo < to_hi ? to_lo : to_hi;
      } else {
        gap = q[a] < lo[a] ? lo[a] - q[a] : q[a] - hi[a];
      }
      sum += gap * gap;
    }
    return sum;
  }
}

// The squared distance from q to p. kMetric 1, plain Euclidean coordinates: dx^2 + dy^2 + ... is
// exactly what Space::squared_distance computes for them (weights 1, summed in the same order);
// kMetric 2, the flat torus: likewise with each difference wrapped as Coordinate::delta wraps it;
// kMetric 0: the space's own. kDim: their number when known at compile time, 0 otherwise.
// (Stopping a sum once it passes the visitor's bound saved 8% of the instructions on T^4 but
// cost 15% of the time: the branch is unpredictable.)
template <int kMetric, int kDim>
inline double NeighborIndex::distance2(const double* q, const double* p) const {
  if constexpr (kMetric == 0) {
    return space_.squared_distance(q, p);
  } else {
    double d2 = 0.0;
    const std::size_t dim = kDim > 0 ? static_cast<std::size_t>(kDim) : dim_;
    for (std::size_t a = 0; a < dim; ++a) {
      const double d = kMetric == 2 ? s1_distance_in_chart(q[a], p[a]) : p[a] - q[a];
      d2 += d * d;
    }
    return d2;
  }
}

// Depth first, the child on q's side of the split first; the other child only if its box's
// lower bound does not exceed visit.bound() (equal bounds are searched: exact ties matter).
template <int kMetric, int kDim, class Visit>
void NeighborIndex::search(int node, const double* q, Visit& visit) const {
  const Node& n = nodes_[static_cast<std::size_t>(node)];
  if (n.axis < 0) {
    for (int i = n.begin; i < n.end; ++i) visit(ids_[static_cast<std::size_t>(i)], distance2<kMetric, kDim>(q, point(i)));
    return;
  }
  const bool left_first = q[n.axis] <= n.split;
  const int near = left_first ? n.left : n.right, far = left_first ? n.right : n.left;
  search<kMetric, kDim>(near, q, visit);
  if (box_bound<kMetric, kDim>(far, q) <= visit.bound() * kPruneSafety) search<kMetric, kDim>(far, q, visit);
}

// Every tree, the largest first (its near points bound the smaller trees' searches soonest),
// then the buffer, all into the one visitor: its best-so-far list (or its list within r) is
// the merge, so the answer is brute force's whichever part holds each point.
// The buffer's distances by the same kernel as the leaves' (the bits brute force computes, so
// equal distances tie alike): an RRT's query scans up to kBufferSize buffered points, and with
// Space::squared_distance's per-coordinate tests that scan was a tenth of an RRT's instructions.
template <int kMetric, int kDim, class Visit>
void NeighborIndex::search_all(const double* q, Visit& visit) const {
  for (const Tree& tree : trees_) search<kMetric, kDim>(tree.root, q, visit);
  for (int i = buffer_begin_; i < static_cast<int>(count_); ++i)
    visit(ids_[static_cast<std::size_t>(i)], distance2<kMetric, kDim>(q, point(i)));
}

template <class Visit>
void NeighborIndex::search(const double* q, Visit& visit) const {
  if (plain_ && dim_ == 2)
    search_all<1, 2>(q, visit);
  else if (plain_)
    search_all<1, 0>(q, visit);
  else if (torus_ && dim_ == 2)
    search_all<2, 2>(q, visit);
  else if (torus_ && dim_ == 4)  // the 4-link arm (the benches' T^4): unrolled, a fifth fewer instructions
    search_all<2, 4>(q, visit);
  else if (torus_)  // T^N, other N (an N-link arm): the torus's distances, N known at run time
    search_all<2, 0>(q, visit);
  else
    search_all<0, 0>(q, visit);
}

void NeighborIndex::k_nearest(const Config& q, int k, int exclude, std::vector<Neighbor>& out) const {
  out.clear();
  if (k <= 0 || count_ == 0) return;
  out.resize(static_cast<std::size_t>(k));  // the best so far, in out's storage
  KBest visitor{out.data(), static_cast<std::size_t>(k), exclude};
  search(q.data(), visitor);
  out.resize(visitor.count);
}

void NeighborIndex::within(const Config& q, double r, int exclude, std::vector<Neighbor>& out) const {
  out.clear();
  if (count_ == 0) return;
  struct Visitor {
    std::vector<Neighbor>& found;
    double r2;
    int exclude;
    double bound() const { return r2; }
    void operator()(int idx, double d2) {
      if (idx != exclude && d2 <= r2) found.push_back({idx, d2});
    }
  } visitor{out, r * r, exclude};
  search(q.data(), visitor);
  std::sort(out.begin(), out.end(), [](const Neighbor& a, const Neighbor& b) {
    return closer(a.squared_distance, a.index, b);
  });
}

std::vector<Neighbor> brute_force_k_nearest(const Space& space, const std::vector<Config>& points, const Config& q,
                                            int k, int exclude) {
  std::vector<Neighbor> all;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (static_cast<int>(i) != exclude) all.push_back({static_cast<int>(i), space.squared_distance(q, points[i])});
  std::sort(all.begin(), all.end(),
            [](const Neighbor& a, const Neighbor& b) { return closer(a.squared_distance, a.index, b); });
  if (static_cast<int>(all.size()) > k) all.resize(static_cast<std::size_t>(std::max(k, 0)));
  return all;
}

}  // namespace csl
