// RgMappingKernel: the RG Mapping Kernel's core (thesis 2.2, 5.2, 6.1.1), free of middleware. It takes
// the aligned scans (ScanMapper) and the gateway hypotheses (GatewayDetection) by ID and keeps the
// RG Map consistently structured:
//   - Stacking (2.2): every scan goes into the current region; its line map and preliminary
//     description are available at any time (currentRegion()).
//   - Detected / Updated gateway: the hypothesis is placed into the map frame (GatewayGeometry.h)
//     and the current region is attached on the side the robot is on (GatewayGeometry.h), unless
//     (ours) the robot sees that side's crossing point through another door's line: then it
//     looks into the region beyond that door, which need not be its own. Only for doors (ours): a
//     hallway area's sides are attached by the traversals the detector reports, never by where
//     the robot stood when the area was seen. Areas are squares classified from a few sequences
//     and often sit among furniture, so "near a crossing point" put the robot on the wrong side
//     and joined regions that are not one. Loops through a hallway area close when it is
//     traversed.
//   - A door the detector reports under a new ID where the map already has a door (the
//     detector's odometry drifted since, or it lost the first track) is the known door seen again
//     (6.1.1; ours: matched by position in the map frame): the new ID becomes an alias of it, and
//     its traversals and sides are the known door's. Both tracks report the robot passing the
//     door: a traversal into the current region right after the robot came in through the same
//     gateway (reported or repaired) changes nothing.
//   - A traversed hallway area that fewer than minAreaSequences observation sequences support
//     changes no structure yet (ours): one sequence often finds a crossing among furniture or at a
//     door across the hallway.
//   - A traversed door that does not separate its two sides (DoorSeparation.h: the scans around it
//     show free floor around its ends, as around a pillar or a cabinet's corner) is no door: the
//     regions on its two sides are one, it is neutralised and the robot stays where it is (ours).
//     The same for a traversed hallway area whose two sides the robot went between are joined by
//     floor around its square (a room's corner or a gap between desks classified as a junction;
//     DoorSeparation.h).
//   - Traversed gateway: the region left behind is finalised (RegionFinalised, or RegionUpdated
//     after a revisit: its description is then computed from all its scans), and the robot enters
//     the region on the other side: the one already known there (a revisit updates it, thesis
//     2.2) or a new one. Scans at or after the traversal scan that were stacked before the event
//     came move along into the entered region.
//   - Loop closing (6.1.1, figures 6.1, 6.2): a door observed or any gateway traversed from a side that
//     already lies in another region than the current one means both are the same place: they are
//     merged (the lower ID stays). A gateway with the same region on both sides is neutralised:
//     kept (it still serves localisation), flagged, and it joins no two regions.
//   - Missed traversals (6.1.1, figure 6.4): when the robot observes or traverses a gateway from
//     a side whose region is not the current one, and its path in this visit of the current
//     region crossed the gateway's line onto that side without a traversal being reported, the
//     region is split at that crossing: the scans from there on (and the gateway sides attached
//     since) form a new region on the robot's side, which then joins whatever region already lies
//     there; the names of the objects it holds go with it. Deliberate difference: the thesis
//     leaves such errors to later loop closings ("temporary inconsistency"); we repair what the
//     current visit shows and leave earlier visits to loop closing. Not for hallway areas
//     (GatewayGeometry.h).
//   - A known door passed unreported (ours): the detector tracks doors in its odometry frame and
//     loses them as odometry drifts, so on a later pass it may report nothing. After every scan,
//     a robot that stands on a known door's side (GatewayGeometry.h: near its crossing point, not
//     through another door) whose region is not the current one, having crossed the door's line
//     in this visit, is treated as above: the missed traversal is repaired. A traversal the
//     detector reports late for that passage then changes nothing (without it, a hallway region
//     swept through rooms past known doors).
//   - Requests: merge two regions (e.g. "these are the same room", 6.1.1) and undo one of the latest
//     such merges (ours: RevertibleMerges.h), name regions and objects (semantics),
//     revise corrected poses (SLAM loop closures: descriptions follow, RegionModels.h), learn RG
//     Graph costs (5.4).
// Every change is an RgMapEvent; the whole state is RgMapState (serialise it with RgMapCodec.h).
// Same inputs, same map: nothing depends on addresses, hashing or time.
// Deliberate differences: the thesis matches scans within a region (ScanStudio); we take the
// ScanMapper's corrected poses as they are and treat a corrected pose as the sensor pose (as the
// ScanMapper does). A hallway area joins at most two regions here: the side of its first
// traversal's start and the side that traversal went to; traversals through its further sides
// change no structure. Labels that are no transition
// (Deadend, Hallway, and Wider-Twin for a passage beside a door, PassageTracker.h) drop a gateway
// that was never traversed; one that was traversed keeps the label and joins nothing: the regions
// on its two sides are merged (it is neutralised). A traversal reported with such a label is taken
// as the relabelling (the detector may relabel a gateway in the scan the robot crosses it). Such a
// label on a detector ID that is an alias of a known door takes only the alias away, and no new
// ID becomes an alias of a gateway so labelled.
// The final description is computed when first asked for (a checkpoint does not hold it), not at
// finalisation, so that a region that cannot be described never blocks the structuring.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/gateways/detection/GatewayRecord.h"
#include "core/rgmap/graph/RgGraph.h"
#include "core/rgmap/kernel/DoorSeparation.h"
#include "core/rgmap/kernel/GatewayGeometry.h"
#include "core/rgmap/kernel/RegionModels.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

struct RgMappingKernelConfig {
  SideEvidenceConfig sides;
  double sameDoorM = 0.5;  // a new detector ID whose door lies within this of a known door's is that door
  std::size_t minAreaSequences = 2;  // a hallway area seen in fewer observation sequences joins no regions
  DoorSeparationConfig separation;   // a traversed door that does not separate joins its regions
  std::size_t revertibleMerges = 8;  // the latest merges on request that can be undone (unmergeRegions)
  RegionModelConfig models;
  EdgeCostConfig costs;
};

template <class V>
void describe(V& v, RgMappingKernelConfig& c) {
  v.section("sides", c.sides);
  v.field("same_door_m", c.sameDoorM);
  v.field("min_area_sequences", c.minAreaSequences);
  v.section("separation", c.separation);
  v.field("revertible_merges", c.revertibleMerges);
  v.section("models", c.models);
  v.section("costs", c.costs);
}

// A revised corrected pose of scan `scanId` (map frame).
struct CorrectedPose {
  DataId scanId = 0;
  Pose2D pose;
};

// The current region with its line map and (preliminary) description, valid until the next change.
struct CurrentRegion {
  const Region& region;
  const RegionLineMap& lines;
  const RegionDescription& description;
};

class RgMappingKernel {
 public:
  // An empty map. Throws ConfigError / InvalidArgumentError for a bad configuration.
  explicit RgMappingKernel(const RgMappingKernelConfig& config = {});
  // Resumes from a saved state (RgMapCodec.h). Throws InvalidArgumentError naming the first
  // violation of checkConsistency() or a learned cost the cost table refuses.
  RgMappingKernel(const RgMappingKernelConfig& config, RgMapState state);

  // Stacks the scan into the current region (the first scan creates region 1 with its frame at
  // `corrected`). Throws InvalidArgumentError (and changes nothing) for an ID not above
  // state().lastScanId or a non-finite pose.
  void addScan(const LaserScan& scan, const Pose2D& corrected);

  // Takes in one event of the gateway detector; `lastScanCorrected` is the corrected pose of the
  // scan event.gateway.lastScan. Throws InvalidArgumentError (and changes nothing) for an ID not
  // above state().lastGatewayEventId, a malformed event (validateGatewayEvent, KernelInputs.h) or
  // a non-finite pose.
  void addGatewayEvent(const GatewayEvent& event, const Pose2D& lastScanCorrected);

  // New corrected poses from SLAM, those of pose revision `revision` (state().lastPoseRevision
  // becomes it). Poses of scans the kernel does not hold still re-place the gateways last seen
  // in them. Throws InvalidArgumentError (and changes nothing) for a non-finite pose.
  void revisePoses(std::span<const CorrectedPose> poses, std::uint64_t revision);

  // Merges two regions on request; returns the merged region (the lower ID). Throws
  // InvalidArgumentError (and changes nothing) for an unknown region, a == b, or two regions that
  // share no gateway unless `force`: rooms with no gateway between them (offices on opposite
  // sides of a hallway) are rarely one room. The latest config.revertibleMerges merges on request
  // can be undone (the kernel's own loop closings cannot).
  RegionId mergeRegions(RegionId a, RegionId b, bool force);
  // Undoes the latest merge on request that made region `merged` (RevertibleMerges.h says what
  // comes back, where scans taken since go and when it is safe); returns the restored region.
  // Throws InvalidArgumentError (and changes nothing) if no such merge is among the latest
  // config.revertibleMerges, or the map changed since so that the undo is not safe, saying how.
  RegionId unmergeRegions(RegionId merged);

  // Names a region (an empty name removes the name). Throws InvalidArgumentError for an unknown
  // region or a name another region has.
  void nameRegion(RegionId region, const std::string& name);
  std::optional<RegionId> regionByName(const std::string& name) const;
  // Names the object of region `region` at `atInRegion` (region frame; ObjectNames.h says which
  // object that is), replacing a name it had; an empty name removes its name. Throws
  // InvalidArgumentError for a non-finite point, an unknown region, no object there, or a name
  // another object has.
  void nameObject(RegionId region, const Eigen::Vector2d& atInRegion, const std::string& name);
  // The region holding the object named `name` and the object's centre in the map frame when it
  // was named.
  struct NamedObject {
    RegionId region;
    Eigen::Vector2d namedAt = Eigen::Vector2d::Zero();
  };
  std::optional<NamedObject> objectByName(const std::string& name) const;

  // Cost adaptation of the RG Graph (EdgeCostTable.h). Throw InvalidArgumentError for an edge or
  // door that is not in the graph, or bad measurements.
  void recordEdgeTraversal(const EdgeKey& edge, double lengthM, double timeS);
  void recordDoorState(GatewayId gateway, bool traversable);

  const RgMapState& state() const { return state_; }
  RegionId currentRegionId() const { return state_.current; }
  // Throws NotAvailableError before the first input.
  CurrentRegion currentRegion() const;
  // The line map / description of a region in its own frame. Throw NotAvailableError for an
  // unknown region (and InvalidArgumentError as RegionModels.h says).
  const RegionLineMap& lineMap(RegionId region) const;
  const RegionDescription& description(RegionId region) const;
  // A gateway's points in the frame of one of its regions (or any region). Throws
  // NotAvailableError for an unknown gateway or region.
  PlacedGateway gatewayInRegion(GatewayId gateway, RegionId region) const;

  // The events after `afterId`, oldest first.
  std::vector<RgMapEvent> eventsSince(RgMapEventId afterId) const;
  // The RG Graph of the map now, with the learned costs (RgMapGraph.h).
  RgGraph graph() const;
  // checkConsistency(state()) (RgMapConsistency.h).
  std::vector<std::string> checkConsistency() const;

 private:
  void ensureCurrentRegion(const Pose2D& frame, DataId scan);
  void observe(const GatewayEvent& event, const Pose2D& odomToMap, const Pose2D& robot);
  void traverse(const GatewayEvent& event, const Pose2D& odomToMap);
  std::optional<GatewayId> findGateway(DetectorGatewayId detectorId) const;
  // The door of the map nearest to `record`'s, if its gateway points lie within config.sameDoorM
  // (passageEndsDistance).
  std::optional<GatewayId> sameDoorAs(const GatewayRecord& record, const Pose2D& odomToMap) const;
  // The kernel's gateway for the detector's record, added or refreshed.
  GatewayId takeIn(const GatewayRecord& record, const Pose2D& odomToMap, bool announceUpdate, DataId scan);
  // The index of gateway `id`'s crossing point that crossing point `k` of `record` names (the
  // record may be an alias's, with its own numbering).
  std::size_t crossingOf(GatewayId id, const GatewayRecord& record, const Pose2D& odomToMap, std::size_t k) const;
  // The side of gateway `id` with crossing point `crossing`; a hallway area's unknown side takes it.
  std::optional<std::size_t> sideOf(GatewayId id, std::size_t crossing);
  // `region` lies on side `side` of gateway `id`: attach it, or merge it with the region there.
  // Returns the region that lies there now.
  RegionId joinSide(GatewayId id, std::size_t side, RegionId region, DataId scan);
  // The repair of a missed traversal (see above), looking at the current visit's scans before
  // `before`; whether there was one to repair.
  bool repairMissedCrossing(GatewayId id, std::size_t robotSide, DataId before);
  // A known door the robot's path crossed without a traversal report (see above), repaired once
  // the robot stands on the door's other side.
  void repairPassedDoor(const Pose2D& robot, DataId scan);
  // The robot left `region` at `scan`: finalised, or removed if it holds no scan.
  void leave(RegionId region, DataId scan);

  RgMappingKernelConfig config_;
  RgMapState state_;
  mutable RegionModels models_;
};

}  // namespace rgnav
