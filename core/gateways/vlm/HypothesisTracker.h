// HypothesisTracker: observation sequences from VLM hypotheses tracked over consecutive scans,
// thesis 4.1.2.3 and 4.1.3. "The VLM hypotheses tracking is based on the gateway points and
// Euclidean distances. If all gateway points of two VLM hypotheses have an approximate match,
// they are considered to be identical." Gateway points are compared in the world frame (the
// scan's sensor pose); each hypothesis and each sequence is matched at most once per scan, the
// closest pairs first. A sequence starts when a hypothesis is observed with its centre closer
// than startDistanceM; it is finished when the robot enters the gateway (passes the entrance,
// the hidden line, by more than entryDepthM: that observation is not added) or when it is lost.
// Where we differ: "lost" allows maxMissedScans scans without a match (a person walking through
// the view should not cut a sequence); the thesis does not say how many. A coasted scan counts
// as a match, not as a miss.
// Where we differ (2), coasting: a sequence that no hypothesis of a scan matches, once it has
// minDetectionsToCoast detections, is observed in that scan at its last gateway points
// (VlmObserver::observeAt: lines through them), for at most maxCoastedScans scans of its life.
// Clutter that hides a depth singularity or breaks a wall line for a few scans then neither cuts
// the sequence nor leaves out the observations close to the gateway, where the hypotheses fail
// most often. On the simulated hallways (rgctl eval crossings, seed 1, 120 layouts) the lowest
// class rate in the 2 m cluttered hallways rose from 0.944 to 0.976 (with HMMs retrained on
// coasted sequences, config/gateways). The price: the counter-class (hypotheses in a straight
// hallway, no gateway) is told from the gateway classes less well (91.5 % against 95.2 % at
// 2 m, strongly cluttered), since a coasted observation repeats the lines of the hypothesis,
// right or wrong. Coasting only happens while the VLM is in the scan's view
// (VlmObserver::observeAt) and its centre within startDistanceM.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/gateways/vlm/GatewayPoints.h"
#include "core/gateways/vlm/VlmObserver.h"

namespace rgnav {

struct TrackerParams {
  double startDistanceM = 7.0;     // a sequence starts below this distance (table 4.1: 7 m)
  // Every gateway point of a match within this distance. From afar, a hidden line through a
  // depth singularity moves along the wall by the beam spacing over the grazing angle.
  double matchToleranceM = 0.5;
  std::size_t maxMissedScans = 2;  // lost after more consecutive scans without a match
  double entryDepthM = 0.1;        // entered: the robot this far past the entrance
  std::size_t minDetectionsToCoast = 3;  // detections of a sequence before it may coast
  std::size_t maxCoastedScans = 8;       // coasted observations per sequence at most
};

template <class V>
void describe(V& v, TrackerParams& c) {
  v.field("start_distance_m", c.startDistanceM);
  v.field("match_tolerance_m", c.matchToleranceM);
  v.field("max_missed_scans", c.maxMissedScans);
  v.field("entry_depth_m", c.entryDepthM);
  v.field("min_detections_to_coast", c.minDetectionsToCoast);
  v.field("max_coasted_scans", c.maxCoastedScans);
}

enum class SequenceEnd { Entered, Lost, Flushed };

// The observations of one tracked hypothesis, in the order they were made (decreasing
// distance while the robot approaches): plain vectors, the input of the classifiers.
struct TrackedSequence {
  std::uint64_t id = 0;
  GatewayPoints gatewayPoints;                     // world frame, from the last matched hypothesis
  std::vector<double> distances;                   // m, robot to gateway centre, per observation
  std::vector<std::vector<double>> observations;   // observation vectors (ObservationVector.h)
  SequenceEnd end = SequenceEnd::Flushed;
};

// Everything a tracker knows, so that a module can checkpoint it and resume exactly.
struct RunningSequence {
  TrackedSequence sequence;
  std::size_t missed = 0;   // scans neither matched nor coasted since the last match
  std::size_t coasted = 0;  // observations made by coasting, of the whole sequence
};

struct HypothesisTrackerState {
  std::uint64_t nextId = 1;
  std::vector<RunningSequence> running;
  std::vector<TrackedSequence> finished;  // not taken yet
};

class HypothesisTracker {
 public:
  // Throws InvalidArgumentError for non-positive distances or tolerance.
  explicit HypothesisTracker(const TrackerParams& params = {});
  // Resumes from a saved state; throws as above.
  HypothesisTracker(const TrackerParams& params, HypothesisTrackerState state);

  // Observes a known VLM, given its gateway points in the sensor frame of the current scan.
  using KnownVlmObserver = std::function<std::optional<VlmObservation>(const GatewayPoints& inSensorFrame)>;

  // The hypotheses of one scan whose sensor frame is `sensorPose` in the world; sequences they
  // do not match coast through `observeKnown` where allowed (no coasting when it is empty).
  void update(const Pose2D& sensorPose, const std::vector<VlmObservation>& observations,
              const KnownVlmObserver& observeKnown = {});
  // Ends every running sequence (end of the data).
  void flush();
  // The sequences finished since the last call, in the order they finished.
  std::vector<TrackedSequence> takeFinished();
  std::size_t runningCount() const { return state_.running.size(); }
  const HypothesisTrackerState& state() const { return state_; }

 private:
  void finish(std::size_t index, SequenceEnd end);
  // Sequences no hypothesis matched: entered when the robot is past their entrance, else coasted
  // where allowed.
  void followUnmatched(const Eigen::Vector2d& robot, const Pose2D& toSensor, const KnownVlmObserver& observeKnown,
                       std::vector<bool>& trackMatched, std::vector<bool>& entered);

  TrackerParams params_;
  HypothesisTrackerState state_;
};

}  // namespace rgnav
