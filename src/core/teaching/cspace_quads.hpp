#pragma once
// The 2-link arm's C-space T^2 cut into quads that follow the exact C-obstacles' edges (from
// ArmCSpaceMap's blocked theta2 intervals), for drawing them on a curved surface such as the
// 3-D torus, where a grid of cells would draw each edge as the cells' blocks.
#include <vector>

#include "core/teaching/cspace_map.hpp"

namespace csl {

/// A quad of T^2 in the unit square's coordinates u = (theta1 + pi) / 2pi and
/// v = (theta2 + pi) / 2pi: corners (u0, va0), (u1, va1), (u1, vb1), (u0, vb0), va <= vb at
/// each edge. Its v edges slant where a C-obstacle's edge runs across it.
struct CSpaceQuad {
  double u0, u1, va0, va1, vb0, vb1;
  bool blocked;
};

/// T^2 in `columns` strips of theta1 (columns >= 1). Each strip is cut at the ends of the
/// blocked theta2 intervals at its two edges, joined by straight lines where both edges cut
/// the same intervals; an interval at one edge that meets none at the other ends inside the
/// strip in a point at its middle (a tip). Where an interval meets two (pieces that merge or
/// split) or an end moves more than 1/24 of a turn (a tip's ends included: where link 1
/// starts to collide, a whole column's interval must not narrow to a point), the strip is
/// halved, down to an eighth, and an eighth that still differs takes its centre's intervals.
/// So a quad is wrong only within a strip's width of an edge. Pieces are at most 1/rows of a
/// turn long in v (rows >= 1), so that a curved surface stays round. The quads tile the
/// square: each strip's pieces run from v = 0 to v = 1 at both of its edges.
std::vector<CSpaceQuad> cspace_quads(const ArmCSpaceMap& map, int columns, int rows);

}  // namespace csl
