#pragma once
// Nearest neighbours in a configuration space: a k-d tree that uses the space's own metric,
// weights and wrap-around (an angle near pi is close to one near -pi). Answers are exactly
// those of brute force, ordered by (distance, index), so roadmaps do not depend on the index,
// for angles in the chart [-pi, pi) (Space::wrap's): the tree prunes by chart coordinates.
#include <vector>

#include "core/space.hpp"

namespace csl {

struct Neighbor {
  int index;
  double squared_distance;
};

class NeighborIndex {
 public:
  explicit NeighborIndex(const Space& space) : space_(space) {}

  /// Indexes `points` (copied); replaces what was indexed before.
  void build(const std::vector<Config>& points);
  int size() const { return static_cast<int>(count_); }
  /// The indexed points' indices in the tree's leaf order: neighbouring entries are close in
  /// space, so querying in this order keeps the tree in cache.
  const std::vector<int>& leaf_order() const { return ids_; }

  /// The k points nearest to q, other than the point `exclude` (-1: none), nearest first,
  /// ties by smaller index. Fewer when the index holds fewer.
  void k_nearest(const Config& q, int k, int exclude, std::vector<Neighbor>& out) const;
  /// All points within distance r of q (inclusive), other than `exclude`, nearest first.
  void within(const Config& q, double r, int exclude, std::vector<Neighbor>& out) const;

 private:
  struct Node {
    int begin = 0, end = 0;  // range of leaf-ordered points in the subtree
    int axis = -1;           // split axis; -1 = leaf
    double split = 0.0;      // left holds coordinates <= split, right >= split
    int left = -1, right = -1;
  };
  int build_node(int begin, int end, std::vector<double>& cell);
  // Lower bound on the squared distance from q to anything in node n's bounding box.
  double box_lower_bound(int n, const double* q) const;
  const double* point(int i) const { return &pts_[static_cast<std::size_t>(i) * dim_]; }
  // kMetric: 0 = the space's general metric, 1 = plain Euclidean (linear, weight 1),
  // 2 = flat torus (angular, weight 1); kDim: the number of coordinates if known (2), else 0.
  template <int kMetric, int kDim, class Visit>
  void search(int node, const double* q, Visit& visit) const;
  template <int kMetric, int kDim>
  double box_bound(int n, const double* q) const;
  template <class Visit>
  void search(const double* q, Visit& visit) const;

  Space space_;
  std::size_t dim_ = 0, count_ = 0;
  bool plain_ = false;  // all coordinates linear with weight 1: distances are plain Euclidean
  bool torus_ = false;  // all coordinates angular with weight 1: the flat torus
  std::vector<double> pts_;  // count_ x dim_ coordinates, in leaf order (cache-friendly)
  std::vector<int> ids_;     // leaf order -> index given to build()
  std::vector<Node> nodes_;
  std::vector<double> box_;  // per node: dim_ lows then dim_ highs (chart coordinates)
};

/// The same answers by brute force (for tests, and tiny sets).
std::vector<Neighbor> brute_force_k_nearest(const Space& space, const std::vector<Config>& points, const Config& q,
                                            int k, int exclude);

}  // namespace csl
