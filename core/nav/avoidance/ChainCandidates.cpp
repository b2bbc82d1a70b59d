// Candidate chains for the Collision Avoidance (see ChainCandidates.h).
#include "core/nav/avoidance/ChainCandidates.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

namespace {

// Joins below this length are left out (the targets coincide).
constexpr double kMinJoinM = 1e-3;

}  // namespace

TrajectoryChain sliceChain(const TrajectoryChain& chain, double from, double to) {
  from = std::max(from, 0.0);
  to = std::min(to, chain.length());
  TrajectoryChain out;
  double segmentStart = 0.0;
  for (const TrajectorySegment& segment : chain.segments()) {
    const double a = std::max(from, segmentStart) - segmentStart;
    const double b = std::min(to, segmentStart + segment.length) - segmentStart;
    if (b - a > kMinJoinM)
      out.append(TrajectorySegment{segment.poseAt(a), b - a, segment.curvatureAt(a), segment.sharpness});
    segmentStart += segment.length;
  }
  return out;
}

}  // namespace rgnav
