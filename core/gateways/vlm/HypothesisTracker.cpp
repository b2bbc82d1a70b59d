// Tracking of VLM hypotheses into observation sequences; see HypothesisTracker.h.
#include "core/gateways/vlm/HypothesisTracker.h"

#include <algorithm>
#include <tuple>
#include <utility>

#include "core/common/Errors.h"

namespace rgnav {

HypothesisTracker::HypothesisTracker(const TrackerParams& params) : params_(params) {
  if (!(params.startDistanceM > 0.0) || !(params.matchToleranceM > 0.0) || !(params.entryDepthM >= 0.0))
    throw InvalidArgumentError("hypothesis tracker: need positive start distance and tolerance, entry depth >= 0");
}

HypothesisTracker::HypothesisTracker(const TrackerParams& params, HypothesisTrackerState state)
    : HypothesisTracker(params) {
  state_ = std::move(state);
}

void HypothesisTracker::finish(std::size_t index, SequenceEnd end) {
  state_.running[index].sequence.end = end;
  state_.finished.push_back(std::move(state_.running[index].sequence));
  state_.running.erase(state_.running.begin() + static_cast<std::ptrdiff_t>(index));
}

void HypothesisTracker::update(const Pose2D& sensorPose, const std::vector<VlmObservation>& observations,
                               const KnownVlmObserver& observeKnown) {
  const Eigen::Vector2d robot(sensorPose.x, sensorPose.y);
  std::vector<GatewayPoints> world;
  world.reserve(observations.size());
  for (const VlmObservation& o : observations) world.push_back(transformed(o.hypothesis.gatewayPoints, sensorPose));

  // Candidate matches (distance, track, hypothesis), closest first.
  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
  for (std::size_t t = 0; t < state_.running.size(); ++t)
    for (std::size_t h = 0; h < world.size(); ++h)
      if (const double d = largestPointDistance(state_.running[t].sequence.gatewayPoints, world[h]);
          d <= params_.matchToleranceM)
        candidates.emplace_back(d, t, h);
  std::sort(candidates.begin(), candidates.end());

  std::vector<bool> trackMatched(state_.running.size(), false), hypothesisUsed(world.size(), false);
  std::vector<bool> entered(state_.running.size(), false);
  for (const auto& [d, t, h] : candidates) {
    if (trackMatched[t] || hypothesisUsed[h]) continue;
    trackMatched[t] = hypothesisUsed[h] = true;
    RunningSequence& track = state_.running[t];
    track.missed = 0;
    track.sequence.gatewayPoints = world[h];
    if (depthPastEntrance(world[h], robot) > params_.entryDepthM) {
      entered[t] = true;
      continue;
    }
    track.sequence.distances.push_back(observations[h].distanceM);
    track.sequence.observations.push_back(observations[h].observation);
  }
  followUnmatched(robot, inverse(sensorPose), observeKnown, trackMatched, entered);
  // Finish from the back so that indices stay valid.
  for (std::size_t t = state_.running.size(); t-- > 0;) {
    if (entered[t]) {
      finish(t, SequenceEnd::Entered);
    } else if (!trackMatched[t] && ++state_.running[t].missed > params_.maxMissedScans) {
      finish(t, SequenceEnd::Lost);
    }
  }
  for (std::size_t h = 0; h < world.size(); ++h) {
    if (hypothesisUsed[h] || observations[h].distanceM > params_.startDistanceM ||
        depthPastEntrance(world[h], robot) > params_.entryDepthM)
      continue;
    RunningSequence track;
    track.sequence.id = state_.nextId++;
    track.sequence.gatewayPoints = world[h];
    track.sequence.distances.push_back(observations[h].distanceM);
    track.sequence.observations.push_back(observations[h].observation);
    state_.running.push_back(std::move(track));
  }
}

void HypothesisTracker::followUnmatched(const Eigen::Vector2d& robot, const Pose2D& toSensor,
                                        const KnownVlmObserver& observeKnown, std::vector<bool>& trackMatched,
                                        std::vector<bool>& entered) {
  for (std::size_t t = 0; t < state_.running.size(); ++t) {
    RunningSequence& track = state_.running[t];
    if (trackMatched[t]) continue;
    if (depthPastEntrance(track.sequence.gatewayPoints, robot) > params_.entryDepthM) {
      entered[t] = true;
      continue;
    }
    const std::size_t detections = track.sequence.observations.size() - track.coasted;
    if (!observeKnown || detections < params_.minDetectionsToCoast || track.coasted >= params_.maxCoastedScans ||
        (gatewayCentre(track.sequence.gatewayPoints) - robot).norm() > params_.startDistanceM)
      continue;
    const std::optional<VlmObservation> o = observeKnown(transformed(track.sequence.gatewayPoints, toSensor));
    if (!o) continue;
    trackMatched[t] = true;
    ++track.coasted;
    track.sequence.distances.push_back(o->distanceM);
    track.sequence.observations.push_back(o->observation);
  }
}

void HypothesisTracker::flush() {
  for (RunningSequence& track : state_.running) {
    track.sequence.end = SequenceEnd::Flushed;
    state_.finished.push_back(std::move(track.sequence));
  }
  state_.running.clear();
}

std::vector<TrackedSequence> HypothesisTracker::takeFinished() { return std::exchange(state_.finished, {}); }

}  // namespace rgnav
