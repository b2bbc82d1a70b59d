// GatewayRecord and GatewayEvent: the entries of the GatewayDetection module's buffer of gateway
// hypotheses (thesis 5.2: "The GDM stacks this information in a buffer that is processed by the
// RG Mapping Kernel"; the gateway features of 2.1.2 and table 2.1: class label, gateway points,
// crossing points, traversal directions). Every change to the buffer is an event with an ID, so
// a consumer follows it by ID like any other data stream. Positions are in the frame of the
// poses the detector was given (the module gives it the odometry poses of the scans);
// `lastScan` and `lastPose` say where a gateway was last seen from, so a consumer places it into
// the map frame with that scan's corrected pose. A hallway area whose evidence turns to Deadend
// or Hallway stays in the buffer with that label: it is no longer thought to be a gateway.
// Door confirmation by vision (4.2.2) will add its evidence to a narrow passage's record as one
// more class ("Door") with its probability; the record needs no other field for it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/common/TypedId.h"

namespace rgnav {

// The detector numbers its gateways from 1; the RG Mapping Kernel numbers the gateways it takes
// in with its own GatewayId. An event's ID is its position in the detector's event buffer
// (DataBuffer), numbered like every buffer's records.
using DetectorGatewayId = TypedId<struct DetectorGatewayConcept>;
using GatewayEventId = DataId;

// Narrow passages (4.2.1) are lines the robot crosses; hallway gateways (turns, junctions,
// crossings of 4.1) are square areas the robot enters on one side and leaves on another.
enum class GatewayKind { NarrowPassage, HallwayArea };

inline constexpr const char* kNarrowPassageClass = "Narrow-Passage";
// A narrow passage superseded by a narrower one it shares a gateway point with, the same opening
// seen askew (PassageTracker.h): no transition.
inline constexpr const char* kWiderTwinClass = "Wider-Twin";

struct ClassProbability {
  std::string name;  // "Narrow-Passage", "Wider-Twin", or a GatewayClass name ("X-Crossing", ...)
  double probability = 0.0;

  friend bool operator==(const ClassProbability&, const ClassProbability&) = default;
};

struct GatewayRecord {
  DetectorGatewayId id;
  GatewayKind kind = GatewayKind::NarrowPassage;
  std::vector<ClassProbability> classes;  // the most probable first
  // Narrow passage: P_left, P_right. Hallway area: hidden-left, front-left, front-right,
  // hidden-right of the gateway area (the corners of the square, GatewayPoints.h).
  std::vector<Eigen::Vector2d> gatewayPoints;
  // One point per side a region lies on, just off the gateway: a narrow passage has two (the
  // side it was first seen from first); a hallway area has one per side of its square, in the
  // order of the sides hidden, left, front, right.
  std::vector<Eigen::Vector2d> crossingPoints;
  double widthM = 0.0;
  DataId firstScan = 0;  // the scan it was first seen in
  DataId lastScan = 0;   // the scan it was last seen in ...
  Pose2D lastPose;       // ... and the robot pose of that scan used to place it
  std::size_t support = 0;     // scans (passages) or observation sequences (hallway areas)
  std::size_t traversals = 0;

  const std::string& label() const { return classes.front().name; }
  // False when the most probable class is a counter-class (Deadend, Hallway) or Wider-Twin: the
  // evidence says this is no transition between regions.
  bool isTransition() const;

  friend bool operator==(const GatewayRecord&, const GatewayRecord&) = default;
};

// The robot went through a gateway: from crossing point `fromSide` to crossing point `toSide`
// (indices into GatewayRecord::crossingPoints); `at` is where its path crossed into the far side.
struct TraversalReport {
  DataId scanId = 0;
  std::size_t fromSide = 0;
  std::size_t toSide = 1;
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit vector, from side to side

  friend bool operator==(const TraversalReport&, const TraversalReport&) = default;
};

enum class GatewayEventKind { Detected, Updated, Traversed };

struct GatewayEvent {
  GatewayEventId id = 0;
  GatewayEventKind kind = GatewayEventKind::Detected;
  GatewayRecord gateway;       // as it is after the event
  TraversalReport traversal;  // Traversed only
  DataId scanId = 0;          // the scan whose processing caused the event

  friend bool operator==(const GatewayEvent&, const GatewayEvent&) = default;
};

}  // namespace rgnav
