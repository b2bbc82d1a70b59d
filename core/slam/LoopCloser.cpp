// Candidate submaps by distance, registration against each, constraints from the accepted ones.
#include "core/slam/LoopCloser.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rgnav {

LoopCloser::LoopCloser(const LoopClosureConfig& loop, const IcpConfig& icp)
    : config_(loop), icp_(icp), pyramidLevels_(pyramidLevelsFor(loop.maxWindowTranslation, loop.grid.resolution)) {}

SearchWindow LoopCloser::window(double distanceSinceLoop) const {
  return {std::min(config_.maxWindowTranslation, config_.windowTranslation + config_.windowTranslationPerMetre * distanceSinceLoop),
          std::min(config_.maxWindowRotation, config_.windowRotation + config_.windowRotationPerMetre * distanceSinceLoop)};
}

std::vector<Constraint> LoopCloser::search(const SlamState& state, KeyframeIndex current,
                                           std::span<const std::vector<Eigen::Vector2f>> normals) {
  const Keyframe& keyframe = state.keyframes[current];
  const RegistrationCriteria criteria{window(state.distanceSinceLoop), config_.minScore, config_.minInlierFraction,
                                     config_.undetermined};
  std::vector<std::pair<double, std::size_t>> candidates;
  for (std::size_t s = 0; s < state.submaps.size(); ++s) {
    const SubmapRecord& submap = state.submaps[s];
    const std::size_t last = submap.first + submap.memberPoses.size() - 1;
    if (last + config_.excludeRecentKeyframes > current) continue;
    const Pose2D& anchor = state.keyframes[submap.anchor].pose;
    const double distance = std::hypot(anchor.x - keyframe.pose.x, anchor.y - keyframe.pose.y);
    if (distance <= config_.candidateRadius + criteria.window.translation) candidates.emplace_back(distance, s);
  }
  std::sort(candidates.begin(), candidates.end());
  if (candidates.size() > config_.maxCandidates) candidates.resize(config_.maxCandidates);

  std::vector<Constraint> constraints;
  for (const auto& [distance, s] : candidates) {
    const SubmapRecord& submap = state.submaps[s];
    const ReferenceMap& reference = submapReference(state, s, normals);
    const Pose2D guess = between(state.keyframes[submap.anchor].pose, keyframe.pose);
    const auto match = registerScan(reference, keyframe.points, guess, criteria, icp_);
    if (!match) continue;
    Constraint constraint;
    constraint.kind = Constraint::Kind::Loop;
    constraint.from = submap.anchor;
    constraint.to = current;
    constraint.measurement = match->pose;
    constraint.information = match->information;
    constraints.push_back(constraint);
  }
  return constraints;
}

const ReferenceMap& LoopCloser::submapReference(const SlamState& state, std::size_t submap,
                                                std::span<const std::vector<Eigen::Vector2f>> normals) {
  const auto hit = std::find_if(cache_.begin(), cache_.end(), [submap](const auto& entry) { return entry.first == submap; });
  if (hit != cache_.end()) {
    cache_.splice(cache_.begin(), cache_, hit);
    return *cache_.front().second;
  }
  std::unique_ptr<ReferenceMap> reference;
  if (cache_.size() >= config_.cachedSubmaps) {
    reference = std::move(cache_.back().second);
    cache_.pop_back();
  } else {
    reference = std::make_unique<ReferenceMap>(config_.grid, pyramidLevels_);
  }
  const SubmapRecord& record = state.submaps[submap];
  reference->clear();
  for (std::size_t m = 0; m < record.memberPoses.size(); ++m) {
    const std::size_t k = record.first + m;
    reference->add(state.keyframes[k].points, normals[k], record.memberPoses[m]);
  }
  reference->build();
  cache_.emplace_front(submap, std::move(reference));
  return *cache_.front().second;
}

}  // namespace rgnav
