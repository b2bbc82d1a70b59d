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

void HypothesisTracker::finish(std::size_t index, SequenceEnd end) {
  running_[index].sequence.end = end;
  finished_.push_back(std::move(running_[index].sequence));
  running_.erase(running_.begin() + static_cast<std::ptrdiff_t>(index));
}

void HypothesisTracker::update(const Pose2D& sensorPose, const std::vector<VlmObservation>& observations) {
  const Eigen::Vector2d robot(sensorPose.x, sensorPose.y);
  std::vector<GatewayPoints> world;
  world.reserve(observations.size());
  for (const VlmObservation& o : observations) world.push_back(transformed(o.hypothesis.gatewayPoints, sensorPose));

  // Candidate matches (distance, track, hypothesis), closest first.
  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
  for (std::size_t t = 0; t < running_.size(); ++t)
    for (std::size_t h = 0; h < world.size(); ++h)
      if (const double d = largestPointDistance(running_[t].sequence.gatewayPoints, world[h]);
          d <= params_.matchToleranceM)
        candidates.emplace_back(d, t, h);
  std::sort(candidates.begin(), candidates.end());

  std::vector<bool> trackMatched(running_.size(), false), hypothesisUsed(world.size(), false);
  std::vector<bool> entered(running_.size(), false);
  for (const auto& [d, t, h] : candidates) {
    if (trackMatched[t] || hypothesisUsed[h]) continue;
    trackMatched[t] = hypothesisUsed[h] = true;
    Track& track = running_[t];
    track.missed = 0;
    track.sequence.gatewayPoints = world[h];
    if (depthPastEntrance(world[h], robot) > params_.entryDepthM) {
      entered[t] = true;
      continue;
    }
    track.sequence.distances.push_back(observations[h].distanceM);
    track.sequence.observations.push_back(observations[h].weights);
  }
  // Finish from the back so that indices stay valid.
  for (std::size_t t = running_.size(); t-- > 0;) {
    if (entered[t]) {
      finish(t, SequenceEnd::Entered);
    } else if (!trackMatched[t] && ++running_[t].missed > params_.maxMissedScans) {
      finish(t, SequenceEnd::Lost);
    }
  }
  for (std::size_t h = 0; h < world.size(); ++h) {
    if (hypothesisUsed[h] || observations[h].distanceM > params_.startDistanceM ||
        depthPastEntrance(world[h], robot) > params_.entryDepthM)
      continue;
    Track track;
    track.sequence.id = nextId_++;
    track.sequence.gatewayPoints = world[h];
    track.sequence.distances.push_back(observations[h].distanceM);
    track.sequence.observations.push_back(observations[h].weights);
    running_.push_back(std::move(track));
  }
}

void HypothesisTracker::flush() {
  for (Track& track : running_) {
    track.sequence.end = SequenceEnd::Flushed;
    finished_.push_back(std::move(track.sequence));
  }
  running_.clear();
}

std::vector<TrackedSequence> HypothesisTracker::takeFinished() { return std::exchange(finished_, {}); }

}  // namespace rgnav
