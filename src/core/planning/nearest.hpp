#pragma once
// Nearest neighbours in a configuration space: a k-d tree that uses the space's own metric,
// weights and wrap-around (an angle near pi is close to one near -pi). Answers are exactly
// those of brute force, ordered by (distance, index), so roadmaps do not depend on the index,
// for angles in the chart [-pi, pi) (Space::wrap's): the tree prunes by chart coordinates.
//
// Points can also be inserted one at a time (an RRT's tree grows so). Rebuilding the whole
// tree per insert costs O(n log n) each; instead the index is a few k-d trees of sizes at least
// doubling (the logarithmic method, Bentley and Saxe 1980) plus a short unindexed buffer of
// the latest inserts. A full buffer is merged with the smallest trees into one new tree, so a
// point is rebuilt O(log n) times (amortised insert O(log^2 n)), and a query searches
// O(log n) trees and the buffer with one best-so-far list: the answers stay exact.
#include <vector>

#include "core/spaces/space.hpp"

namespace csl {

struct Neighbor {
  int index;
  double squared_distance;
};

class NeighborIndex {
 public:
  explicit NeighborIndex(const Space& space);

  /// Indexes `points` (copied) as indices 0 .. points.size() - 1; replaces what was indexed
  /// before (inserted points too): one tree, no buffer.
  void build(const std::vector<Config>& points);
  /// Adds q (the space's dim() coordinates, angles in the chart) as the next index, size() before
  /// the call, and returns that index.
  int insert(const Config& q);
  /// Room for `n` points in all without reallocating (a planner that inserts one at a time and
  /// knows about how many: most RRT-Connect queries end within a few dozen vertices, where
  /// growing the arrays by doubling was a tenth of the work). Changes no answer.
  void reserve(int n);
  /// All points, built and inserted.
  int size() const { return static_cast<int>(count_); }
  /// Every index once, so that neighbouring entries are close in space and querying in this
  /// order keeps the trees in cache: each tree's leaf order, largest tree first, then the
  /// buffered inserts in the order they came. After build() alone: the tree's leaf order.
  const std::vector<int>& leaf_order() const { return ids_; }

  /// The k points nearest to q, other than the point `exclude` (-1: none), nearest first,
  /// ties by smaller index. Fewer when the index holds fewer.
  void k_nearest(const Config& q, int k, int exclude, std::vector<Neighbor>& out) const;
  /// All points within distance r of q (inclusive), other than `exclude`, nearest first.
  void within(const Config& q, double r, int exclude, std::vector<Neighbor>& out) const;

  /// The most inserts that wait in the buffer, unindexed and scanned by every query; a full
  /// buffer becomes a tree, merged with the smallest trees (see insert()). Measured: 16, 32
  /// and 64 cost alike (100 000 inserts, each after a 10-nearest query, in R^2 and SE(2)).
  static constexpr int kBufferSize = 32;

 private:
  struct Node {
    int begin = 0, end = 0;  // range of positions (leaf order) of the subtree's points
    int axis = -1;           // split axis; -1 = leaf
    double split = 0.0;      // left holds coordinates <= split, right >= split
    int left = -1, right = -1;
  };
  struct Tree {
    int begin = 0;  // its points: positions begin .. the next tree's begin (or buffer_begin_)
    int root = 0;   // its nodes: root .. the next tree's root (or nodes_.size())
  };
  // Builds a tree over positions [begin, count_) (their points in any order), in place.
  void build_tree(int begin);
  int build_node(int begin, int end, std::vector<double>& cell, std::vector<int>& perm, int first);
  // Lower bound on the squared distance from q to anything in node n's bounding box.
  double box_lower_bound(int n, const double* q) const;
  const double* point(int i) const { return &pts_[static_cast<std::size_t>(i) * dim_]; }
  // kMetric: 0 = the space's general metric, 1 = plain Euclidean (linear, weight 1),
  // 2 = flat torus (angular, weight 1); kDim: the number of coordinates if known (2), else 0.
  template <int kMetric, int kDim, class Visit>
  void search(int node, const double* q, Visit& visit) const;
  template <int kMetric, int kDim>
  double box_bound(int n, const double* q) const;
  template <int kMetric, int kDim>
  double distance2(const double* q, const double* p) const;
  template <int kMetric, int kDim, class Visit>
  void search_all(const double* q, Visit& visit) const;
  template <class Visit>
  void search(const double* q, Visit& visit) const;

  Space space_;
  std::size_t dim_ = 0, count_ = 0;
  bool plain_ = false;  // all coordinates linear with weight 1: distances are plain Euclidean
  bool torus_ = false;  // all coordinates angular with weight 1: the flat torus
  // Per position, trees first (each in its leaf order: cache-friendly), then the buffer.
  std::vector<double> pts_;  // count_ x dim_ coordinates
  std::vector<int> ids_;     // position -> index (given by build() or returned by insert())
  std::vector<Tree> trees_;  // largest first; sizes at least double toward the front
  int buffer_begin_ = 0;     // positions buffer_begin_ .. count_: the unindexed inserts
  std::vector<Node> nodes_;  // all trees' nodes, tree after tree
  std::vector<double> box_;  // per node: dim_ lows then dim_ highs (chart coordinates)
};

/// The same answers by brute force (for tests, and tiny sets).
std::vector<Neighbor> brute_force_k_nearest(const Space& space, const std::vector<Config>& points, const Config& q,
                                            int k, int exclude);

}  // namespace csl
