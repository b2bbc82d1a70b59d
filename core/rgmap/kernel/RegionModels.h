// RegionModels: the metric description M and the properties P of each region (thesis 2.1.1,
// 5.2): its 2D line segment map (RegionLineMap) and its RegionDescription, in the region's own
// frame, computed from the region's aligned scans and its gateway lines (GatewayGeometry.h), its
// beams cut at the doors between other regions (otherDoorLines), at the squares of the hallway
// areas between other regions (otherAreaLines) and just beyond its own doors
// (doorFrameLines), and for scans taken in front of an own door at that door's wall
// (doorWallLines); scans taken just past its own doors add nothing to its evidence (pastOwnDoor).
// Both are pure functions of the map state (the region's scans in ID order with their corrected
// poses, its frame, its gateway lines, the map's doors and areas and, for doors no region is attached to,
// the other regions' scans), so they are not part of a checkpoint:
// a resumed kernel computes the very same ones. They are computed on demand and cached; a cached
// model remembers its inputs and is reused when they are unchanged, extended scan by scan when the
// region only gained scans (the current region while the robot is in it), and rebuilt otherwise
// (merged or split regions, revised poses, moved or new doors). So nobody has to tell the cache
// what changed.
// Memory: the line map and the description evidence (freespace counts, hull, a bounded sample of
// measurements) of every region that was asked for.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <vector>

#include "core/lines/RegionLineMap.h"
#include "core/rgmap/describe/RegionDescription.h"
#include "core/rgmap/describe/RegionEvidence.h"
#include "core/rgmap/kernel/DoorSides.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

// Where doorFrameLines lie.
struct DoorFrameCut {
  double depthM = 0.3;   // beyond the door's line
  double widenM = 1.0;   // longer than the door at each end
};

template <class V>
void describe(V& v, DoorFrameCut& c) {
  v.field("depth_m", c.depthM);
  v.field("widen_m", c.widenM);
}

// Which scans of a region stay out of its freespace evidence (pastOwnDoor).
struct PastOwnDoor {
  double depthM = 1.0;   // up to this far beyond the line of one of its own doors ...
  double besideM = 0.5;  // ... and at most this far beside the door's ends
};

template <class V>
void describe(V& v, PastOwnDoor& c) {
  v.field("depth_m", c.depthM);
  v.field("beside_m", c.besideM);
}

// Which scans of a region have their beams cut at the wall of one of its own doors (doorWallLines).
struct DoorWallCut {
  double frontM = 1.2;   // sensor up to this far in front of the door's line ...
  double besideM = 0.5;  // ... and at most this far beside the door's ends
  double wallM = 3.0;    // the wall: the door's line lengthened this much at each end
};

template <class V>
void describe(V& v, DoorWallCut& c) {
  v.field("front_m", c.frontM);
  v.field("beside_m", c.besideM);
  v.field("wall_m", c.wallM);
}

struct RegionModelConfig {
  LineExtractorParams extractor;
  LineMergerParams merger;
  RegionEvidenceConfig evidence;
  DescriptionParams description;
  DoorFrameCut doorFrames;
  PastOwnDoor pastOwnDoors;
  DoorWallCut doorWalls;
  DoorSideProbe unattachedDoors;  // which doors no region is attached to cut (otherDoorLines)
};

template <class V>
void describe(V& v, RegionModelConfig& c) {
  v.section("extractor", c.extractor);
  v.section("merger", c.merger);
  v.section("evidence", c.evidence);
  v.section("description", c.description);
  v.section("door_frames", c.doorFrames);
  v.section("past_own_doors", c.pastOwnDoors);
  v.section("door_walls", c.doorWalls);
  v.section("unattached_doors", c.unattachedDoors);
}

// The gateway lines of `region` in its own frame: every side of its gateways that lies in it,
// by gateway ID and side.
std::vector<GatewaySegment> regionGatewaySegments(const RgMapState& state, const Region& region);

// The lines of every door that is not neutralised and not the region's own, and has a region on a
// side or separates the region from another one (DoorSides.h; `noReturnFreeRangeM` as the
// region freespace's), in the region's frame. With the
// region's own gateway lines they cut its beams (thesis 5.2: "laser beams that cross a gateway are
// filtered out"; ours: every such door, not only its own): a region also sees through doors
// between other regions (through an open room into the next one), and what lies behind them is no
// part of it either.
// A door no region was ever attached to (neither passed nor observed from near by) cuts only where
// the region's robot stood on one side of it and another region saw it from the other: most such
// doors are no doors (gaps between furniture, a partition's end and a far corner), and cutting at
// all of them took the floor behind them from every region (open cubicles above all); a real door
// between two rooms the robot entered from the hallway is one of them (Freiburg52: each room's
// region saw half the other room through it).
std::vector<GatewaySegment> otherDoorLines(const RgMapState& state, const Region& region,
                                          const DoorSideProbe& probe = {},
                                          double noReturnFreeRangeM = FreespaceConfig{}.noReturnFreeRangeM);

// The four sides of the square of every hallway area that joins two regions, neither of them this
// one (not neutralised), in the region's frame (ours, as otherDoorLines does for doors): a hallway
// region sees along the hallway through the junctions beyond its own, into the parts of the
// hallway other regions hold. A ground-truth hallway, one room, is then covered less by its best
// region, which stops at the next region's junction (docs/EVALUATION.md gives the trade).
std::vector<GatewaySegment> otherAreaLines(const RgMapState& state, const Region& region);

// One of the region's own doors (not neutralised) in the region's frame, with the direction from
// its crossing point in the region to the one beyond.
struct OwnDoor {
  GatewaySegment line;
  Eigen::Vector2d away = Eigen::Vector2d::Zero();
  friend bool operator==(const OwnDoor& a, const OwnDoor& b) {
    return a.line.a == b.line.a && a.line.b == b.line.b && a.away == b.away;
  }
};
std::vector<OwnDoor> ownDoors(const RgMapState& state, const Region& region);

// The region's own doors moved cut.depthM to their other side and lengthened by cut.widenM at both
// ends, in the region's frame (ours). The robot that stands in a door frame, just in front of the
// door's line, before the traversal, sees past that line into the next room, through the door and
// at a slant; these lines stop its beams soon after the door.
std::vector<GatewaySegment> doorFrameLines(std::span<const OwnDoor> doors, const DoorFrameCut& cut);

// For a scan taken at `sensor` (region frame) in front of one of the region's own `doors` (on the
// region's side, at most cut.frontM from its line, at most cut.besideM beside its ends): that
// door's line lengthened by cut.wallM at each end (ours). From just in front of a door the robot
// sees the next room through it in a wide fan, and the door's line, placed from the jambs the
// detector saw, is often shorter than the opening or a little off it: the fan's slanting beams
// passed beside its ends and the region claimed a strip of the hallway (office_c: a room's region
// with 59 % of its pixels in the hallway). A door stands in a wall, so what lies beyond the wall's
// line is not the region's either.
std::vector<GatewaySegment> doorWallLines(std::span<const OwnDoor> doors, const Eigen::Vector2d& sensor,
                                          const DoorWallCut& cut);

// Whether `sensor` (region frame) lies beyond one of the region's own `doors`: past its line by at
// most limits.depthM, beside its ends by at most limits.besideM (ours). A scan taken there looks into
// the next room: the robot has passed the door, but the traversal has not reached the kernel yet,
// or it turned back in the doorway. Its beams stay out of the region's freespace evidence (office_c:
// the robot in the doorway claimed half the next room for the room it came from).
bool pastOwnDoor(std::span<const OwnDoor> doors, const Eigen::Vector2d& sensor, const PastOwnDoor& limits);

class RegionModels {
 public:
  // Throws ConfigError for a negative door frame depth or widening, a negative PastOwnDoor or
  // DoorWallCut distance, a bad DoorSideProbe (and as RegionEvidence and RegionLineMap do for theirs).
  explicit RegionModels(const RegionModelConfig& config = {});

  // The line map / description of region `id` of `state`. Throws NotAvailableError for an unknown
  // region, InvalidArgumentError if the region's scans do not fit into a description (a region
  // wider than the freespace grid's maximum extent). References stay valid until the next call.
  const RegionLineMap& lineMap(const RgMapState& state, RegionId id);
  const RegionDescription& description(const RgMapState& state, RegionId id);

  // Drops the models of regions that are no longer in `state`.
  void prune(const RgMapState& state);

 private:
  struct ScanKey {
    DataId id = 0;
    Pose2D corrected;
    friend bool operator==(const ScanKey&, const ScanKey&) = default;
  };
  struct Model {
    Pose2D frame;
    std::vector<GatewaySegment> gateways;  // its own gateway lines
    std::vector<GatewaySegment> cutting;   // `gateways`, otherDoorLines, otherAreaLines, doorFrameLines:
                                           // what cuts its beams
    std::vector<OwnDoor> doors;            // its own doors: scans past them leave out its evidence,
                                           // scans in front of them are also cut at doorWallLines
    std::vector<ScanKey> scans;  // the scans in `lines` and `evidence`, in order
    RegionLineMap lines;
    RegionEvidence evidence;
    std::optional<RegionDescription> description;  // of all of the above
  };

  Model& upToDate(const RgMapState& state, RegionId id);

  RegionModelConfig config_;
  std::map<RegionId, Model> models_;
};

}  // namespace rgnav
