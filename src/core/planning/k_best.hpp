#pragma once
// The k nearest a search has found so far, kept sorted in a row the caller provides: the one
// insertion both neighbour indexes use (the k-d tree, nearest.cpp, and the grid,
// nearest_grid.cpp), so that they order equal distances alike, as brute force does.
#include <cstddef>
#include <limits>

#include "core/planning/nearest.hpp"

namespace csl {

/// Nearer first; equal distances by smaller index: the order brute force gives.
inline bool closer(double d2, int index, const Neighbor& than) {
  return d2 < than.squared_distance || (d2 == than.squared_distance && index < than.index);
}

/// The best k so far, nearest first, in row[0 .. count) (room for k; sized once, no push or
/// pop per point): insertion beats a heap for small k.
struct KBest {
  Neighbor* row;
  std::size_t k;
  int exclude;  ///< never entered (the query point itself); -1: none
  std::size_t count = 0;
  double worst = std::numeric_limits<double>::infinity();  ///< the k-th distance once full

  /// What a search may prune against: nothing farther (squared) can enter.
  double bound() const { return worst; }
  void operator()(int idx, double d2) {
    if (d2 > worst || idx == exclude) return;  // cannot enter (d2 == worst: the index decides)
    std::size_t at = count;
    if (count == k) {
      if (!closer(d2, idx, row[k - 1])) return;
      at = k - 1;
    } else {
      ++count;
    }
    while (at > 0 && closer(d2, idx, row[at - 1])) {
      row[at] = row[at - 1];
      --at;
    }
    row[at] = {idx, d2};
    if (count == k) worst = row[k - 1].squared_distance;
  }
};

}  // namespace csl
