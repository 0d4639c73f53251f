#pragma once
// The k nearest neighbours of every point of a set at once, as the PRM's connect phase needs
// them. In the plane and on the flat torus T^2 (the point robot, the 2-link arm) a uniform grid
// of cells holding about two points each answers this several times faster than a k-d tree:
// building it is a counting sort, and each query takes the points within a radius guessed from
// its neighbour's answer and ranks them, without a branch per point; where that cannot answer
// (too few within, ties) it looks at the cells around its own, ring by ring, until no unvisited
// cell can hold a nearer point. Other spaces, and point sets with a dense cluster (where a grid
// compares most pairs), use the k-d tree.
// Answers are exactly brute force's: the same neighbours in the same order (ties by smaller
// index), found with the same squared distances (rounded to float in the rows), for angles in
// the chart [-pi, pi) (as Space::wrap leaves them, and as every configuration the planners
// make is): the grid and the k-d tree place and prune points by their chart coordinates, and
// may miss a neighbour given as an angle outside it.
#include <vector>

#include "core/planning/nearest.hpp"

namespace csl {

/// An entry of all_k_nearest's rows: half a Neighbor (8 bytes), since PRM keeps k of them for
/// every vertex while it connects. The distance is rounded to float: enough to compare rows;
/// whoever needs the exact one measures the pair again (Space::squared_distance gives the bits
/// the search compared).
struct NearNeighbor {
  int index;
  float squared_distance;
};

/// How all_k_nearest found its rows: by selection among the points within a radius (the grid's
/// common case), or by a search (the grid's ring search, or the k-d tree). The same answers
/// either way; tests and benchmarks read this to know which one ran.
struct KNearestStats {
  std::size_t selected = 0, searched = 0;
};

/// Row i (k entries, at out[i * k ..]) holds the k points nearest to points[i] among the others,
/// nearest first, ties by smaller index: NeighborIndex::k_nearest(points[i], k, i) for every i.
/// Rows of fewer (fewer than k + 1 points) are padded with {-1, 0}.
void all_k_nearest(const Space& space, const std::vector<Config>& points, int k, std::vector<NearNeighbor>& out,
                   KNearestStats* stats = nullptr);

/// For rows from all_k_nearest (k per point): seen[i] = 1 where row p's entry i is a point q < p
/// whose own row holds p, i.e. the pair was proposed from q's side already; 0 elsewhere (and on
/// padding). Returns the number of entries left at 0 that are not padding: every pair that is
/// in some row, once. (PRM checks each close pair once: these are its candidates.)
std::size_t mark_pairs_seen(const std::vector<NearNeighbor>& rows, int k, std::vector<unsigned char>& seen);

}  // namespace csl
