// Tracking narrow passages over scans (see PassageTracker.h).
#include "core/gateways/passages/PassageTracker.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "core/common/Errors.h"
#include "core/gateways/passages/PassageEndsDistance.h"
#include "core/gateways/passages/SegmentCrossing.h"

namespace rgnav {
namespace {

// Side of p relative to the directed line right -> left: true for its left.
bool leftOf(const TrackedGateway& g, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = g.left - g.right, q = p - g.right;
  return d.x() * q.y() - d.y() * q.x() > 0.0;
}

// Whether `wider` is a wider twin of `narrower` (see PassageTracker.h).
bool widerTwin(const TrackedGateway& wider, const TrackedGateway& narrower, const PassageTrackerConfig& config) {
  if (wider.widthM() < config.twinWidthFactor * narrower.widthM()) return false;
  bool shared = false;
  for (const Eigen::Vector2d& p : {wider.left, wider.right})
    for (const Eigen::Vector2d& q : {narrower.left, narrower.right}) shared = shared || (p - q).norm() <= config.sharedPointM;
  if (!shared) return false;
  const Eigen::Vector2d a = (wider.left - wider.right).normalized(), b = (narrower.left - narrower.right).normalized();
  return std::abs(a.dot(b)) >= std::cos(config.twinMaxAngleRad);
}

}  // namespace

void validate(const PassageTrackerConfig& config) {
  if (!std::isfinite(config.associationDistanceM) || config.associationDistanceM <= 0.0)
    throw ConfigError("passage tracker: associationDistanceM must be positive and finite");
  if (config.minSupport == 0) throw ConfigError("passage tracker: minSupport must be at least 1");
  if (config.forgetAfterUpdates == 0) throw ConfigError("passage tracker: forgetAfterUpdates must be at least 1");
  if (!std::isfinite(config.sharedPointM) || config.sharedPointM < 0.0)
    throw ConfigError("passage tracker: sharedPointM must be >= 0 and finite");
  if (!(config.twinMaxAngleRad >= 0.0 && config.twinMaxAngleRad <= M_PI / 2.0))
    throw ConfigError("passage tracker: twinMaxAngleRad must lie in [0, pi/2]");
  if (!std::isfinite(config.twinWidthFactor) || config.twinWidthFactor < 1.0)
    throw ConfigError("passage tracker: twinWidthFactor must be >= 1 and finite");
}

PassageTracker::PassageTracker(const PassageTrackerConfig& config) : config_(config) { validate(config_); }

PassageTracker::PassageTracker(const PassageTrackerConfig& config, PassageTrackerState state)
    : config_(config), state_(std::move(state)) {
  validate(config_);
}

TrackerUpdate PassageTracker::update(DataId scanId, const Pose2D& robotPose,
                                     const std::vector<PassageHypothesis>& hypotheses) {
  ++state_.updates;
  TrackerUpdate out;
  traverse(scanId, robotPose, out);
  for (const PassageHypothesis& h : hypotheses) associate(h, robotPose, out);
  supersedeWiderTwins(out);
  std::erase_if(state_.tracks, [&](const PassageTrackState& t) {
    return !t.gateway.confirmed && state_.updates - t.lastUpdate >= config_.forgetAfterUpdates;
  });
  return out;
}

void PassageTracker::traverse(DataId scanId, const Pose2D& robotPose, TrackerUpdate& out) {
  const std::optional<Pose2D> last = state_.lastPose;
  state_.lastPose = robotPose;
  if (!last) return;
  const Eigen::Vector2d from(last->x, last->y), to(robotPose.x, robotPose.y);
  for (PassageTrackState& t : state_.tracks) {
    TrackedGateway& g = t.gateway;
    if (!g.confirmed || g.superseded) continue;
    const auto at = segmentCrossing(from, to, g.left, g.right);
    if (!at) continue;
    ++g.traversals;
    // The first hypothesis was seen from the left of right -> left (the scanner sweeps from
    // P_right to P_left counter-clockwise).
    out.traversals.push_back({g.id, scanId, *at, leftOf(g, from)});
  }
}

void PassageTracker::associate(const PassageHypothesis& h, const Pose2D& robotPose, TrackerUpdate& out) {
  PassageTrackState* best = nullptr;
  bool bestSwapped = false;
  double bestCost = config_.associationDistanceM;
  for (PassageTrackState& t : state_.tracks) {
    const TrackedGateway& g = t.gateway;
    const PassageEndsDistance d = passageEndsDistance(h.left, h.right, g.left, g.right);
    if (d.distanceM <= bestCost) {
      best = &t;
      bestCost = d.distanceM;
      bestSwapped = d.swapped;
    }
  }
  if (!best) {
    best = &state_.tracks.emplace_back();
    best->gateway.id = state_.nextId++;
    best->gateway.firstScan = h.scanId;
  }
  PassageTrackState& t = *best;
  TrackedGateway& g = t.gateway;
  t.leftSum += bestSwapped ? h.right : h.left;
  t.rightSum += bestSwapped ? h.left : h.right;
  t.confidenceSum += h.confidence;
  ++g.observations;
  g.left = t.leftSum / double(g.observations);
  g.right = t.rightSum / double(g.observations);
  g.meanConfidence = t.confidenceSum / double(g.observations);
  g.lastScan = h.scanId;
  g.lastRobotPose = robotPose;
  if (t.lastUpdate != state_.updates) ++g.support;
  t.lastUpdate = state_.updates;
  if (!g.confirmed && g.support >= config_.minSupport) {
    g.confirmed = true;
    out.confirmed.push_back(g.id);
  }
}

void PassageTracker::supersedeWiderTwins(TrackerUpdate& out) {
  std::vector<TrackedGateway*> doors;
  for (PassageTrackState& t : state_.tracks)
    if (t.gateway.confirmed && !t.gateway.superseded) doors.push_back(&t.gateway);
  // Narrowest first, so that a twin is judged against the doors that stay.
  std::stable_sort(doors.begin(), doors.end(),
                   [](const TrackedGateway* a, const TrackedGateway* b) { return a->widthM() < b->widthM(); });
  for (std::size_t k = 0; k < doors.size(); ++k) {
    TrackedGateway& g = *doors[k];
    for (std::size_t n = 0; n < k && !g.superseded; ++n)
      g.superseded = !doors[n]->superseded && widerTwin(g, *doors[n], config_);
    if (!g.superseded) continue;
    // A traversal found earlier in this update (traverse() runs first) was no passage after all.
    g.traversals -= std::size_t(std::erase_if(out.traversals, [&](const GatewayTraversal& t) { return t.gateway == g.id; }));
    const auto justConfirmed = std::find(out.confirmed.begin(), out.confirmed.end(), g.id);
    if (justConfirmed != out.confirmed.end())
      out.confirmed.erase(justConfirmed);
    else
      out.superseded.push_back(g.id);
  }
}

std::vector<TrackedGateway> PassageTracker::tracks() const {
  std::vector<TrackedGateway> all;
  for (const PassageTrackState& t : state_.tracks) all.push_back(t.gateway);
  return all;
}

std::vector<TrackedGateway> PassageTracker::gateways() const {
  std::vector<TrackedGateway> confirmed;
  for (const PassageTrackState& t : state_.tracks)
    if (t.gateway.confirmed && !t.gateway.superseded) confirmed.push_back(t.gateway);
  return confirmed;
}

const TrackedGateway* PassageTracker::find(PassageTrackId id) const {
  for (const PassageTrackState& t : state_.tracks)
    if (t.gateway.id == id) return &t.gateway;
  return nullptr;
}

}  // namespace rgnav
