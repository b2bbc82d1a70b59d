// Tests the RG Mapping Kernel's online structuring (thesis 2.2, 5.2) on a synthetic floor, a
// hallway with two rooms behind doors: three regions and two gateways with references both ways,
// gateways placed from the drifting odometry frame into the map frame, scans in the region they
// were taken in, a turn joining regions once two sequences support it and merging them again when
// it turns out to be a hallway, a revisited room updated and not duplicated, region descriptions,
// naming, merging on request, a path through the RG Graph, revised SLAM poses, bad inputs
// refused; a hallway area's sides attached by traversals only, and an area with floor around it
// joining no regions; beams cut at every door with a region on a side or between two regions, and just
// beyond the region's own doors, no robot side beside a door's ends.
#include "core/rgmap/kernel/RgMappingKernel.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"
#include "core/rgmap/graph/RgPathSearch.h"
#include "core/rgmap/kernel/DoorSeparation.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "core/rgmap/kernel/RgMapEdits.h"
#include "core/rgmap/kernel/RgMapViews.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;
using rgnav::testing::feedChecked;
using rgnav::testing::twoRoomTour;

namespace {

constexpr RegionId kHallway{1}, kRoom1{2}, kRoom2{3};
constexpr GatewayId kDoor1{1}, kDoor2{2};

RgMappingKernel mappedFloor() {
  const std::vector<rgnav::testing::KernelInput> inputs = twoRoomTour().inputs();
  return rgnav::testing::mapped(inputs, inputs.size());
}

std::string joinedViolations(const RgMappingKernel& k) {
  std::string out;
  for (const std::string& v : k.checkConsistency()) out += v + "\n";
  return out;
}

std::size_t countEvents(const RgMappingKernel& k, RgMapEventKind kind, RegionId region = RegionId{}) {
  return static_cast<std::size_t>(
      std::count_if(k.state().events.begin(), k.state().events.end(),
                    [&](const RgMapEvent& e) { return e.kind == kind && (region.isNone() || e.region == region); }));
}

// A hallway-area gateway at the south-east corner of ringCorridor() (the square x in [8, 10],
// y in [0, 2]; or the same square moved to have its south-west corner at `southWest`) as the
// detector reports it to a robot coming from the west: corners hidden-left, front-left,
// front-right, hidden-right; crossing points hidden, left, front, right; all in the tours'
// odometry frame, supported by `sequences` observation sequences.
GatewayEvent cornerEvent(GatewayEventId id, GatewayEventKind kind, const StoredScan& at, std::size_t from = 0,
                         std::size_t to = 1, std::size_t sequences = 2,
                         const Eigen::Vector2d& southWest = Eigen::Vector2d(8, 0)) {
  const auto odom = [&](double x, double y) {
    return transformPoint(rgnav::testing::kTourDrift, Eigen::Vector2d(x, y) + southWest - Eigen::Vector2d(8, 0));
  };
  GatewayEvent e;
  e.id = id;
  e.kind = kind;
  GatewayRecord& r = e.gateway;
  r.id = DetectorGatewayId{7};
  r.kind = GatewayKind::HallwayArea;
  r.classes = {{"L-Turn", 0.8}, {"T-Junction", 0.2}};
  r.gatewayPoints = {odom(8, 2), odom(10, 2), odom(10, 0), odom(8, 0)};
  r.crossingPoints = {odom(7.5, 1), odom(9, 2.5), odom(10.5, 1), odom(9, -0.5)};
  r.widthM = 2.0;
  r.support = sequences;
  r.firstScan = r.lastScan = at.scan.id;
  r.lastPose = at.scan.odometry;
  e.traversal = {at.scan.id, from, to, transformPoint(rgnav::testing::kTourDrift, {at.corrected.x, at.corrected.y}),
                 Eigen::Vector2d::UnitY()};
  return e;
}

// Feeds `inputs` (scans only) into `k`: after the first scan for which `detectWhen` holds,
// `detect` runs, after the first for which `traverseWhen` holds (not before detect), `traverse`;
// `afterEach` after every input. Whether `traverse` ran.
using ScanTest = std::function<bool(const StoredScan&)>;
using ScanAction = std::function<void(const StoredScan&)>;
bool feedWithArea(RgMappingKernel& k, const std::vector<rgnav::testing::KernelInput>& inputs, const ScanTest& detectWhen,
                  const ScanAction& detect, const ScanTest& traverseWhen, const ScanAction& traverse,
                  const std::function<void()>& afterEach = [] {}) {
  bool detected = false, traversed = false;
  for (const rgnav::testing::KernelInput& in : inputs) {
    rgnav::testing::feed(k, in);
    const StoredScan& at = *in.scan;
    if (!detected && detectWhen(at)) {
      detect(at);
      detected = true;
    }
    if (detected && !traversed && traverseWhen(at)) {
      traverse(at);
      traversed = true;
    }
    afterEach();
  }
  return traversed;
}

}  // namespace

class RgMappingKernelTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMappingKernelTest);
  CPPUNIT_TEST(floorHasThreeRegionsAndTwoGateways);
  CPPUNIT_TEST(gatewaysArePlacedInTheMapFrame);
  CPPUNIT_TEST(scansLieInTheRegionTheyWereTakenIn);
  CPPUNIT_TEST(revisitedRoomIsUpdatedNotDuplicated);
  CPPUNIT_TEST(descriptionsStayInsideTheirRooms);
  CPPUNIT_TEST(beamsAreCutAtEveryDoor);
  CPPUNIT_TEST(beamsAreCutAtOtherRegionsAreas);
  CPPUNIT_TEST(beamsAreCutJustBeyondOwnDoors);
  CPPUNIT_TEST(scansPastOwnDoorsLeaveTheEvidence);
  CPPUNIT_TEST(noSideBesideAPassagesEnds);
  CPPUNIT_TEST(preliminaryDescriptionGrowsWithTheScans);
  CPPUNIT_TEST(hallwayTurnJoinsTwoRegions);
  CPPUNIT_TEST(hallwayAreaSidesComeFromTraversalsOnly);
  CPPUNIT_TEST(areaWithFloorAroundItJoinsNoRegions);
  CPPUNIT_TEST(regionsAreNamedAndFoundByName);
  CPPUNIT_TEST(objectsAreNamedAndFoundByName);
  CPPUNIT_TEST(regionsAreMergedOnRequest);
  CPPUNIT_TEST(regionsJoinedByAGatewayMergeWithoutForce);
  CPPUNIT_TEST(pathLeadsThroughBothDoors);
  CPPUNIT_TEST(learnedCostsAreKept);
  CPPUNIT_TEST(revisedPosesMoveTheDescription);
  CPPUNIT_TEST(badInputsAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void floorHasThreeRegionsAndTwoGateways() {
    const RgMappingKernel k = mappedFloor();
    const RgMapState& s = k.state();
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), s.regions.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.gateways.size());
    CPPUNIT_ASSERT((s.regions.at(kHallway).gateways == std::set<GatewayId>{kDoor1, kDoor2}));
    CPPUNIT_ASSERT((s.regions.at(kRoom1).gateways == std::set<GatewayId>{kDoor1}));
    CPPUNIT_ASSERT((s.regions.at(kRoom2).gateways == std::set<GatewayId>{kDoor2}));
    // Side A is the side each door was first seen from: the hallway.
    const Gateway& d1 = s.gateways.at(kDoor1);
    const Gateway& d2 = s.gateways.at(kDoor2);
    CPPUNIT_ASSERT_EQUAL(kHallway, d1.sides[kSideA].region);
    CPPUNIT_ASSERT_EQUAL(kRoom1, d1.sides[kSideB].region);
    CPPUNIT_ASSERT_EQUAL(kHallway, d2.sides[kSideA].region);
    CPPUNIT_ASSERT_EQUAL(kRoom2, d2.sides[kSideB].region);
    CPPUNIT_ASSERT_EQUAL(DetectorGatewayId{11}, d1.record.id);
    CPPUNIT_ASSERT(d1.door() && !d1.neutralised && !d2.neutralised);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), d1.traversalsFrom[kSideA]);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), d1.traversalsFrom[kSideB]);
    CPPUNIT_ASSERT_EQUAL(kHallway, k.currentRegionId());
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), countEvents(k, RgMapEventKind::RegionCreated));
    for (std::size_t i = 0; i < s.events.size(); ++i) CPPUNIT_ASSERT_EQUAL(RgMapEventId(i + 1), s.events[i].id);
  }

  void gatewaysArePlacedInTheMapFrame() {
    const RgMappingKernel k = mappedFloor();
    const PlacedGateway d1 = placeGateway(k.state().gateways.at(kDoor1));
    CPPUNIT_ASSERT((d1.gatewayPoints[0] - Eigen::Vector2d(3.55, 2)).norm() < 1e-9);
    CPPUNIT_ASSERT((d1.gatewayPoints[1] - Eigen::Vector2d(4.45, 2)).norm() < 1e-9);
    CPPUNIT_ASSERT((d1.crossingPoints[0] - Eigen::Vector2d(4, 1.5)).norm() < 1e-9);  // the hallway side
    CPPUNIT_ASSERT((traversalDirection(k.state().gateways.at(kDoor1)) - Eigen::Vector2d(0, 1)).norm() < 1e-9);
    // In room 1's own frame, mapped back with the frame, it is the same door.
    const Pose2D frame = k.state().regions.at(kRoom1).frame;
    const PlacedGateway inRoom = k.gatewayInRegion(kDoor1, kRoom1);
    CPPUNIT_ASSERT((transformPoint(frame, inRoom.gatewayPoints[1]) - Eigen::Vector2d(4.45, 2)).norm() < 1e-9);
  }

  void scansLieInTheRegionTheyWereTakenIn() {
    const RgMappingKernel k = mappedFloor();
    const RgMapState& s = k.state();
    for (const auto& [id, region] : s.regions)
      for (DataId scan : region.scans) {
        const Pose2D& p = s.scans.at(scan).corrected;
        const RegionId truth = p.y < 2.0 ? kHallway : p.x < 6.5 ? kRoom1 : kRoom2;
        CPPUNIT_ASSERT_EQUAL_MESSAGE("scan " + std::to_string(scan), truth, id);
      }
  }

  void revisitedRoomIsUpdatedNotDuplicated() {
    const RgMappingKernel k = mappedFloor();
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), countEvents(k, RgMapEventKind::RegionEntered, kRoom1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), countEvents(k, RgMapEventKind::RegionFinalised, kRoom1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), countEvents(k, RgMapEventKind::RegionUpdated, kRoom1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), countEvents(k, RgMapEventKind::RegionFinalised, kRoom2));
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), countEvents(k, RgMapEventKind::RegionUpdated, kRoom2));
    // Both visits' scans are in room 1: the first visit's last scan and the second visit's first.
    const std::vector<DataId>& scans = k.state().regions.at(kRoom1).scans;
    const auto gap = std::adjacent_find(scans.begin(), scans.end(), [](DataId a, DataId b) { return b != a + 1; });
    CPPUNIT_ASSERT(gap != scans.end());
    CPPUNIT_ASSERT_EQUAL(scans.size(), k.description(kRoom1).scanCount);
  }

  void descriptionsStayInsideTheirRooms() {
    const RgMappingKernel k = mappedFloor();
    const struct {
      RegionId region;
      Eigen::AlignedBox2d room;
    } cases[] = {{kRoom1, {Eigen::Vector2d(2, 2), Eigen::Vector2d(6, 6)}},
                 {kRoom2, {Eigen::Vector2d(7, 2), Eigen::Vector2d(11, 6)}},
                 {kHallway, {Eigen::Vector2d(0, 0), Eigen::Vector2d(12, 2)}}};
    for (const auto& c : cases) {
      const RegionDescription& d = k.description(c.region);
      CPPUNIT_ASSERT(!d.boundingBox.isEmpty());
      CPPUNIT_ASSERT(d.freespaceBytes() > 0);
      CPPUNIT_ASSERT(k.lineMap(c.region).lineCount() >= 3);
      const Pose2D frame = k.state().regions.at(c.region).frame;
      const Eigen::AlignedBox2d room(c.room.min().array() - 0.1, c.room.max().array() + 0.1);
      for (auto corner : {Eigen::AlignedBox2d::BottomLeft, Eigen::AlignedBox2d::BottomRight,
                          Eigen::AlignedBox2d::TopLeft, Eigen::AlignedBox2d::TopRight}) {
        const Eigen::Vector2d p = transformPoint(frame, d.boundingBox.corner(corner));
        CPPUNIT_ASSERT_MESSAGE("region " + std::to_string(c.region.value()), room.contains(p));
      }
    }
  }

  void preliminaryDescriptionGrowsWithTheScans() {
    RgMappingKernel k;
    const std::vector<rgnav::testing::KernelInput> inputs = twoRoomTour().inputs();
    CPPUNIT_ASSERT_THROW(k.currentRegion(), NotAvailableError);
    CPPUNIT_ASSERT_EQUAL(std::string(), feedChecked(k, inputs, 0, 5));
    const std::size_t early = k.currentRegion().description.scanCount;
    CPPUNIT_ASSERT_EQUAL(std::string(), feedChecked(k, inputs, 5, 10));
    const CurrentRegion now = k.currentRegion();
    CPPUNIT_ASSERT_EQUAL(kHallway, now.region.id);
    CPPUNIT_ASSERT(now.description.scanCount > early);
    CPPUNIT_ASSERT_EQUAL(now.region.scans.size(), now.lines.scanCount());
  }

  void hallwayTurnJoinsTwoRegions() {
    rgnav::testing::SyntheticTour tour(rgnav::testing::ringCorridor(), rgnav::testing::kTourDrift);
    tour.setReports(DetectorGatewayId{21}, rgnav::testing::DoorReports::None);
    tour.driveThrough({{6.1, 1}, {9, 1}, {9, 5}});
    RgMappingKernel k;
    feedWithArea(
        k, tour.inputs(), [](const StoredScan& at) { return at.corrected.x >= 6.5; },
        [&](const StoredScan& at) { k.addGatewayEvent(cornerEvent(1, GatewayEventKind::Detected, at), at.corrected); },
        [](const StoredScan& at) { return at.corrected.y > 2.0; },
        [&](const StoredScan& at) {
          // Seen in one sequence only, the turn joins no regions yet; in two, it does.
          k.addGatewayEvent(cornerEvent(2, GatewayEventKind::Traversed, at, 0, 1, 1), at.corrected);
          CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().regions.size());
          k.addGatewayEvent(cornerEvent(3, GatewayEventKind::Traversed, at), at.corrected);
        },
        [&] { CPPUNIT_ASSERT_EQUAL(std::string(), joinedViolations(k)); });
    const RgMapState& s = k.state();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.regions.size());
    const Gateway& corner = s.gateways.at(GatewayId{1});
    CPPUNIT_ASSERT(!corner.door());
    CPPUNIT_ASSERT(corner.sides[kSideA].region == RegionId{1} && corner.sides[kSideA].crossing == 0);
    CPPUNIT_ASSERT(corner.sides[kSideB].region == RegionId{2} && corner.sides[kSideB].crossing == 1);
    // Each region is bounded by the side of the square it lies beyond.
    const std::vector<GatewaySegment> west = regionGatewaySegments(s, s.regions.at(RegionId{1}));
    const std::vector<GatewaySegment> north = regionGatewaySegments(s, s.regions.at(RegionId{2}));
    CPPUNIT_ASSERT(west.size() == 1 && north.size() == 1);
    const Pose2D& frame2 = s.regions.at(RegionId{2}).frame;
    CPPUNIT_ASSERT((transformPoint(s.regions.at(RegionId{1}).frame, west[0].a) - Eigen::Vector2d(8, 0)).norm() < 1e-9);
    CPPUNIT_ASSERT((transformPoint(frame2, north[0].a) - Eigen::Vector2d(8, 2)).norm() < 1e-9);
    CPPUNIT_ASSERT((transformPoint(frame2, north[0].b) - Eigen::Vector2d(10, 2)).norm() < 1e-9);
    const RgGraph graph = k.graph();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), graph.nodes().size());
    CPPUNIT_ASSERT((graph.nodes()[1].position - Eigen::Vector2d(9, 2.5)).norm() < 1e-9);
    // Through two further sides of the square: recorded, but no structure changes.
    const StoredScan& last = *tour.inputs().back().scan;
    k.addGatewayEvent(cornerEvent(4, GatewayEventKind::Traversed, last, 2, 3), last.corrected);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), k.state().regions.size());
    CPPUNIT_ASSERT_EQUAL(RegionId(2), k.currentRegionId());
    CPPUNIT_ASSERT_EQUAL(RgMapEventKind::GatewayTraversed, k.state().events.back().kind);
    // More views say it is no turn: the hallway goes on, the two regions are one.
    GatewayEvent hallway = cornerEvent(5, GatewayEventKind::Updated, last);
    hallway.gateway.classes = {{"Hallway", 0.9}, {"L-Turn", 0.1}};
    k.addGatewayEvent(hallway, last.corrected);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().regions.size());
    CPPUNIT_ASSERT_EQUAL(RegionId(1), k.currentRegionId());
    CPPUNIT_ASSERT(k.state().gateways.at(GatewayId{1}).neutralised);
    CPPUNIT_ASSERT_EQUAL(std::string(), joinedViolations(k));
  }

  // Seen from right beside its west crossing point, the turn gets no region on that side: only
  // its traversal attaches regions to a hallway area.
  void hallwayAreaSidesComeFromTraversalsOnly() {
    rgnav::testing::SyntheticTour tour(rgnav::testing::ringCorridor(), rgnav::testing::kTourDrift);
    tour.setReports(DetectorGatewayId{21}, rgnav::testing::DoorReports::None);
    tour.driveThrough({{6.1, 1}, {7.3, 1}});
    RgMappingKernel k;
    for (const rgnav::testing::KernelInput& in : tour.inputs()) rgnav::testing::feed(k, in);
    const StoredScan& at = *tour.inputs().back().scan;
    k.addGatewayEvent(cornerEvent(1, GatewayEventKind::Detected, at), at.corrected);
    k.addGatewayEvent(cornerEvent(2, GatewayEventKind::Updated, at), at.corrected);
    const Gateway& corner = k.state().gateways.at(GatewayId{1});
    CPPUNIT_ASSERT_EQUAL(RegionId(0), corner.sides[kSideA].region);
    CPPUNIT_ASSERT_EQUAL(RegionId(0), corner.sides[kSideB].region);
    CPPUNIT_ASSERT(k.state().regions.at(RegionId{1}).gateways.empty());
  }

  // A "turn" in the middle of an open room (the square x, y in [4, 6] of a 10 x 10 m room): the
  // robot comes from the west and leaves it to the north, but there is floor all around it, so
  // its two sides are one region and it is neutralised; the ring corridor's corner, between
  // walls, separates.
  void areaWithFloorAroundItJoinsNoRegions() {
    rgnav::testing::TourWorld room;
    room.walls = rgnav::testing::boxWalls({5, 5}, 0.0, 10, 10);
    rgnav::testing::SyntheticTour tour(room, rgnav::testing::kTourDrift);
    tour.driveThrough({{1, 5}, {5, 5}, {5, 8}, {2, 8}, {2, 2}, {8, 2}, {8, 8}, {5, 8}});
    RgMappingKernel k;
    const auto report = [&](GatewayEventId id, GatewayEventKind kind) {
      return [&k, id, kind](const StoredScan& at) {
        k.addGatewayEvent(cornerEvent(id, kind, at, 0, 1, 2, {4, 4}), at.corrected);
      };
    };
    CPPUNIT_ASSERT(feedWithArea(
        k, tour.inputs(), [](const StoredScan& at) { return at.corrected.x >= 2.0; },
        report(1, GatewayEventKind::Detected), [](const StoredScan& at) { return at.corrected.y > 6.5; },
        report(2, GatewayEventKind::Traversed)));
    CPPUNIT_ASSERT(!areaSeparatesSides(k.state(), GatewayId{1}, 0, 1, {}));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().regions.size());
    CPPUNIT_ASSERT(k.state().gateways.at(GatewayId{1}).neutralised);
    CPPUNIT_ASSERT_EQUAL(std::string(), joinedViolations(k));

    rgnav::testing::SyntheticTour ring(rgnav::testing::ringCorridor(), rgnav::testing::kTourDrift);
    ring.setReports(DetectorGatewayId{21}, rgnav::testing::DoorReports::None);
    ring.driveThrough({{6.1, 1}, {9, 1}, {9, 5}});
    RgMappingKernel corner;
    for (const rgnav::testing::KernelInput& in : ring.inputs()) rgnav::testing::feed(corner, in);
    const StoredScan& last = *ring.inputs().back().scan;
    corner.addGatewayEvent(cornerEvent(1, GatewayEventKind::Detected, last), last.corrected);
    corner.addGatewayEvent(cornerEvent(2, GatewayEventKind::Traversed, last), last.corrected);
    CPPUNIT_ASSERT(areaSeparatesSides(corner.state(), GatewayId{1}, 0, 1, {}));
  }

  void beamsAreCutAtEveryDoor() {
    const RgMappingKernel k = mappedFloor();
    const RgMapState& s = k.state();
    // Room 1: room 2's door, in room 1's frame.
    const Region& room1 = s.regions.at(kRoom1);
    const std::vector<GatewaySegment> others = otherDoorLines(s, room1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), others.size());
    const PlacedGateway door2 = placeGateway(s.gateways.at(kDoor2), room1.frame);
    CPPUNIT_ASSERT(others[0].a == door2.gatewayPoints[0] && others[0].b == door2.gatewayPoints[1]);
    // The hallway has both doors as its own gateway lines: nothing more.
    CPPUNIT_ASSERT(otherDoorLines(s, s.regions.at(kHallway)).empty());
    // A door no region was attached to cuts only between two regions: the hallway's robot stood
    // south of door 2 only and room 2 saw it from the north (and the other way round). Room 1's
    // robot never stood in front of it.
    RgMapState unattached = s;
    unattached.gateways.at(kDoor2).sides[kSideA].region = RegionId{};
    unattached.gateways.at(kDoor2).sides[kSideB].region = RegionId{};
    CPPUNIT_ASSERT(otherDoorLines(unattached, room1).empty());
    const Region& hallway = unattached.regions.at(kHallway);
    const std::vector<GatewaySegment> cutHallway = otherDoorLines(unattached, hallway);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), cutHallway.size());
    const PlacedGateway door2InHallway = placeGateway(s.gateways.at(kDoor2), hallway.frame);
    CPPUNIT_ASSERT(cutHallway[0].a == door2InHallway.gatewayPoints[0] && cutHallway[0].b == door2InHallway.gatewayPoints[1]);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), otherDoorLines(unattached, unattached.regions.at(kRoom2)).size());  // and door 1
    // Nobody saw it from the north: it cuts nothing.
    RgMapState unseen = unattached;
    unseen.regions.at(kRoom2).scans.clear();
    CPPUNIT_ASSERT(otherDoorLines(unseen, unseen.regions.at(kHallway)).empty());
    // The hallway's robot stood on both sides of it: the door is inside the hallway's region.
    RgMapState bothSides = unattached;
    std::vector<DataId>& hallwayScans = bothSides.regions.at(kHallway).scans;
    const std::vector<DataId>& room2Scans = bothSides.regions.at(kRoom2).scans;
    hallwayScans.insert(hallwayScans.end(), room2Scans.begin(), room2Scans.end());
    CPPUNIT_ASSERT(otherDoorLines(bothSides, bothSides.regions.at(kHallway)).empty());
  }

  void beamsAreCutAtOtherRegionsAreas() {
    const RgMappingKernel k = mappedFloor();
    RgMapState s = k.state();
    // A junction square between the hallway and room 2 (as if the robot had crossed it).
    Gateway area;
    area.id = GatewayId{99};
    area.record.id = DetectorGatewayId{99};
    area.record.kind = GatewayKind::HallwayArea;
    area.record.classes = {{"T-Junction", 1.0}};
    area.record.gatewayPoints = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    area.record.crossingPoints = {{2, 0.5}, {0.5, 2}, {2, 3.5}, {3.5, 2}};
    area.sides[kSideA] = {kHallway, 0, 0};
    area.sides[kSideB] = {kRoom2, 2, 0};
    s.gateways.emplace(area.id, area);
    s.regions.at(kHallway).gateways.insert(area.id);
    s.regions.at(kRoom2).gateways.insert(area.id);
    const Region& room1 = s.regions.at(kRoom1);
    const std::vector<GatewaySegment> sides = otherAreaLines(s, room1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), sides.size());
    const PlacedGateway square = placeGateway(s.gateways.at(area.id), room1.frame);
    for (std::size_t k = 0; k < 4; ++k)
      CPPUNIT_ASSERT(sides[k].a == square.gatewayPoints[k] && sides[k].b == square.gatewayPoints[(k + 1) % 4]);
    // Its own regions and doors: nothing; a neutralised area or one with a side unknown: nothing.
    CPPUNIT_ASSERT(otherAreaLines(s, s.regions.at(kHallway)).empty());
    CPPUNIT_ASSERT(otherAreaLines(s, s.regions.at(kRoom2)).empty());
    RgMapState neutralised = s;
    neutralised.gateways.at(area.id).neutralised = true;
    CPPUNIT_ASSERT(otherAreaLines(neutralised, room1).empty());
    RgMapState oneSide = s;
    oneSide.gateways.at(area.id).sides[kSideB] = {RegionId{}, 2, 0};
    CPPUNIT_ASSERT(otherAreaLines(oneSide, room1).empty());
  }

  void beamsAreCutJustBeyondOwnDoors() {
    const RgMappingKernel k = mappedFloor();
    const RgMapState& s = k.state();
    const Region& room1 = s.regions.at(kRoom1);
    // Door 1, (3.55, 2)-(4.45, 2) in the map frame, moved 0.3 m into the hallway and 1 m longer
    // at each end.
    const std::vector<GatewaySegment> lines = doorFrameLines(ownDoors(s, room1), DoorFrameCut{0.3, 1.0});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), lines.size());
    const Eigen::Vector2d a = transformPoint(room1.frame, lines[0].a), b = transformPoint(room1.frame, lines[0].b);
    const Eigen::Vector2d west = a.x() < b.x() ? a : b, east = a.x() < b.x() ? b : a;
    CPPUNIT_ASSERT((west - Eigen::Vector2d(2.55, 1.7)).norm() < 0.05);
    CPPUNIT_ASSERT((east - Eigen::Vector2d(5.45, 1.7)).norm() < 0.05);
    // The hallway's lines lie in the rooms; a room seen through its door from the hallway ends there.
    for (const GatewaySegment& line : doorFrameLines(ownDoors(s, s.regions.at(kHallway)), DoorFrameCut{0.3, 1.0}))
      CPPUNIT_ASSERT_DOUBLES_EQUAL(2.3, transformPoint(s.regions.at(kHallway).frame, line.a).y(), 0.05);
    // A neutralised door cuts nothing.
    RgMapState merged = s;
    mergeRegions(merged, kHallway, kRoom1, s.lastScanId);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), doorFrameLines(ownDoors(merged, merged.regions.at(kHallway)), DoorFrameCut{}).size());
  }

  void scansPastOwnDoorsLeaveTheEvidence() {
    const RgMappingKernel k = mappedFloor();
    const RgMapState& s = k.state();
    const Region& room1 = s.regions.at(kRoom1);
    const std::vector<OwnDoor> doors = ownDoors(s, room1);  // door 1, (3.55, 2)-(4.45, 2), the hallway below
    const auto past = [&](double x, double y) {
      const Pose2D inRoom = between(room1.frame, Pose2D{x, y, 0.0});
      return pastOwnDoor(doors, {inRoom.x, inRoom.y}, PastOwnDoor{1.0, 0.5});
    };
    CPPUNIT_ASSERT(past(4.0, 1.5));
    CPPUNIT_ASSERT(past(4.9, 1.1));
    CPPUNIT_ASSERT(!past(4.0, 2.5));  // in the room
    CPPUNIT_ASSERT(!past(4.0, 0.8));  // deeper in the hallway
    CPPUNIT_ASSERT(!past(5.3, 1.5));  // beside the door
    // In front of the door, in the room, its beams are also cut at the door's wall: the door's
    // line lengthened 3 m at both ends.
    const auto walls = [&](double x, double y) {
      const Pose2D inRoom = between(room1.frame, Pose2D{x, y, 0.0});
      return doorWallLines(doors, {inRoom.x, inRoom.y}, DoorWallCut{1.2, 0.5, 3.0});
    };
    const std::vector<GatewaySegment> wall = walls(4.0, 2.8);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), wall.size());
    const double wallLength = (wall[0].b - wall[0].a).norm();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.9 + 6.0, wallLength, 0.1);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, doors[0].away.dot(wall[0].a - doors[0].line.a), 1e-9);  // on the door's line
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), walls(4.9, 2.1).size());
    CPPUNIT_ASSERT(walls(4.0, 3.5).empty());  // farther into the room
    CPPUNIT_ASSERT(walls(4.0, 1.5).empty());  // past the door
    CPPUNIT_ASSERT(walls(5.3, 2.5).empty());  // beside the door
    // A hallway scan in the doorway that reached room 1 (a traversal reported late) adds nothing
    // to room 1's description: no scan, no freespace.
    const std::vector<DataId>& hallwayScans = s.regions.at(kHallway).scans;
    const auto doorway = std::find_if(hallwayScans.begin(), hallwayScans.end(), [&](DataId id) {
      const Pose2D& p = s.scans.at(id).corrected;
      return past(p.x, p.y);
    });
    CPPUNIT_ASSERT(doorway != hallwayScans.end());
    RgMapState late = s;
    std::vector<DataId>& lateScans = late.regions.at(kRoom1).scans;
    lateScans.insert(std::upper_bound(lateScans.begin(), lateScans.end(), *doorway), *doorway);
    RegionModels models;
    const RegionDescription& before = models.description(s, kRoom1);
    const std::size_t scanCount = before.scanCount;
    const std::size_t freeBytes = before.freespaceBytes();
    const RegionDescription& after = models.description(late, kRoom1);
    CPPUNIT_ASSERT_EQUAL(scanCount, after.scanCount);
    CPPUNIT_ASSERT_EQUAL(freeBytes, after.freespaceBytes());
    // Counted as a room scan, it would have added itself and the hallway it saw.
    RegionModelConfig counted;
    counted.pastOwnDoors.depthM = 0.0;
    RegionModels countingModels(counted);
    const RegionDescription& seen = countingModels.description(late, kRoom1);
    CPPUNIT_ASSERT_EQUAL(scanCount + 1, seen.scanCount);
    CPPUNIT_ASSERT(seen.freespaceBytes() > freeBytes);
  }

  void noSideBesideAPassagesEnds() {
    const RgMappingKernel k = mappedFloor();
    const Gateway& door1 = k.state().gateways.at(kDoor1);  // (3.55, 2)-(4.45, 2), the hallway below
    SideEvidenceConfig config;  // marginM 0.3, besideM 0.5
    config.rangeM = 2.5;        // all four positions are within it of a crossing point
    const std::optional<std::size_t> room(1);
    CPPUNIT_ASSERT(robotCrossing(door1, {4.0, 3.0}, config) == room);
    CPPUNIT_ASSERT(robotCrossing(door1, {4.9, 3.0}, config) == room);  // 0.45 m beside its end
    CPPUNIT_ASSERT(!robotCrossing(door1, {5.2, 3.0}, config));         // 0.75 m beside: the next room
    CPPUNIT_ASSERT(!robotCrossing(door1, {2.8, 2.8}, config));
  }

  void regionsAreNamedAndFoundByName() {
    RgMappingKernel k = mappedFloor();
    k.nameRegion(kRoom1, "office");
    k.nameRegion(kRoom2, "lab");
    CPPUNIT_ASSERT_EQUAL(kRoom1, *k.regionByName("office"));
    CPPUNIT_ASSERT_EQUAL(kRoom2, *k.regionByName("lab"));
    CPPUNIT_ASSERT(!k.regionByName("kitchen"));
    CPPUNIT_ASSERT_THROW(k.nameRegion(kHallway, "office"), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(k.nameRegion(RegionId{99}, "nowhere"), InvalidArgumentError);
    k.nameRegion(kRoom1, "office");  // again: no conflict with itself
    k.nameRegion(kRoom2, "");
    CPPUNIT_ASSERT(!k.regionByName("lab"));
    CPPUNIT_ASSERT_EQUAL(RgMapEventKind::RegionNamed, k.state().events.back().kind);
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  void objectsAreNamedAndFoundByName() {
    const Eigen::Vector2d truth = rgnav::testing::cabinetCentre();
    const std::vector<rgnav::testing::KernelInput> inputs =
        twoRoomTour(rgnav::testing::hallwayWithTwoRoomsAndCabinet()).inputs();
    RgMappingKernel k = rgnav::testing::mapped(inputs, inputs.size());
    const RegionView room = regionView(k, kRoom1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), room.objects.size());
    const Pose2D cabinet = between(room.summary.frame, {truth.x(), truth.y(), 0.0});  // the true centre, region frame
    CPPUNIT_ASSERT_DOUBLES_EQUAL(cabinet.x, room.objects[0].pose.x, 0.1);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(cabinet.y, room.objects[0].pose.y, 0.1);
    CPPUNIT_ASSERT(regionView(k, kHallway).objects.empty());

    k.nameObject(kRoom1, {cabinet.x + 0.2, cabinet.y}, "files");
    CPPUNIT_ASSERT_EQUAL(RgMapEventKind::ObjectNamed, k.state().events.back().kind);
    CPPUNIT_ASSERT_EQUAL(std::string("files"), regionView(k, kRoom1).objects[0].name);
    const auto found = k.objectByName("files");
    CPPUNIT_ASSERT(found && found->region == kRoom1);
    CPPUNIT_ASSERT((found->namedAt - truth).norm() < 0.1);  // map frame = true frame here
    CPPUNIT_ASSERT(!k.objectByName("desk"));
    CPPUNIT_ASSERT_THROW(k.nameObject(kRoom1, {cabinet.x + 2.0, cabinet.y}, "desk"), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(k.nameObject(RegionId{99}, {0.0, 0.0}, "desk"), InvalidArgumentError);
    for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()})
      CPPUNIT_ASSERT_THROW(k.nameObject(kRoom1, {bad, cabinet.y}, "desk"), InvalidArgumentError);
    CPPUNIT_ASSERT(!k.objectByName("desk"));
    k.nameObject(kRoom1, {cabinet.x, cabinet.y}, "cabinet");  // renames it
    CPPUNIT_ASSERT(!k.objectByName("files"));
    CPPUNIT_ASSERT_EQUAL(std::string("cabinet"), regionView(k, kRoom1).objects[0].name);
    CPPUNIT_ASSERT(k.checkConsistency().empty());

    // The name survives a merge of its region and a checkpoint round trip.
    k.mergeRegions(kHallway, kRoom1, false);
    CPPUNIT_ASSERT_EQUAL(kHallway, k.objectByName("cabinet")->region);
    const RgMappingKernel resumed({}, deserializeRgMap(serializeRgMap(k.state()), scanJournalLines(k.state())));
    CPPUNIT_ASSERT(resumed.objectByName("cabinet"));
    const Pose2D inMerged = between(k.state().regions.at(kHallway).frame, {truth.x(), truth.y(), 0.0});
    k.nameObject(kHallway, {inMerged.x, inMerged.y}, "");
    CPPUNIT_ASSERT(!k.objectByName("cabinet"));
  }

  // The two rooms lie on opposite sides of the hallway: no gateway joins them, so a merge asked
  // without force is refused and changes nothing; forced, it merges them.
  void regionsAreMergedOnRequest() {
    RgMappingKernel k = mappedFloor();
    k.nameRegion(kRoom2, "lab");
    const std::size_t scans = k.state().regions.at(kRoom1).scans.size() + k.state().regions.at(kRoom2).scans.size();
    const std::size_t events = k.state().events.size();
    CPPUNIT_ASSERT_THROW_MESSAGE("no shared gateway", k.mergeRegions(kRoom2, kRoom1, false), InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), k.state().regions.size());
    CPPUNIT_ASSERT_EQUAL(events, k.state().events.size());
    CPPUNIT_ASSERT_EQUAL(kRoom1, k.mergeRegions(kRoom2, kRoom1, true));
    const RgMapState& s = k.state();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.regions.size());
    CPPUNIT_ASSERT_EQUAL(scans, s.regions.at(kRoom1).scans.size());
    CPPUNIT_ASSERT((s.regions.at(kRoom1).gateways == std::set<GatewayId>{kDoor1, kDoor2}));
    CPPUNIT_ASSERT_EQUAL(kRoom1, s.gateways.at(kDoor2).sides[kSideB].region);
    CPPUNIT_ASSERT_EQUAL(kRoom1, *k.regionByName("lab"));  // the lower one had no name
    const RgMapEvent& merged = s.events.back();
    CPPUNIT_ASSERT(merged.kind == RgMapEventKind::RegionsMerged && merged.region == kRoom1 && merged.other == kRoom2);
    CPPUNIT_ASSERT(k.checkConsistency().empty());
    CPPUNIT_ASSERT_EQUAL(scans, k.description(kRoom1).scanCount);
    CPPUNIT_ASSERT_THROW(k.mergeRegions(kRoom1, kRoom1, true), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(k.mergeRegions(kRoom1, kRoom2, true), InvalidArgumentError);
  }

  // Regions joined by a gateway merge without force (the same room seen twice), and the refusal
  // of regions that share none says why.
  void regionsJoinedByAGatewayMergeWithoutForce() {
    RgMappingKernel k = mappedFloor();
    try {
      k.mergeRegions(kRoom1, kRoom2, false);
      CPPUNIT_FAIL("regions with no gateway between them were merged");
    } catch (const InvalidArgumentError& e) {
      CPPUNIT_ASSERT(std::string(e.what()).find("share no gateway") != std::string::npos);
    }
    CPPUNIT_ASSERT_EQUAL(kHallway, k.mergeRegions(kRoom2, kHallway, false));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), k.state().regions.size());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  void pathLeadsThroughBothDoors() {
    const RgMappingKernel k = mappedFloor();
    const RgGraph graph = k.graph();
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), graph.nodes().size());
    const RgPath path = findPath(graph, {kRoom1, {4, 4.5}}, {kRoom2, {9, 4.5}});
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), path.crossings.size());
    const NodeKey expected[] = {
        {kDoor1, GatewaySide::B}, {kDoor1, GatewaySide::A}, {kDoor2, GatewaySide::A}, {kDoor2, GatewaySide::B}};
    const RegionId regions[] = {kRoom1, kHallway, kHallway, kRoom2};
    for (std::size_t i = 0; i < 4; ++i) {
      CPPUNIT_ASSERT(path.crossings[i].key == expected[i]);
      CPPUNIT_ASSERT_EQUAL(regions[i], path.crossings[i].region);
    }
    // 2 m down to the door, 1 m through it, 5 m along the hallway, 1 m through, 2 m up.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(11.0, path.lengthM, 1e-9);
  }

  void learnedCostsAreKept() {
    RgMappingKernel k = mappedFloor();
    k.recordDoorState(kDoor2, false);
    const EdgeKey hallway = edgeKey(EdgeKind::Region, {kDoor1, GatewaySide::A}, {kDoor2, GatewaySide::A});
    k.recordEdgeTraversal(hallway, 5.0, 20.0);
    CPPUNIT_ASSERT_THROW(k.recordDoorState(GatewayId{99}, true), InvalidArgumentError);
    k.nameRegion(kRoom2, "lab");  // any later change keeps them
    const RgGraph graph = k.graph();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(10.0, graph.edges()[*graph.findEdge(hallway)].costM, 1e-9);
    CPPUNIT_ASSERT(graph.edges()[*graph.findEdge(gatewayEdgeKey(kDoor2))].costM > 30.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), static_cast<std::size_t>(std::count_if(
                                             k.state().events.begin(), k.state().events.end(), [](const RgMapEvent& e) {
                                               return e.kind == RgMapEventKind::CostsLearned;
                                             })));
  }

  void revisedPosesMoveTheDescription() {
    RgMappingKernel k = mappedFloor();
    const double northWall = k.description(kRoom2).boundingBox.max().x();
    std::vector<CorrectedPose> revised;
    for (DataId scan : k.state().regions.at(kRoom2).scans) {
      Pose2D p = k.state().scans.at(scan).corrected;
      p.y += 0.5;  // as if SLAM had moved the whole room north
      revised.push_back({scan, p});
    }
    revised.push_back({100000, {}});  // a scan the kernel never had: ignored
    k.revisePoses(revised, 3);
    CPPUNIT_ASSERT_EQUAL(RgMapEventKind::PosesRevised, k.state().events.back().kind);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{3}, k.state().lastPoseRevision);
    // The room's frame faces north (it was entered northwards): its north wall is the box's +x end.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, northWall, 0.05);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.5, k.description(kRoom2).boundingBox.max().x(), 0.05);
    CPPUNIT_ASSERT(k.checkConsistency().empty());
    const std::size_t events = k.state().events.size();
    k.revisePoses(revised, 3);  // nothing new
    CPPUNIT_ASSERT_EQUAL(events, k.state().events.size());
  }

  void badInputsAreRefused() {
    RgMappingKernelConfig badFrames;
    badFrames.models.doorFrames.depthM = -0.1;
    CPPUNIT_ASSERT_THROW(RgMappingKernel{badFrames}, ConfigError);
    RgMappingKernelConfig badPast;
    badPast.models.pastOwnDoors.besideM = NAN;
    CPPUNIT_ASSERT_THROW(RgMappingKernel{badPast}, ConfigError);
    RgMappingKernelConfig badProbe;
    badProbe.models.unattachedDoors.depthM = -1.0;
    CPPUNIT_ASSERT_THROW(RgMappingKernel{badProbe}, ConfigError);
    RgMappingKernelConfig badDoorMatch;
    badDoorMatch.sameDoorM = -1.0;
    CPPUNIT_ASSERT_THROW(RgMappingKernel{badDoorMatch}, ConfigError);
    RgMappingKernel k;
    const std::vector<rgnav::testing::KernelInput> inputs = twoRoomTour().inputs();
    CPPUNIT_ASSERT_EQUAL(std::string(), feedChecked(k, inputs, 0, 20));
    const std::string before = std::to_string(k.state().events.size()) + "/" + std::to_string(k.state().scans.size());
    std::size_t last = 19;
    while (!inputs[last].scan) --last;
    const StoredScan& fed = *inputs[last].scan;
    CPPUNIT_ASSERT_THROW(k.addScan(fed.scan, fed.corrected), InvalidArgumentError);
    LaserScan next = fed.scan;
    next.id = 1000;
    CPPUNIT_ASSERT_THROW(k.addScan(next, {std::nan(""), 0, 0}), InvalidArgumentError);
    const auto event = std::find_if(inputs.begin(), inputs.end(), [](const auto& in) { return in.event.has_value(); });
    CPPUNIT_ASSERT_THROW(k.addGatewayEvent(*event->event, event->lastScanCorrected), InvalidArgumentError);  // old ID
    GatewayEvent broken = *event->event;
    broken.id = 1000;
    broken.gateway.crossingPoints.pop_back();
    CPPUNIT_ASSERT_THROW(k.addGatewayEvent(broken, event->lastScanCorrected), InvalidArgumentError);
    broken = *event->event;
    broken.id = 1000;
    broken.kind = GatewayEventKind::Traversed;
    broken.traversal.toSide = broken.traversal.fromSide;
    CPPUNIT_ASSERT_THROW(k.addGatewayEvent(broken, event->lastScanCorrected), InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(before,
                         std::to_string(k.state().events.size()) + "/" + std::to_string(k.state().scans.size()));
    CPPUNIT_ASSERT_THROW(k.description(RegionId{42}), NotAvailableError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMappingKernelTest);
