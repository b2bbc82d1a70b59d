// GatewayDetector: the work of the GatewayDetection module (thesis 5.2, "Gateway Detection
// Module") on one scan at a time: narrow passages (4.2.1, NarrowPassageDetector + PassageTracker)
// and hallway gateways (4.1: VlmObserver, HypothesisTracker, HMM classification with Bayes
// fusion, HallwayAreaTracker), both placed with the robot pose given with the scan. It keeps the buffer
// of gateway hypotheses (GatewayRecord.h): a gateway gets its ID when it is first reported
// (a passage once confirmed, an area once classified as a gateway); every report, update and
// traversal is an event. The whole state can be saved and resumed, so that a restarted module
// goes on exactly where it stopped.
// Where we differ: the thesis ran hallway-gateway detection offline (Matlab) only; here both run
// online. Without trained HMMs (no model file) only narrow passages are detected.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "core/gateways/classify/HmmClassifier.h"
#include "core/gateways/detection/GatewayRecord.h"
#include "core/gateways/detection/HallwayAreaTracker.h"
#include "core/gateways/passages/NarrowPassageDetector.h"
#include "core/gateways/passages/PassageTracker.h"
#include "core/gateways/vlm/HypothesisTracker.h"
#include "core/gateways/vlm/VlmObserver.h"

namespace rgnav {

struct GatewayDetectorConfig {
  NarrowPassageConfig passages;
  PassageTrackerConfig passageTracking;
  VlmObserverParams hallways;  // hypotheses.hallwayWidthM: d_hw of the building
  TrackerParams sequences;
  HallwayAreaConfig areas;
  double crossingOffsetM = 0.5;  // crossing points lie this far off a passage's line
};

template <class V>
void describe(V& v, GatewayDetectorConfig& c) {
  v.section("passages", c.passages);
  v.section("passage_tracking", c.passageTracking);
  v.section("hallways", c.hallways);
  v.section("sequences", c.sequences);
  v.section("areas", c.areas);
  v.field("crossing_offset_m", c.crossingOffsetM);
}

struct GatewayDetectorState {
  PassageTrackerState passages;
  HypothesisTrackerState sequences;
  HallwayAreaState areas;
  std::map<PassageTrackId, DetectorGatewayId> passageIds;  // passage track -> gateway
  std::map<std::size_t, DetectorGatewayId> areaIds;   // area index -> gateway
  DetectorGatewayId nextGatewayId{1};
  GatewayEventId nextEventId = 1;
  DataId lastScan = 0;
};

class GatewayDetector {
 public:
  // `classifier` empty: narrow passages only. Throws ConfigError for a bad configuration,
  // InvalidArgumentError for HMMs that do not fit the observer.
  GatewayDetector(const GatewayDetectorConfig& config, std::optional<HmmClassifier> classifier,
                  GatewayDetectorState state = {});
  GatewayDetector(const GatewayDetector&) = delete;
  GatewayDetector& operator=(const GatewayDetector&) = delete;

  // The scan with the robot's pose when it was taken; scans must come in ID order (an older or equal ID
  // is an InvalidArgumentError). Returns the events it caused, in order.
  std::vector<GatewayEvent> addScan(const LaserScan& scan, const Pose2D& robotPose);

  // The reported gateways, by ID.
  std::vector<GatewayRecord> gateways() const;
  GatewayDetectorState state() const;
  DataId lastScan() const { return lastScan_; }
  bool detectsHallways() const { return classifier_.has_value(); }

 private:
  GatewayRecord passageRecord(const TrackedGateway& track, DetectorGatewayId id) const;
  GatewayRecord areaRecord(std::size_t area, DetectorGatewayId id) const;
  GatewayEvent event(GatewayEventKind kind, GatewayRecord record, TraversalReport traversal = {});
  void detectPassages(const LaserScan& scan, const Pose2D& robotPose, std::vector<GatewayEvent>& out);
  void detectHallways(const LaserScan& scan, const Pose2D& robotPose, std::vector<GatewayEvent>& out);

  GatewayDetectorConfig config_;
  std::optional<HmmClassifier> classifier_;
  NarrowPassageDetector passageDetector_;
  PassageTracker passageTracker_;
  std::optional<VlmObserver> observer_;
  HypothesisTracker sequenceTracker_;
  std::unique_ptr<HallwayAreaTracker> areaTracker_;
  std::map<PassageTrackId, DetectorGatewayId> passageIds_;
  std::map<std::size_t, DetectorGatewayId> areaIds_;
  DetectorGatewayId nextGatewayId_;
  GatewayEventId nextEventId_;
  DataId lastScan_;
};

}  // namespace rgnav
