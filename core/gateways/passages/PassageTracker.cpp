// Tracking narrow passages over scans (see PassageTracker.h).
#include "core/gateways/passages/PassageTracker.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>

#include "core/common/Errors.h"
#include "core/gateways/passages/SegmentCrossing.h"

namespace rgnav {
namespace {

// Side of p relative to the directed line right -> left: true for its left.
bool leftOf(const TrackedGateway& g, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = g.left - g.right, q = p - g.right;
  return d.x() * q.y() - d.y() * q.x() > 0.0;
}

}  // namespace

void validate(const PassageTrackerConfig& config) {
  if (!std::isfinite(config.associationDistanceM) || config.associationDistanceM <= 0.0)
    throw ConfigError("passage tracker: associationDistanceM must be positive and finite");
  if (config.minSupport == 0) throw ConfigError("passage tracker: minSupport must be at least 1");
  if (config.forgetAfterUpdates == 0) throw ConfigError("passage tracker: forgetAfterUpdates must be at least 1");
}

PassageTracker::PassageTracker(const PassageTrackerConfig& config) : config_(config) { validate(config_); }

TrackerUpdate PassageTracker::update(DataId scanId, const Pose2D& robotPose,
                                     const std::vector<PassageHypothesis>& hypotheses) {
  ++updates_;
  TrackerUpdate out;
  traverse(scanId, robotPose, out);
  for (const PassageHypothesis& h : hypotheses) associate(h, out);
  for (std::size_t i = tracks_.size(); i-- > 0;) {
    if (tracks_[i].confirmed || updates_ - sums_[i].lastUpdate < config_.forgetAfterUpdates) continue;
    tracks_.erase(tracks_.begin() + static_cast<std::ptrdiff_t>(i));
    sums_.erase(sums_.begin() + static_cast<std::ptrdiff_t>(i));
  }
  return out;
}

void PassageTracker::traverse(DataId scanId, const Pose2D& robotPose, TrackerUpdate& out) {
  const Eigen::Vector2d from(lastPose_.x, lastPose_.y), to(robotPose.x, robotPose.y);
  const bool moved = hasPose_;
  hasPose_ = true;
  lastPose_ = robotPose;
  if (!moved) return;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    TrackedGateway& g = tracks_[i];
    if (!g.confirmed) continue;
    const auto at = segmentCrossing(from, to, g.left, g.right);
    if (!at) continue;
    ++g.traversals;
    // The first hypothesis was seen from the left of right -> left (the scanner sweeps from
    // P_right to P_left counter-clockwise).
    out.traversals.push_back({g.id, scanId, *at, leftOf(g, from)});
  }
}

void PassageTracker::associate(const PassageHypothesis& h, TrackerUpdate& out) {
  std::optional<std::size_t> best;
  bool bestSwapped = false;
  double bestCost = config_.associationDistanceM;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const TrackedGateway& g = tracks_[i];
    const double straight = std::max((h.left - g.left).norm(), (h.right - g.right).norm());
    const double swapped = std::max((h.left - g.right).norm(), (h.right - g.left).norm());
    const double cost = std::min(straight, swapped);
    if (cost <= bestCost) {
      best = i;
      bestCost = cost;
      bestSwapped = swapped < straight;
    }
  }
  if (!best) {
    best = tracks_.size();
    tracks_.push_back({nextId_++});
    tracks_.back().firstScan = h.scanId;
    sums_.emplace_back();
  }
  TrackedGateway& g = tracks_[*best];
  Sums& s = sums_[*best];
  s.left += bestSwapped ? h.right : h.left;
  s.right += bestSwapped ? h.left : h.right;
  s.confidence += h.confidence;
  ++g.observations;
  g.left = s.left / double(g.observations);
  g.right = s.right / double(g.observations);
  g.meanConfidence = s.confidence / double(g.observations);
  g.lastScan = h.scanId;
  if (s.lastUpdate != updates_) ++g.support;
  s.lastUpdate = updates_;
  if (!g.confirmed && g.support >= config_.minSupport) {
    g.confirmed = true;
    out.confirmed.push_back(g.id);
  }
}

std::vector<TrackedGateway> PassageTracker::gateways() const {
  std::vector<TrackedGateway> confirmed;
  std::copy_if(tracks_.begin(), tracks_.end(), std::back_inserter(confirmed),
               [](const TrackedGateway& g) { return g.confirmed; });
  return confirmed;
}

}  // namespace rgnav
