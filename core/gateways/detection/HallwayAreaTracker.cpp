// Hallway gateway areas from classified sequences; see HallwayAreaTracker.h.
#include "core/gateways/detection/HallwayAreaTracker.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/common/Errors.h"
#include "core/gateways/classify/GatewayObservation.h"
#include "core/gateways/passages/SegmentCrossing.h"
#include "core/gateways/vlm/ObservationVector.h"
#include "core/gateways/vlm/TrackedObservations.h"

namespace rgnav {
namespace {

// The end points of side `side` (0 hidden, 1 left, 2 front, 3 right).
std::pair<Eigen::Vector2d, Eigen::Vector2d> sideOf(const GatewayPoints& p, std::size_t side) {
  switch (side) {
    case 0: return {p[kHiddenRight], p[kHiddenLeft]};
    case 1: return {p[kHiddenLeft], p[kFrontLeft]};
    case 2: return {p[kFrontLeft], p[kFrontRight]};
    default: return {p[kFrontRight], p[kHiddenRight]};
  }
}

bool inside(const GatewayPoints& p, const Eigen::Vector2d& q) {
  // The corners go round the convex quadrangle; q is inside if it lies on the same side of all
  // four edges.
  int positive = 0, negative = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = p[i], b = p[(i + 1) % 4];
    const double c = (b - a).x() * (q - a).y() - (b - a).y() * (q - a).x();
    positive += c > 0.0;
    negative += c < 0.0;
  }
  return positive == 0 || negative == 0;
}

}  // namespace

void validate(const HallwayAreaConfig& config) {
  if (!std::isfinite(config.mergeDistanceM) || config.mergeDistanceM <= 0.0)
    throw ConfigError("hallway areas: mergeDistanceM must be positive and finite");
  if (config.minObservations == 0) throw ConfigError("hallway areas: minObservations must be at least 1");
}

std::size_t HallwayArea::bestView() const {
  std::size_t best = 0;
  for (std::size_t v = 1; v < views.size(); ++v)
    if (views[v].sequences >= views[best].sequences) best = v;
  return best;
}

Eigen::Vector2d sideMidpoint(const GatewayPoints& points, std::size_t side) {
  const auto [a, b] = sideOf(points, side);
  return 0.5 * (a + b);
}

HallwayAreaTracker::HallwayAreaTracker(const HallwayAreaConfig& config, const HmmClassifier& classifier,
                                       HallwayAreaState state)
    : config_(config), classifier_(classifier), state_(std::move(state)) {
  validate(config_);
  if (classifier_.dimension() != static_cast<Eigen::Index>(kObservationSize))
    throw InvalidArgumentError("hallway areas: the HMMs take " + std::to_string(classifier_.dimension()) +
                               " values per observation, the VLM observer gives " + std::to_string(kObservationSize));
}

std::optional<std::size_t> HallwayAreaTracker::addSequence(const TrackedSequence& sequence, DataId scanId,
                                                           const Pose2D& robotPose) {
  if (sequence.observations.size() < config_.minObservations) return std::nullopt;
  const GatewayObservationSequence observed = toObservationSequence(sequence);
  const Eigen::VectorXd logLikelihoods = classifier_.logLikelihoods(observed);
  const Eigen::Vector2d centre = gatewayCentre(sequence.gatewayPoints);
  const Eigen::Vector2d entrance = sideMidpoint(sequence.gatewayPoints, 0);

  auto area = std::find_if(state_.areas.begin(), state_.areas.end(), [&](const HallwayArea& a) {
    return (gatewayCentre(a.points) - centre).norm() <= config_.mergeDistanceM;
  });
  if (area == state_.areas.end()) {
    const Eigen::VectorXd alone = bayesUpdate(classifier_.priors(), logLikelihoods);
    Eigen::Index best = 0;
    alone.maxCoeff(&best);
    if (!isTransition(classifier_.classes()[static_cast<std::size_t>(best)])) return std::nullopt;
    area = state_.areas.insert(state_.areas.end(), HallwayArea{sequence.gatewayPoints, {}, scanId, scanId, robotPose, 0, {}});
  }
  auto view = std::find_if(area->views.begin(), area->views.end(), [&](const HallwayView& v) {
    return (v.entrance - entrance).norm() <= config_.mergeDistanceM;
  });
  if (view == area->views.end())
    view = area->views.insert(area->views.end(), HallwayView{entrance, classifier_.priors(), 0});
  view->posterior = bayesUpdate(view->posterior, logLikelihoods);
  ++view->sequences;
  // A sequence ends when the robot enters the gateway, so an area it makes may already hold the
  // robot, which came in through the side the sequence saw the gateway from. A lost sequence
  // says nothing about where the robot came in.
  const Eigen::Vector2d robot(robotPose.x, robotPose.y);
  if (sequence.end == SequenceEnd::Entered && !area->enteredThrough && inside(area->points, robot)) {
    std::size_t nearest = 0;
    for (std::size_t side = 1; side < 4; ++side)
      if ((sideMidpoint(area->points, side) - entrance).norm() < (sideMidpoint(area->points, nearest) - entrance).norm())
        nearest = side;
    area->enteredThrough = nearest;
  }
  area->lastScan = scanId;
  area->lastRobotPose = robotPose;
  return static_cast<std::size_t>(area - state_.areas.begin());
}

std::vector<AreaPassing> HallwayAreaTracker::move(const Eigen::Vector2d& position) {
  std::vector<AreaPassing> out;
  const std::optional<Eigen::Vector2d> last = std::exchange(state_.lastPosition, position);
  if (!last) return out;
  for (std::size_t i = 0; i < state_.areas.size(); ++i) {
    HallwayArea& area = state_.areas[i];
    for (std::size_t side = 0; side < 4; ++side) {
      const auto [a, b] = sideOf(area.points, side);
      const auto at = segmentCrossing(*last, position, a, b);
      if (!at) continue;
      if (inside(area.points, position)) {
        area.enteredThrough = side;
      } else {
        if (area.enteredThrough && *area.enteredThrough != side && isGateway(i)) {
          ++area.traversals;
          out.push_back({i, *area.enteredThrough, side, *at});
        }
        area.enteredThrough.reset();
      }
    }
  }
  return out;
}

GatewayPosterior HallwayAreaTracker::classes(std::size_t area) const {
  const HallwayArea& a = state_.areas.at(area);
  return GatewayPosterior{classifier_.classes(), a.views.at(a.bestView()).posterior};
}

bool HallwayAreaTracker::isGateway(std::size_t area) const { return isTransition(classes(area).best()); }

}  // namespace rgnav
