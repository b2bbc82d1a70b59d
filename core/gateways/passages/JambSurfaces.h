// JambSurfaces: what the surfaces of one scan say about gateway-point candidates (ours, not in
// thesis 4.2.1, which takes any closest point). The scan points are cut into surfaces at depth
// jumps by the adaptive breakpoint detector of the line extraction (BreakpointDetector.h, Borges
// & Aldon 2004). For a candidate they give
//   - its jamb length: the distance from it to the end of its surface away from the passage (a
//     door jamb bounds a wall; a table or chair leg of the IPA floor plans bounds nothing);
//   - whether it is the far side of a depth jump (the wall behind a table leg, where the leg's
//     shadow begins), which no jamb is;
//   - the end of its surface towards the passage, and whether its surface continues the gateway
//     line outwards: a wall end in line with the passage, as the jambs of a door in a wall are.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/lines/BreakpointDetector.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

class JambSurfaces {
 public:
  // Keeps a reference to `points` (the valid points of one scan in beam order).
  JambSurfaces(const std::vector<ScanPoint>& points, double angleIncrementRad, const BreakpointParams& params);

  // `away` is +1 to measure towards increasing point indices (for P_left), -1 for decreasing
  // (for P_right).
  double jambLengthM(std::size_t candidate, int away) const;

  // Index of the last point of the candidate's surface towards the passage (the opposite of
  // `away`).
  std::size_t surfaceEnd(std::size_t candidate, int away) const;

  // True if the candidate is only where a nearer object hides its surface: the next point
  // towards the passage (the opposite of `away`) starts another surface and is nearer to the
  // scanner. A jamb is an edge, the near side of a depth jump.
  bool hiddenBehindNeighbour(std::size_t candidate, int away) const;

  // True if the candidate's surface continues the line through `a` and `b` outwards (the
  // opposite of the passage) for at least `reachM`: every point of it within reachM of the
  // candidate lies within `toleranceM` of that line, and the surface reaches further.
  bool continuesLine(std::size_t candidate, int away, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                     double reachM, double toleranceM) const;

 private:
  const std::vector<ScanPoint>& points_;
  std::vector<std::pair<std::size_t, std::size_t>> runs_;
  std::vector<std::size_t> runOf_;  // per point
};

}  // namespace rgnav
