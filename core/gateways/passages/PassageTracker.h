// PassageTracker: fuses narrow-passage hypotheses of consecutive scans (poses given, e.g. the
// corrected poses of the scan mapper) into gateways, and reports when the robot traverses one.
// The thesis (4.2.1, 5.2) keeps a buffer of hypotheses for the RG mapping kernel but gives no
// tracking method; this one is ours:
//   - association: a hypothesis belongs to the track whose mean gateway points are nearest, if
//     both of its points lie within associationDistanceM of them (in either order: a door seen
//     from its other side has left and right swapped); otherwise it starts a new track;
//   - support: the number of scans with at least one associated hypothesis; a track with
//     minSupport scans is confirmed, i.e. reported as a gateway;
//   - an unconfirmed track without support in the last forgetAfterUpdates updates is dropped;
//   - traversal: the robot's path from the previous update's pose to this one crosses the
//     segment between a confirmed gateway's points;
//   - wider twins: a confirmed gateway that shares a gateway point (within sharedPointM) with a
//     narrower confirmed one, lies within twinMaxAngleRad of its direction and is at least
//     twinWidthFactor times as wide is the same opening seen askew: the line from a door's jamb
//     to the corner of a cabinet or wall just inside the room. The detector keeps the narrowest of
//     the pairs it sees in one scan (NarrowPassageDetector.h, the thesis' minimum-width rule);
//     this carries the rule across scans, where the two were seen from different places. Only a
//     door that is not superseded itself supersedes (narrowest first), and the wider one is
//     superseded for good, also if its door is superseded later: it is no door, reports no
//     traversal (not even one in the update that supersedes it), and one confirmed in the same
//     update is not reported at all. Lines at a larger angle are different openings
//     that share a wall's end (a partition's end with a door beside it), so they stay; the width
//     factor keeps doors whose twin is only a few per cent wider (docs/EVALUATION.md).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/TypedId.h"
#include "core/gateways/passages/PassageHypothesis.h"

namespace rgnav {

// A track of the tracker; the detector gives a confirmed track its own DetectorGatewayId.
using PassageTrackId = TypedId<struct PassageTrackConcept>;

struct PassageTrackerConfig {
  double associationDistanceM = 0.6;  // a door seen from its two sides differs by the wall's thickness
  std::size_t minSupport = 3;          // scans
  std::size_t forgetAfterUpdates = 50;
  double sharedPointM = 0.25;                    // wider twins: a gateway point this close ...
  double twinMaxAngleRad = 60.0 * M_PI / 180.0;  // ... lines at most this far apart in direction ...
  double twinWidthFactor = 1.15;                 // ... and at least this many times as wide
};

template <class V>
void describe(V& v, PassageTrackerConfig& c) {
  v.field("association_distance_m", c.associationDistanceM);
  v.field("min_support_scans", c.minSupport);
  v.field("forget_after_updates", c.forgetAfterUpdates);
  v.field("shared_point_m", c.sharedPointM);
  v.degrees("twin_max_angle_deg", c.twinMaxAngleRad);
  v.field("twin_width_factor", c.twinWidthFactor);
}

// Throws ConfigError for a non-positive association distance, a zero count, a negative shared-point
// distance, an angle outside [0, pi/2] or a width factor below 1.
void validate(const PassageTrackerConfig& config);

struct TrackedGateway {
  PassageTrackId id;  // from 1, increasing
  Eigen::Vector2d left = Eigen::Vector2d::Zero();   // mean gateway points, in the order of the
  Eigen::Vector2d right = Eigen::Vector2d::Zero();  // first hypothesis (seen from its side)
  double meanConfidence = 0.0;
  std::size_t support = 0;  // scans
  std::size_t observations = 0;
  DataId firstScan = 0;
  DataId lastScan = 0;
  Pose2D lastRobotPose;  // the robot's pose at lastScan, as given to update()
  bool confirmed = false;
  bool superseded = false;  // a wider twin of a narrower confirmed gateway (see above): no door
  std::size_t traversals = 0;

  double widthM() const { return (left - right).norm(); }
  Eigen::Vector2d midpoint() const { return 0.5 * (left + right); }
};

struct GatewayTraversal {
  PassageTrackId gateway;
  DataId scanId = 0;                              // the update at which it was crossed
  Eigen::Vector2d crossing = Eigen::Vector2d::Zero();  // where the path crossed the gateway line
  bool fromObservedSide = false;  // from the side the gateway was first seen from to the other
};

// Everything a tracker knows, so that a module can checkpoint it and resume exactly.
struct PassageTrackState {
  TrackedGateway gateway;
  Eigen::Vector2d leftSum = Eigen::Vector2d::Zero(), rightSum = Eigen::Vector2d::Zero();
  double confidenceSum = 0.0;
  std::size_t lastUpdate = 0;  // the update that last brought a hypothesis
};

struct PassageTrackerState {
  std::vector<PassageTrackState> tracks;  // in the order they were started
  std::size_t updates = 0;
  PassageTrackId nextId{1};
  std::optional<Pose2D> lastPose;  // the robot's pose at the last update
};

struct TrackerUpdate {
  std::vector<PassageTrackId> confirmed;   // gateways confirmed by this update (none superseded)
  std::vector<PassageTrackId> superseded;  // gateways confirmed earlier and superseded by this update
  std::vector<GatewayTraversal> traversals;
};

class PassageTracker {
 public:
  // Throws ConfigError for a bad configuration.
  explicit PassageTracker(const PassageTrackerConfig& config = {});
  // Resumes from a saved state. Throws ConfigError for a bad configuration.
  PassageTracker(const PassageTrackerConfig& config, PassageTrackerState state);

  // The hypotheses of scan `scanId`, taken with the robot at `robotPose` (world frame, the
  // frame of the hypotheses). Updates must come in scan order.
  TrackerUpdate update(DataId scanId, const Pose2D& robotPose, const std::vector<PassageHypothesis>& hypotheses);

  // Every live track, confirmed or not, in the order they were started.
  std::vector<TrackedGateway> tracks() const;
  std::vector<TrackedGateway> gateways() const;  // the confirmed ones that are not superseded
  // The track of gateway `id`, or nullptr.
  const TrackedGateway* find(PassageTrackId id) const;
  const PassageTrackerState& state() const { return state_; }

 private:
  void traverse(DataId scanId, const Pose2D& robotPose, TrackerUpdate& out);
  void associate(const PassageHypothesis& hypothesis, const Pose2D& robotPose, TrackerUpdate& out);
  void supersedeWiderTwins(TrackerUpdate& out);

  PassageTrackerConfig config_;
  PassageTrackerState state_;
};

}  // namespace rgnav
