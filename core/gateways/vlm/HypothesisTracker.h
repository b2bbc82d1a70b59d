// HypothesisTracker: observation sequences from VLM hypotheses tracked over consecutive scans,
// thesis 4.1.2.3 and 4.1.3. "The VLM hypotheses tracking is based on the gateway points and
// Euclidean distances. If all gateway points of two VLM hypotheses have an approximate match,
// they are considered to be identical." Gateway points are compared in the world frame (the
// scan's sensor pose); each hypothesis and each sequence is matched at most once per scan, the
// closest pairs first. A sequence starts when a hypothesis is observed with its centre closer
// than startDistanceM; it is finished when the robot enters the gateway (passes the entrance,
// the hidden line, by more than entryDepthM: that observation is not added) or when it is lost.
// Where we differ: "lost" allows maxMissedScans scans without a match (a person walking through
// the view should not cut a sequence); the thesis does not say how many.
#pragma once

#include <cstddef>
#include <cstdint>
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
};

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
  std::size_t missed = 0;  // consecutive scans without a match
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

  // The hypotheses of one scan whose sensor frame is `sensorPose` in the world.
  void update(const Pose2D& sensorPose, const std::vector<VlmObservation>& observations);
  // Ends every running sequence (end of the data).
  void flush();
  // The sequences finished since the last call, in the order they finished.
  std::vector<TrackedSequence> takeFinished();
  std::size_t runningCount() const { return state_.running.size(); }
  const HypothesisTrackerState& state() const { return state_; }

 private:
  void finish(std::size_t index, SequenceEnd end);

  TrackerParams params_;
  HypothesisTrackerState state_;
};

}  // namespace rgnav
