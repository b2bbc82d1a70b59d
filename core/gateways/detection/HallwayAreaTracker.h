// HallwayAreaTracker: hallway gateways (turns, junctions, crossings; thesis 4.1) from the
// classified observation sequences of the VLM hypothesis tracker, and their traversals.
//   - Places: a sequence belongs to the area whose centre lies within mergeDistanceM of its
//     gateway centre, otherwise it starts a new area (its gateway points become the area's).
//   - Views: the class of a gateway depends on where it is entered from (a T-junction entered
//     from a side branch is an LT- or RT-junction, a left turn entered from its other leg a
//     right turn), so an area keeps one view per entrance: sequences whose entrance (the
//     midpoint of the hidden line) lies within mergeDistanceM of a view's are fused into it
//     with Bayes' rule (4.1.4, last paragraph); others open a new view. The area's classes are
//     those of the view with the most sequences (the latest on ties).
//   - An area is a gateway while its best class is one of the six gateway classes of figure
//     4.1; Deadend and the counter-class Hallway are no transitions between regions.
//   - Traversal (ours; the thesis tracks hallway gateways only until they are entered): the
//     robot's path enters the square through one side and leaves it through another. A sequence
//     ends as the robot enters, so an area that a sequence ended that way makes or updates while
//     the robot is inside takes the side nearest the sequence's entrance as the one the robot
//     came through (not so for a lost sequence: the robot may have come in from anywhere).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/gateways/classify/HmmClassifier.h"
#include "core/gateways/vlm/GatewayPoints.h"
#include "core/gateways/vlm/HypothesisTracker.h"

namespace rgnav {

struct HallwayAreaConfig {
  double mergeDistanceM = 1.0;
  std::size_t minObservations = 3;  // shorter sequences are not classified
};

template <class V>
void describe(V& v, HallwayAreaConfig& c) {
  v.field("merge_distance_m", c.mergeDistanceM);
  v.field("min_observations", c.minObservations);
}

// Throws ConfigError for a non-positive distance or zero observations.
void validate(const HallwayAreaConfig& config);

struct HallwayView {
  Eigen::Vector2d entrance = Eigen::Vector2d::Zero();
  Eigen::VectorXd posterior;  // over the classifier's classes
  std::size_t sequences = 0;
};

struct HallwayArea {
  GatewayPoints points{};  // world frame, from the first sequence
  std::vector<HallwayView> views;
  DataId firstScan = 0, lastScan = 0;
  Pose2D lastRobotPose;  // at lastScan
  std::size_t traversals = 0;
  std::optional<std::size_t> enteredThrough;  // side, while the robot is inside
  std::size_t bestView() const;
};

struct HallwayAreaState {
  std::vector<HallwayArea> areas;
  std::optional<Eigen::Vector2d> lastPosition;
};

// A side of the square: 0 hidden (hidden-right to hidden-left), 1 left, 2 front, 3 right.
struct AreaPassing {
  std::size_t area = 0;
  std::size_t fromSide = 0, toSide = 0;
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
};

class HallwayAreaTracker {
 public:
  // Throws ConfigError for a bad configuration, InvalidArgumentError if the classifier's
  // dimension differs from the observation vector's (ObservationVector.h).
  HallwayAreaTracker(const HallwayAreaConfig& config, const HmmClassifier& classifier, HallwayAreaState state = {});

  // Classifies a finished sequence (seen up to scan `scanId`, the robot at `robotPose`) and
  // fuses it into its area; the
  // index of that area, or nullopt if the sequence is too short or a Hallway sequence where
  // there is no area yet.
  std::optional<std::size_t> addSequence(const TrackedSequence& sequence, DataId scanId, const Pose2D& robotPose);
  // The robot moved to `position`; the areas it went through.
  std::vector<AreaPassing> move(const Eigen::Vector2d& position);

  bool isGateway(std::size_t area) const;
  GatewayPosterior classes(std::size_t area) const;
  const HallwayAreaState& state() const { return state_; }

 private:
  HallwayAreaConfig config_;
  const HmmClassifier& classifier_;
  HallwayAreaState state_;
};

// The midpoint of side `side` (as in AreaPassing) of a gateway area.
Eigen::Vector2d sideMidpoint(const GatewayPoints& points, std::size_t side);

}  // namespace rgnav
