// The swept-footprint check (see SweptFootprint.h).
#include "core/nav/avoidance/SweptFootprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/raster/DistanceField.h"

namespace rgnav {

namespace {

constexpr double kFar = 1e9;
// Heading change between two sampled poses at most, rad (turns on the spot).
constexpr double kMaxTurnPerSample = 0.05;
// A robot starting closer than the margin may come this much closer still near the start: a turn
// on the spot is an arc of a millimetre radius (ChainCandidates.h), which moves the centre by up
// to twice that.
constexpr double kReliefSlackM = 0.005;

OccupancyGrid onlyOccupied(OccupancyGrid grid) {
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col)
      if (grid.at({col, row}) == Cell::Unknown) grid.set({col, row}, Cell::Free);
  return grid;
}

// Signed distance from the footprint at the origin (heading along x) to the point (x, y).
double footprintDistance(const Footprint& footprint, double x, double y) {
  if (footprint.shape == Footprint::Shape::Disk) return std::hypot(x, y) - footprint.radius;
  const double ax = std::abs(x - footprint.centerOffset) - footprint.length / 2.0;
  const double ay = std::abs(y) - footprint.width / 2.0;
  if (ax <= 0.0 && ay <= 0.0) return std::max(ax, ay);
  return std::hypot(std::max(ax, 0.0), std::max(ay, 0.0));
}

}  // namespace

ObstacleClearance::ObstacleClearance(OccupancyGrid obstacles)
    : obstacles_(onlyOccupied(std::move(obstacles))) {
  distanceCells_ = squaredDistanceToBlocked(obstacles_);
  for (float& d : distanceCells_) d = d >= kNoBlockedCell ? static_cast<float>(kFar) : std::sqrt(d);
}

double ObstacleClearance::pointClearance(WorldPoint p) const {
  const auto cell = obstacles_.cellOf(p);
  if (!cell) return kFar;
  const double res = obstacles_.resolution();
  const double d = distanceCells_[static_cast<std::size_t>(cell->row) * obstacles_.width() + cell->col];
  return d >= kFar ? kFar : d * res - res * (M_SQRT1_2 + 0.5);
}

double ObstacleClearance::windowClearance(const Footprint& footprint, const Pose2D& pose, double reach) const {
  const double res = obstacles_.resolution();
  const WorldPoint o = obstacles_.origin();
  const int c0 = std::max(0, static_cast<int>(std::floor((pose.x - reach - o.x) / res)));
  const int c1 = std::min(obstacles_.width() - 1, static_cast<int>(std::floor((pose.x + reach - o.x) / res)));
  const int r0 = std::max(0, static_cast<int>(std::floor((pose.y - reach - o.y) / res)));
  const int r1 = std::min(obstacles_.height() - 1, static_cast<int>(std::floor((pose.y + reach - o.y) / res)));
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double best = reach - footprint.circumradius();
  const Cell* cells = obstacles_.cells().data();
  for (int row = r0; row <= r1; ++row)
    for (int col = c0; col <= c1; ++col) {
      if (cells[static_cast<std::size_t>(row) * obstacles_.width() + col] != Cell::Occupied) continue;
      const double dx = o.x + (col + 0.5) * res - pose.x, dy = o.y + (row + 0.5) * res - pose.y;
      best = std::min(best, footprintDistance(footprint, c * dx + s * dy, -s * dx + c * dy) - res / 2.0);
    }
  return best;
}

double ObstacleClearance::footprintClearance(const Footprint& footprint, const Pose2D& pose, double exactBelow) const {
  const double bound = pointClearance({pose.x, pose.y}) - footprint.circumradius();
  if (bound >= exactBelow) return bound;
  return windowClearance(footprint, pose, footprint.circumradius() + exactBelow + obstacles_.resolution());
}

SweptCheck checkSwept(const ObstacleClearance& clearance, const TrajectoryChain& chain, const Footprint& footprint,
                      const SweptCheckOptions& options) {
  SweptCheck out;
  out.minClearance = options.marginM + options.clearanceCapM;
  if (chain.empty()) return out;
  const double length = chain.length();
  // Samples every stepM along the chain and every kMaxTurnPerSample of heading (pivots).
  std::vector<double> samples{0.0};
  double segmentStart = 0.0;
  for (const TrajectorySegment& segment : chain.segments()) {
    const double turn = std::abs(segment.curvature) * segment.length + std::abs(segment.sharpness) * segment.length * segment.length / 2.0;
    const int n = std::max(1, static_cast<int>(std::ceil(std::max(segment.length / options.stepM, turn / kMaxTurnPerSample))));
    for (int k = 1; k <= n; ++k) samples.push_back(segmentStart + segment.length * k / n);
    segmentStart += segment.length;
  }
  // A robot that already stands closer than the margin (or, by the cells' coarseness, seems to
  // touch) may leave: near the start it must only not come closer.
  const double atStart = clearance.footprintClearance(footprint, chain.start(), out.minClearance);
  const double startRequired = atStart < options.marginM ? atStart - kReliefSlackM : options.marginM;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double s = samples[i];
    const double d = i == 0 ? atStart : clearance.footprintClearance(footprint, chain.poseAt(s), out.minClearance);
    const double required = s <= options.reliefM ? startRequired : options.marginM;
    if (d < required) {
      out.clear = false;
      out.freeLength = i == 0 ? 0.0 : samples[i - 1];
      return out;
    }
    out.minClearance = std::min(out.minClearance, d);
  }
  out.freeLength = length;
  return out;
}

}  // namespace rgnav
