// Figure 3.2 of the thesis; see QuadrangleRules.h.
#include "core/objects/QuadrangleRules.h"

#include "core/common/Errors.h"
#include "core/objects/SegmentRelations.h"

namespace rgnav {
namespace {

bool angleFits(const LineSegment& a, const LineSegment& b, const GroupingParams& p) {
  const double angle = minAngle(a, b);
  return p.minAngleRad < angle && angle < p.maxAngleRad;
}

bool near(const LineSegment& a, const LineSegment& b, const GroupingParams& p) {
  return segmentDistance(a, b) < p.maxNeighbourDistanceM;
}

bool apart(const LineSegment& a, const LineSegment& b, const GroupingParams& p) {
  return segmentDistance(a, b) > p.minOppositeDistanceM;
}

// One valid configuration of figure 3.2: (a next to c) and/or (b next to d), the corners a-c and
// b-d at valid angles, the opposite sides a-d and b-c far enough apart.
bool validConfiguration(const LineSegment& a, const LineSegment& b, const LineSegment& c, const LineSegment& d, bool ac,
                        bool bd, const GroupingParams& p) {
  const bool neighbours = p.restrictive ? (ac && bd) : (ac || bd);
  return neighbours && angleFits(a, c, p) && angleFits(b, d, p) && apart(a, d, p) && apart(b, c, p);
}

}  // namespace

void validate(const GroupingParams& p) {
  if (!(p.minAngleRad > 0.0 && p.minAngleRad < p.maxAngleRad) || !(p.maxNeighbourDistanceM > 0.0) ||
      !(p.minOppositeDistanceM >= 0.0))
    throw InvalidArgumentError("quadrangle grouping: need 0 < alpha_min < alpha_max, DN_max > 0, DO_min >= 0");
}

bool isNeighbourPair(const LineSegment& a, const LineSegment& b, const GroupingParams& params) {
  return angleFits(a, b, params) && near(a, b, params);
}

PairOfPairs classifyPairOfPairs(const LineSegment& li, const LineSegment& lj, const LineSegment& lk,
                                const LineSegment& ll, const GroupingParams& p) {
  const bool ik = near(li, lk, p), il = near(li, ll, p), jk = near(lj, lk, p), jl = near(lj, ll, p);
  if (ik && jk) return PairOfPairs::kInvalidKNearIAndJ;
  if (il && jl) return PairOfPairs::kInvalidLNearIAndJ;
  if (ik && il) return PairOfPairs::kInvalidINearKAndL;
  if (jk && jl) return PairOfPairs::kInvalidJNearKAndL;
  if (!ik && !il && !jk && !jl) return PairOfPairs::kInvalidNoNeighbour;
  if (validConfiguration(li, lj, lk, ll, ik, jl, p)) return PairOfPairs::kQuadIJLK;
  if (validConfiguration(li, lj, ll, lk, il, jk, p)) return PairOfPairs::kQuadIJKL;
  return PairOfPairs::kNoQuadrangle;
}

}  // namespace rgnav
