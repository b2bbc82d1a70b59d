// The rules of 2D line grouping to quadrangles, thesis 3.1, figure 3.2, for four given line
// segments; QuadrangleGrouping applies them to a whole line map.
// Stage 1 (neighbour pair): alpha_min < minAngle(li, lj) < alpha_max AND distance(li, lj) < DN_max.
// Stage 2 (pair of pairs lp_ij, lp_kl): b_nm = distance(ln, lm) < DN_max for (i,k), (i,l), (j,k),
// (j,l). Invalid: b_ik AND b_jk; b_il AND b_jl; b_ik AND b_il; b_jk AND b_jl; all four false.
// Valid, non-restrictive (A): (b_ik OR b_jl) AND angles (i,k), (j,l) in range AND
// distance(i,l) > DO_min AND distance(j,k) > DO_min -> quad(i, j, l, k); or the same with k and
// l exchanged -> quad(i, j, k, l). Restrictive (B, for 2D rectangles from laser data): OR
// becomes AND. The thesis laser parameters (3.2) are the defaults.
#pragma once

#include <cmath>

#include "core/lines/LineSegment.h"

namespace rgnav {

struct GroupingParams {
  double minAngleRad = 80.0 * M_PI / 180.0;   // alpha_min
  double maxAngleRad = 100.0 * M_PI / 180.0;  // alpha_max
  double maxNeighbourDistanceM = 0.200;       // DN_max
  double minOppositeDistanceM = 0.200;        // DO_min
  bool restrictive = true;                    // case B (laser); false: case A (images)
};

template <class V>
void describe(V& v, GroupingParams& c) {
  v.degrees("min_angle_deg", c.minAngleRad);
  v.degrees("max_angle_deg", c.maxAngleRad);
  v.field("max_neighbour_distance_m", c.maxNeighbourDistanceM);
  v.field("min_opposite_distance_m", c.minOppositeDistanceM);
  v.field("restrictive", c.restrictive);
}

// Throws InvalidArgumentError unless 0 < alpha_min < alpha_max, DN_max > 0 and DO_min >= 0.
void validate(const GroupingParams& params);

// Stage 1 of figure 3.2.
bool isNeighbourPair(const LineSegment& a, const LineSegment& b, const GroupingParams& params);

// The outcome of stage 2 of figure 3.2 for the pairs (li, lj) and (lk, ll).
enum class PairOfPairs {
  kInvalidKNearIAndJ,   // b_ik AND b_jk
  kInvalidLNearIAndJ,   // b_il AND b_jl
  kInvalidINearKAndL,   // b_ik AND b_il
  kInvalidJNearKAndL,   // b_jk AND b_jl
  kInvalidNoNeighbour,  // no b true
  kQuadIJLK,            // li next to lk, lj next to ll: quad(li, lj, ll, lk)
  kQuadIJKL,            // li next to ll, lj next to lk: quad(li, lj, lk, ll)
  kNoQuadrangle,        // no invalid configuration, but neither valid one holds
};

PairOfPairs classifyPairOfPairs(const LineSegment& li, const LineSegment& lj, const LineSegment& lk,
                                const LineSegment& ll, const GroupingParams& params);

}  // namespace rgnav
