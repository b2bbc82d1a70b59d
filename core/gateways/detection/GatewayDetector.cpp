// The GatewayDetection module's work on one scan; see GatewayDetector.h.
#include "core/gateways/detection/GatewayDetector.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/common/Errors.h"
#include "core/gateways/vlm/GatewayPoints.h"

namespace rgnav {
namespace {

// Classes by decreasing probability.
std::vector<ClassProbability> ranked(const GatewayPosterior& posterior) {
  std::vector<ClassProbability> out;
  for (std::size_t i = 0; i < posterior.classes.size(); ++i)
    out.push_back({std::string(gatewayClassName(posterior.classes[i])), posterior.probabilities(static_cast<Eigen::Index>(i))});
  std::stable_sort(out.begin(), out.end(),
                   [](const ClassProbability& a, const ClassProbability& b) { return a.probability > b.probability; });
  return out;
}

Eigen::Vector2d position(const Pose2D& pose) { return {pose.x, pose.y}; }

}  // namespace

GatewayDetector::GatewayDetector(const GatewayDetectorConfig& config, std::optional<HmmClassifier> classifier,
                                 GatewayDetectorState state)
    : config_(config),
      classifier_(std::move(classifier)),
      passageDetector_(config.passages),
      passageTracker_(config.passageTracking, std::move(state.passages)),
      sequenceTracker_(config.sequences, std::move(state.sequences)),
      passageIds_(std::move(state.passageIds)),
      areaIds_(std::move(state.areaIds)),
      nextGatewayId_(state.nextGatewayId),
      nextEventId_(state.nextEventId),
      lastScan_(state.lastScan) {
  if (!(config_.crossingOffsetM > 0.0)) throw ConfigError("gateway detection: crossingOffsetM must be positive");
  if (classifier_) {
    observer_.emplace(config_.hallways);
    areaTracker_ = std::make_unique<HallwayAreaTracker>(config_.areas, *classifier_, std::move(state.areas));
  }
}

GatewayDetectorState GatewayDetector::state() const {
  GatewayDetectorState s;
  s.passages = passageTracker_.state();
  s.sequences = sequenceTracker_.state();
  if (areaTracker_) s.areas = areaTracker_->state();
  s.passageIds = passageIds_;
  s.areaIds = areaIds_;
  s.nextGatewayId = nextGatewayId_;
  s.nextEventId = nextEventId_;
  s.lastScan = lastScan_;
  return s;
}

GatewayEvent GatewayDetector::event(GatewayEventKind kind, GatewayRecord record, TraversalReport traversal) {
  return GatewayEvent{nextEventId_++, kind, std::move(record), traversal, lastScan_};
}

GatewayRecord GatewayDetector::passageRecord(const TrackedGateway& track, DetectorGatewayId id) const {
  GatewayRecord r;
  r.id = id;
  r.kind = GatewayKind::NarrowPassage;
  r.classes = {{track.superseded ? kWiderTwinClass : kNarrowPassageClass, track.meanConfidence}};
  r.gatewayPoints = {track.left, track.right};
  // P_right -> P_left turned right points away from the side the passage was first seen from.
  const Eigen::Vector2d along = (track.left - track.right).normalized();
  const Eigen::Vector2d away(along.y(), -along.x());
  r.crossingPoints = {track.midpoint() - config_.crossingOffsetM * away, track.midpoint() + config_.crossingOffsetM * away};
  r.widthM = track.widthM();
  r.firstScan = track.firstScan;
  r.lastScan = track.lastScan;
  r.lastPose = track.lastRobotPose;
  r.support = track.support;
  r.traversals = track.traversals;
  return r;
}

GatewayRecord GatewayDetector::areaRecord(std::size_t index, DetectorGatewayId id) const {
  const HallwayArea& area = areaTracker_->state().areas.at(index);
  GatewayRecord r;
  r.id = id;
  r.kind = GatewayKind::HallwayArea;
  r.classes = ranked(areaTracker_->classes(index));
  r.gatewayPoints.assign(area.points.begin(), area.points.end());
  const Eigen::Vector2d centre = gatewayCentre(area.points);
  for (std::size_t side = 0; side < 4; ++side) {
    const Eigen::Vector2d mid = sideMidpoint(area.points, side);
    r.crossingPoints.push_back(mid + config_.crossingOffsetM * (mid - centre).normalized());
  }
  r.widthM = (area.points[kHiddenLeft] - area.points[kHiddenRight]).norm();
  r.firstScan = area.firstScan;
  r.lastScan = area.lastScan;
  r.lastPose = area.lastRobotPose;
  for (const HallwayView& v : area.views) r.support += v.sequences;
  r.traversals = area.traversals;
  return r;
}

std::vector<GatewayEvent> GatewayDetector::addScan(const LaserScan& scan, const Pose2D& robotPose) {
  if (scan.id <= lastScan_)
    throw InvalidArgumentError("gateway detection: scan " + std::to_string(scan.id) + " after scan " +
                               std::to_string(lastScan_) + "; scans must come in ID order");
  lastScan_ = scan.id;
  std::vector<GatewayEvent> out;
  detectPassages(scan, robotPose, out);
  if (classifier_) detectHallways(scan, robotPose, out);
  return out;
}

void GatewayDetector::detectPassages(const LaserScan& scan, const Pose2D& robotPose, std::vector<GatewayEvent>& out) {
  const TrackerUpdate update = passageTracker_.update(scan.id, robotPose, passageDetector_.detect(scan, robotPose));
  // Wider twins first: a consumer that matches a new door to known ones by position (the RG
  // mapping kernel) then knows the twin for what it is before it sees the door that superseded it.
  for (const PassageTrackId track : update.superseded)
    out.push_back(event(GatewayEventKind::Updated, passageRecord(*passageTracker_.find(track), passageIds_.at(track))));
  for (const PassageTrackId track : update.confirmed) {
    const DetectorGatewayId id = passageIds_[track] = nextGatewayId_++;
    out.push_back(event(GatewayEventKind::Detected, passageRecord(*passageTracker_.find(track), id)));
  }
  for (const GatewayTraversal& t : update.traversals) {
    const TrackedGateway& track = *passageTracker_.find(t.gateway);
    GatewayRecord record = passageRecord(track, passageIds_.at(t.gateway));
    // Crossing point 0 lies on the side the passage was first seen from.
    TraversalReport report{scan.id, t.fromObservedSide ? 0u : 1u, t.fromObservedSide ? 1u : 0u, t.crossing, {}};
    report.direction = (record.crossingPoints[report.toSide] - record.crossingPoints[report.fromSide]).normalized();
    out.push_back(event(GatewayEventKind::Traversed, std::move(record), report));
  }
}

void GatewayDetector::detectHallways(const LaserScan& scan, const Pose2D& robotPose, std::vector<GatewayEvent>& out) {
  sequenceTracker_.update(robotPose, observer_->observe(scan),
                          [&](const GatewayPoints& points) { return observer_->observeAt(points, scan); });
  for (const TrackedSequence& sequence : sequenceTracker_.takeFinished()) {
    const std::optional<std::size_t> area = areaTracker_->addSequence(sequence, scan.id, robotPose);
    if (!area) continue;
    const auto known = areaIds_.find(*area);
    if (known != areaIds_.end()) {
      out.push_back(event(GatewayEventKind::Updated, areaRecord(*area, known->second)));
    } else if (areaTracker_->isGateway(*area)) {
      const DetectorGatewayId id = areaIds_[*area] = nextGatewayId_++;
      out.push_back(event(GatewayEventKind::Detected, areaRecord(*area, id)));
    }
  }
  for (const AreaPassing& passing : areaTracker_->move(position(robotPose))) {
    const auto known = areaIds_.find(passing.area);
    if (known == areaIds_.end()) continue;
    GatewayRecord record = areaRecord(passing.area, known->second);
    TraversalReport report{scan.id, passing.fromSide, passing.toSide, passing.at, {}};
    report.direction = (record.crossingPoints[passing.toSide] - record.crossingPoints[passing.fromSide]).normalized();
    out.push_back(event(GatewayEventKind::Traversed, std::move(record), report));
  }
}

std::vector<GatewayRecord> GatewayDetector::gateways() const {
  std::vector<GatewayRecord> out;
  for (const auto& [track, id] : passageIds_) out.push_back(passageRecord(*passageTracker_.find(track), id));
  for (const auto& [area, id] : areaIds_) out.push_back(areaRecord(area, id));
  std::sort(out.begin(), out.end(), [](const GatewayRecord& a, const GatewayRecord& b) { return a.id < b.id; });
  return out;
}

}  // namespace rgnav
