#pragma once
// Graph tools for roadmaps: union-find for connected components, and A* shortest paths.
#include <functional>
#include <vector>

namespace csl {

/// Disjoint sets with path halving and union by size (Tarjan 1975).
class UnionFind {
 public:
  explicit UnionFind(int n = 0) { reset(n); }
  void reset(int n);
  /// Adds one more singleton set; returns its element.
  int add();
  int find(int x);
  /// Merges the sets of a and b; returns false if they were already one.
  bool unite(int a, int b);
  int sets() const { return sets_; }
  int size() const { return static_cast<int>(parent_.size()); }

 private:
  std::vector<int> parent_, size_;
  int sets_ = 0;
};

struct GraphEdge {
  int a, b;
  double length;
};

/// A* from `source` to `target` over undirected edges (those with usable(i) true), with an
/// admissible heuristic h(v) (a lower bound on the distance from v to target; h = 0 gives
/// Dijkstra). Returns the vertices of a shortest path, source first, or nothing; `via`, if
/// given, receives the index of each edge taken. Ties are broken by vertex index, so the answer
/// is deterministic.
std::vector<int> shortest_path(int vertices, const std::vector<GraphEdge>& edges,
                               const std::function<bool(int)>& usable, int source, int target,
                               const std::function<double(int)>& heuristic, std::vector<int>* via = nullptr);

}  // namespace csl
