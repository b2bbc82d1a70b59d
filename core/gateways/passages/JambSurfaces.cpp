// Surfaces of a scan around gateway-point candidates (see JambSurfaces.h).
#include "core/gateways/passages/JambSurfaces.h"

#include <cmath>

namespace rgnav {

JambSurfaces::JambSurfaces(const std::vector<ScanPoint>& points, double angleIncrementRad,
                           const BreakpointParams& params)
    : points_(points), runs_(splitAtBreakpoints(points, angleIncrementRad, params)), runOf_(points.size()) {
  for (std::size_t r = 0; r < runs_.size(); ++r)
    for (std::size_t i = runs_[r].first; i < runs_[r].second; ++i) runOf_[i] = r;
}

double JambSurfaces::jambLengthM(std::size_t candidate, int away) const {
  const auto& [first, end] = runs_[runOf_[candidate]];
  const std::size_t far = away > 0 ? end - 1 : first;
  return (points_[far].position - points_[candidate].position).norm();
}

std::size_t JambSurfaces::surfaceEnd(std::size_t candidate, int away) const {
  const auto& [first, end] = runs_[runOf_[candidate]];
  return away > 0 ? first : end - 1;
}

bool JambSurfaces::hiddenBehindNeighbour(std::size_t candidate, int away) const {
  if ((away > 0 && candidate == 0) || (away < 0 && candidate + 1 >= points_.size())) return false;
  const std::size_t neighbour = away > 0 ? candidate - 1 : candidate + 1;
  return runOf_[neighbour] != runOf_[candidate] && points_[neighbour].rangeM < points_[candidate].rangeM;
}

bool JambSurfaces::continuesLine(std::size_t candidate, int away, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 double reachM, double toleranceM) const {
  const auto& [first, end] = runs_[runOf_[candidate]];
  const Eigen::Vector2d along = (b - a).normalized();
  const Eigen::Vector2d& from = points_[candidate].position;
  for (auto i = static_cast<std::ptrdiff_t>(candidate);
       i >= static_cast<std::ptrdiff_t>(first) && i < static_cast<std::ptrdiff_t>(end); i += away) {
    const Eigen::Vector2d& p = points_[static_cast<std::size_t>(i)].position;
    const Eigen::Vector2d d = p - a;
    if (std::abs(along.x() * d.y() - along.y() * d.x()) > toleranceM) return false;
    if ((p - from).norm() >= reachM) return true;
  }
  return false;
}

}  // namespace rgnav
