// TrackingSuite: the chains, built with the pose joins the Collision Avoidance uses.
#include "tests/eval/tracking/TrackingSuite.h"

#include <cmath>
#include <stdexcept>

#include "core/nav/motion/PoseJoins.h"

namespace rgnav {

namespace {

TrajectoryChain straight(double length) { return TrajectoryChain({{{}, length, 0.0, 0.0}}); }

TrajectoryChain arc(double radius, double degrees) {
  const double curvature = degrees > 0.0 ? 1.0 / radius : -1.0 / radius;
  return TrajectoryChain({{{}, radius * std::abs(degrees) * M_PI / 180.0, curvature, 0.0}});
}

// A straight, a symmetric turn, a straight.
TrajectoryChain turn(double degrees, const TurnShape& shape) {
  TrajectoryChain chain = straight(2.0);
  for (const TrajectorySegment& s : symmetricTurn(chain.end(), degrees * M_PI / 180.0, shape)) chain.append(s);
  chain.append({chain.end(), 2.0, 0.0, 0.0});
  return chain;
}

TrajectoryChain polyline(const std::vector<Pose2D>& targets, const TurnShape& shape) {
  const std::optional<TrajectoryChain> chain = smoothPolyline({}, targets, shape);
  if (!chain) throw std::logic_error("tracking suite: a polyline does not smooth");
  return *chain;
}

// A quarter turn on the spot (an arc of 1 mm radius), then 2 m straight on: the curvature jumps.
TrajectoryChain spotTurnThenStraight() {
  TrajectoryChain chain({{{}, 0.001 * M_PI / 2.0, 1000.0, 0.0}});
  chain.append({chain.end(), 2.0, 0.0, 0.0});
  return chain;
}

// Targets `spacing` apart along x, alternately `offset` left and right of the axis.
std::vector<Pose2D> zigzag(int count, double spacing, double offset) {
  std::vector<Pose2D> targets;
  for (int i = 1; i <= count; ++i) targets.push_back({i * spacing, i == count ? 0.0 : (i % 2 ? offset : -offset), 0.0});
  return targets;
}

}  // namespace

std::vector<TrackingCase> trackingSuite() {
  const TurnShape gentle{1.0, 1.0, 10.0};
  const TurnShape sharp{2.0, 3.0, 30.0};
  const std::optional<TrajectorySegment> join = clothoidJoin({}, {4.0, 1.5, 0.6}, 2.0);
  if (!join) throw std::logic_error("tracking suite: the G1 join failed");
  return {
      {"straight-3m", straight(3.0), 0.3},
      {"straight-8m", straight(8.0), 1.0},
      {"arc-left-r2-120deg", arc(2.0, 120.0), 0.6},
      {"arc-right-r1-180deg", arc(1.0, -180.0), 0.5},
      {"turn-left-90deg", turn(90.0, gentle), 0.8},
      {"turn-right-135deg", turn(-135.0, sharp), 0.6},
      {"slalom-2m", polyline(zigzag(6, 2.0, 0.6), gentle), 1.0},
      {"slalom-1.5m-tight", polyline(zigzag(6, 1.5, 0.5), sharp), 0.5},
      {"loop-4m", polyline({{4.0, 0.0, 0.0}, {4.0, 4.0, 0.0}, {0.0, 4.0, 0.0}, {0.0, 0.5, 0.0}}, gentle), 0.8},
      {"g1-clothoid-join", TrajectoryChain({*join}), 0.4},
      {"spot-turn-90deg-then-straight", spotTurnThenStraight(), 0.5},
  };
}

}  // namespace rgnav
