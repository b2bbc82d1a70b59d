// Open gateways, their drive points, the frontiers worth a goal, failure counts and reachability,
// shared by both exploration strategies (ExplorationTargets.h).
#include "core/nav/exploration/ExplorationTargets.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rgnav {
namespace {

constexpr std::size_t kDrivePointPlans = 3;  // candidates of one gateway planned at most
constexpr double kSideProbeM = 1.0;          // a crossing point's surroundings, to tell its side's

// The unknown cells within kSideProbeM of `point` (outside the grid: unknown too).
std::size_t unknownAround(const ExplorationGrid& grid, const Eigen::Vector2d& point) {
  const Eigen::Vector2d q = (point - grid.originM()) / grid.resolutionM();
  const int span = static_cast<int>(std::ceil(kSideProbeM / grid.resolutionM()));
  const int col = static_cast<int>(std::floor(q.x())), row = static_cast<int>(std::floor(q.y()));
  std::size_t count = 0;
  for (int r = row - span; r <= row + span; ++r)
    for (int c = col - span; c <= col + span; ++c)
      if ((grid.cellCenter(c, r) - point).norm() <= kSideProbeM && grid.at(c, r) == ExplorationCell::Unknown) ++count;
  return count;
}

std::size_t farthestFrom(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& from, std::size_t except) {
  std::size_t best = except;
  double most = -1.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (i != except && (points[i] - from).norm() > most) best = i, most = (points[i] - from).norm();
  return best;
}

std::optional<OpenGateway> openGateway(const GatewayView& g, const ExplorationGrid& grid, const Eigen::Vector2d& robot) {
  if (g.neutralised || (!g.sideA.isNone() && !g.sideB.isNone()) || g.crossingPoints.size() < 2) return std::nullopt;
  const std::optional<std::size_t> knownSide =
      !g.sideA.isNone() ? std::optional<std::size_t>(0) : !g.sideB.isNone() ? std::optional<std::size_t>(1) : std::nullopt;
  const RegionId known = knownSide == 0 ? g.sideA : g.sideB;
  const auto given = [&](std::optional<std::size_t> side) -> std::optional<std::size_t> {
    if (!side || g.sideCrossings[*side] >= g.crossingPoints.size()) return std::nullopt;
    return g.sideCrossings[*side];
  };
  std::optional<std::size_t> near = given(knownSide);
  std::optional<std::size_t> far = knownSide ? given(1 - *knownSide) : std::nullopt;
  if (!near && !far) {
    // The unexplored side: the crossing point with the most unknown cells around it (the one
    // farther from the robot on a tie).
    std::size_t most = 0;
    for (std::size_t i = 0; i < g.crossingPoints.size(); ++i) {
      const std::size_t unknown = unknownAround(grid, g.crossingPoints[i]);
      if (!far || unknown > most ||
          (unknown == most && (g.crossingPoints[i] - robot).norm() > (g.crossingPoints[*far] - robot).norm()))
        far = i, most = unknown;
    }
  }
  if (!near) near = farthestFrom(g.crossingPoints, g.crossingPoints[*far], *far);
  if (!far || *far == *near) far = farthestFrom(g.crossingPoints, g.crossingPoints[*near], *near);
  OpenGateway out{g.id, known, g.crossingPoints[*near], g.crossingPoints[*far], 0.0};
  for (const Eigen::Vector2d& a : g.gatewayPoints)
    for (const Eigen::Vector2d& b : g.gatewayPoints) out.halfWidthM = std::max(out.halfWidthM, 0.5 * (a - b).norm());
  return out;
}

// Whether `point` lies beyond the gateway's line (within a cell) and near its middle.
bool pastGateway(const OpenGateway& g, const Eigen::Vector2d& point, double cellM) {
  const Eigen::Vector2d middle = 0.5 * (g.near + g.far), away = (g.far - g.near).normalized();
  return away.dot(point - middle) >= -cellM && (point - middle).norm() <= g.halfWidthM + kGatewayFrontierReachM;
}

bool atOpenGateway(const Frontier& f, const std::vector<OpenGateway>& gateways) {
  return std::any_of(gateways.begin(), gateways.end(), [&](const OpenGateway& g) {
    const auto past = std::count_if(f.cells.begin(), f.cells.end(), [&](const Eigen::Vector2d& c) { return pastGateway(g, c, f.cellSizeM); });
    return 2 * static_cast<std::size_t>(past) >= f.cells.size();
  });
}

}  // namespace

std::vector<OpenGateway> openGateways(const PlanningMap& map, const ExplorationGrid& grid, const Eigen::Vector2d& robot) {
  std::vector<OpenGateway> out;
  for (const GatewayView& g : map.gateways)
    if (const auto open = openGateway(g, grid, robot)) out.push_back(*open);
  return out;
}

void countFailure(PointFailures& failures, const Eigen::Vector2d& point) {
  for (auto& [p, count] : failures)
    if ((p - point).norm() <= kSameGoalM) {
      ++count;
      return;
    }
  failures.emplace_back(point, 1);
}

std::size_t failuresAt(const PointFailures& failures, const Eigen::Vector2d& point) {
  std::size_t most = 0;
  for (const auto& [p, count] : failures)
    if ((p - point).norm() <= kSameGoalM) most = std::max(most, count);
  return most;
}

bool Reachability::startPlannable() {
  if (!startPlannable_) startPlannable_ = pathLength_(robot_).has_value();
  return *startPlannable_;
}

std::optional<double> Reachability::lengthTo(const Eigen::Vector2d& point) {
  for (const auto& [p, length] : asked_)
    if (p == point) return length;
  std::optional<double> length = pathLength_(point);
  if (!length && !startPlannable()) length = (point - robot_).norm();
  asked_.emplace_back(point, length);
  return length;
}

std::optional<std::pair<std::size_t, double>> Reachability::nearest(const std::vector<Eigen::Vector2d>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return (points[a] - robot_).norm() < (points[b] - robot_).norm(); });
  // Batches of the nearest by straight line; the first batch that holds a reachable candidate
  // decides. An approximation (a candidate farther by straight line may be nearer by driving)
  // that keeps the plans few.
  for (std::size_t first = 0; first < order.size(); first += kNearestByLine) {
    std::optional<std::pair<std::size_t, double>> best;
    for (std::size_t k = first; k < std::min(order.size(), first + kNearestByLine); ++k) {
      const auto length = lengthTo(points[order[k]]);
      if (length && (!best || *length < best->second)) best = std::make_pair(order[k], *length);
    }
    if (best) return best;
  }
  return std::nullopt;
}

std::vector<Eigen::Vector2d> drivePointCandidates(const OpenGateway& gateway, const ExplorationGrid& grid,
                                                  double robotRadiusM) {
  std::vector<Eigen::Vector2d> out;
  const double span = (gateway.far - gateway.near).norm(), cell = grid.resolutionM();
  if (span <= 0.0) return out;
  const Eigen::Vector2d middle = 0.5 * (gateway.near + gateway.far), away = (gateway.far - gateway.near) / span;
  for (double past = 0.5 * span; past >= cell - 1e-9; past -= cell) {
    const Eigen::Vector2d p = middle + away * past;
    int col = 0, row = 0;
    if (grid.cellOf(p, col, row) && grid.at(col, row) == ExplorationCell::Free &&
        grid.wallDistanceM(col, row) >= goalClearanceM(grid, robotRadiusM))
      out.push_back(p);
  }
  return out;
}

std::optional<Eigen::Vector2d> drivePoint(const OpenGateway& gateway, const ExplorationGrid& grid, double robotRadiusM,
                                          Reachability& reach) {
  const std::vector<Eigen::Vector2d> candidates = drivePointCandidates(gateway, grid, robotRadiusM);
  for (std::size_t i = 0; i < std::min(candidates.size(), kDrivePointPlans); ++i)
    if (reach.lengthTo(candidates[i])) return candidates[i];
  return std::nullopt;
}

std::vector<Frontier> candidateFrontiers(const std::vector<Frontier>& frontiers, const std::vector<OpenGateway>& gateways,
                                         const Eigen::Vector2d& robot, PointFailures& failures, std::size_t maxFailures) {
  std::vector<Frontier> out;
  for (const Frontier& f : frontiers) {
    if (atOpenGateway(f, gateways) || failuresAt(failures, f.viewpoint) >= maxFailures) continue;
    if ((f.viewpoint - robot).norm() <= kSameGoalM) {
      countFailure(failures, f.viewpoint);
      continue;
    }
    out.push_back(f);
  }
  return out;
}

}  // namespace rgnav
