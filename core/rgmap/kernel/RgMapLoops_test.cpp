// Tests the RG Mapping Kernel's structural consistency rules (thesis 6.1.1): around a ring
// corridor with one door (figure 6.1) the door seen again from the side of the first region
// closes the loop, the two regions are merged and the door, with the same region on both sides
// now, is neutralised; traversing it again changes nothing. A door missed on the way into a room
// (figure 6.4) is repaired when it is later observed from inside the room, or only reported when
// the robot leaves through it: the hallway's region is split where the path crossed the door,
// and an object of the room named before the split keeps its name in the room's new region.
// A known door the robot passes while the detector reports nothing of it (the detector lost it)
// is traversed all the same once the robot stands beyond it; the detector's own report of that
// passage, coming late, changes nothing then.
// A door the detector reports anew under another ID is the known door: traversed out of the room
// it keeps the room and the hallway apart (its crossing points numbered from the room's side),
// and seen again from the west of the ring it closes the loop as the first door would; seen
// through another door, it closes nothing.
// Gateway hypotheses that turn out to be no transition are dropped. Consistency holds after
// every input.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <utility>

#include "core/rgmap/kernel/ObjectNames.h"
#include "core/rgmap/kernel/RgMappingKernel.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;
using rgnav::testing::DoorReports;
using rgnav::testing::feedChecked;
using rgnav::testing::KernelInput;
using rgnav::testing::SyntheticTour;

namespace {

void feedAll(RgMappingKernel& k, const std::vector<KernelInput>& inputs, std::size_t begin, std::size_t end) {
  CPPUNIT_ASSERT_EQUAL(std::string(), feedChecked(k, inputs, begin, end));
}

// The detector's update of the gateway of `input`'s event: now labelled `classes`.
void relabel(RgMappingKernel& k, const KernelInput& input, std::vector<ClassProbability> classes) {
  GatewayEvent update = *input.event;
  update.id += 1000;
  update.kind = GatewayEventKind::Updated;
  update.gateway.classes = std::move(classes);
  k.addGatewayEvent(update, input.lastScanCorrected);
}

// The index of the first input after `from` that is a gateway event of `kind`.
std::size_t nextEvent(const std::vector<KernelInput>& inputs, std::size_t from, GatewayEventKind kind) {
  for (std::size_t i = from; i < inputs.size(); ++i)
    if (inputs[i].event && inputs[i].event->kind == kind) return i;
  CPPUNIT_FAIL("no such event");
  return inputs.size();
}

bool happened(const RgMappingKernel& k, RgMapEventKind kind) {
  return std::any_of(k.state().events.begin(), k.state().events.end(),
                     [&](const RgMapEvent& e) { return e.kind == kind; });
}

// Into room 1 of hallwayWithTwoRooms() and around in it, door 11 unseen, then (after
// `whileInside` was applied to the tour) back out to the hallway.
SyntheticTour missedDoorTour(DoorReports whileInside,
                             rgnav::testing::TourWorld world = rgnav::testing::hallwayWithTwoRooms()) {
  SyntheticTour tour(std::move(world), rgnav::testing::kTourDrift);
  tour.setReports(DetectorGatewayId{11}, DoorReports::None);
  tour.driveThrough({{1, 0.9}, {4, 0.9}, {4, 3.5}, {3, 4.5}, {5, 4.5}, {4, 3.5}});
  tour.setReports(DetectorGatewayId{11}, whileInside);
  tour.driveThrough({{4, 4}, {4, 3.5}, {4, 0.9}, {1, 0.9}});
  return tour;
}

// Every scan north of door 11's line (y = 2) lies in `room`, every other one in `hallway`.
void checkScansSplitAtDoor11(const RgMapState& s, RegionId room, RegionId hallway) {
  for (const auto& [id, region] : s.regions)
    for (DataId scan : region.scans)
      CPPUNIT_ASSERT_EQUAL_MESSAGE("scan " + std::to_string(scan), s.scans.at(scan).corrected.y > 2.0 ? room : hallway,
                                   id);
}

// Two regions split by door 11 (detector ID): the hallway's scans in region 1, the room's in region 2.
void checkRepairedRoom(const RgMappingKernel& k) {
  const RgMapState& s = k.state();
  CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.regions.size());
  CPPUNIT_ASSERT_EQUAL(std::size_t(1), s.gateways.size());
  const Gateway& door = s.gateways.begin()->second;
  CPPUNIT_ASSERT_EQUAL(DetectorGatewayId{11}, door.record.id);
  CPPUNIT_ASSERT(!door.neutralised);
  const RegionId room = door.sides[kSideA].region;  // the side it was first seen from: the room
  CPPUNIT_ASSERT_EQUAL(RegionId(2), room);
  CPPUNIT_ASSERT_EQUAL(RegionId(1), door.sides[kSideB].region);
  checkScansSplitAtDoor11(s, room, RegionId{1});
  CPPUNIT_ASSERT(happened(k, RgMapEventKind::GatewayRepaired));
  CPPUNIT_ASSERT_EQUAL(RegionId(1), k.currentRegionId());
}

// After a tour into room 1, out, and into it again: the hallway and the room are two regions
// joined by door 11, and the robot is in the room's region with every scan it took in the room.
void checkRoomRevisited(const RgMappingKernel& k) {
  const RgMapState& s = k.state();
  CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.regions.size());
  const Gateway& door = s.gateways.at(GatewayId{1});
  CPPUNIT_ASSERT(!door.neutralised);
  const RegionId hallway = door.sides[kSideA].region, room = door.sides[kSideB].region;
  CPPUNIT_ASSERT(hallway == RegionId{1} && room == RegionId{2});
  CPPUNIT_ASSERT_EQUAL(room, k.currentRegionId());
  checkScansSplitAtDoor11(s, room, hallway);
}

}  // namespace

class RgMapLoopsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMapLoopsTest);
  CPPUNIT_TEST(ringLoopMergesRegionsAndNeutralisesTheDoor);
  CPPUNIT_TEST(doorMissedOnEntryIsRepairedWhenSeenFromInside);
  CPPUNIT_TEST(doorMissedOnEntryIsRepairedWhenTraversedOut);
  CPPUNIT_TEST(repairedRoomKeepsItsObjectNames);
  CPPUNIT_TEST(knownDoorPassedWithoutReportIsTraversed);
  CPPUNIT_TEST(lateReportOfAPassedDoorChangesNothing);
  CPPUNIT_TEST(doorDetectedAnewIsTheKnownDoor);
  CPPUNIT_TEST(doorDetectedAnewClosesTheRing);
  CPPUNIT_TEST(doorSeenThroughAnotherDoorClosesNothing);
  CPPUNIT_TEST(noTransitionAfterAllIsDropped);
  CPPUNIT_TEST(traversedWiderTwinJoinsItsSides);
  CPPUNIT_TEST(traversalReportedAsWiderTwinIsTheRelabelling);
  CPPUNIT_TEST(widerTwinLabelOnAnAliasTakesOnlyTheAlias);
  CPPUNIT_TEST_SUITE_END();

 public:
  void ringLoopMergesRegionsAndNeutralisesTheDoor() {
    const std::vector<KernelInput> inputs = rgnav::testing::ringTour().inputs();
    RgMappingKernel k;
    // Up to the first traversal and around the block: two regions joined by the door.
    const std::size_t traversal = nextEvent(inputs, 0, GatewayEventKind::Traversed);
    const std::size_t seenAgain = nextEvent(inputs, traversal, GatewayEventKind::Updated);
    feedAll(k, inputs, 0, seenAgain);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), k.state().regions.size());
    CPPUNIT_ASSERT_EQUAL(RegionId(2), k.currentRegionId());
    const Gateway& before = k.state().gateways.at(GatewayId{1});
    CPPUNIT_ASSERT(before.sides[kSideA].region == RegionId{1} && before.sides[kSideB].region == RegionId{2} && !before.neutralised);

    // The door seen again from its west side, which lies in region 1: the robot is in region 1.
    feedAll(k, inputs, seenAgain, seenAgain + 1);
    const RgMapState& s = k.state();
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), s.regions.size());
    CPPUNIT_ASSERT_EQUAL(RegionId(1), k.currentRegionId());
    const Gateway& door = s.gateways.at(GatewayId{1});
    CPPUNIT_ASSERT(door.neutralised);
    CPPUNIT_ASSERT(door.sides[kSideA].region == RegionId{1} && door.sides[kSideB].region == RegionId{1});
    const auto merged = std::find_if(s.events.begin(), s.events.end(),
                                     [](const RgMapEvent& e) { return e.kind == RgMapEventKind::RegionsMerged; });
    CPPUNIT_ASSERT(merged != s.events.end() && merged->region == RegionId{1} && merged->other == RegionId{2});
    CPPUNIT_ASSERT(std::next(merged) != s.events.end() &&
                   std::next(merged)->kind == RgMapEventKind::GatewayNeutralised);
    CPPUNIT_ASSERT_EQUAL(s.scans.size(), s.regions.at(RegionId{1}).scans.size());

    // Through the door again: nothing changes but the traversal count.
    feedAll(k, inputs, seenAgain + 1, inputs.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().regions.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), k.state().gateways.at(GatewayId{1}).traversalsFrom[kSideA]);
    CPPUNIT_ASSERT_EQUAL(RgMapEventKind::GatewayTraversed, k.state().events.back().kind);
    CPPUNIT_ASSERT_EQUAL(k.state().events.back().region, k.state().events.back().other);
    // The neutralised door stays in the RG Graph, inside the one region.
    const RgGraph graph = k.graph();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), graph.nodes().size());
    CPPUNIT_ASSERT(graph.nodes()[0].region == RegionId{1} && graph.nodes()[1].region == RegionId{1});
  }

  void doorMissedOnEntryIsRepairedWhenSeenFromInside() {
    const std::vector<KernelInput> inputs = missedDoorTour(DoorReports::All).inputs();
    RgMappingKernel k;
    const std::size_t detected = nextEvent(inputs, 0, GatewayEventKind::Detected);
    feedAll(k, inputs, 0, detected);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().regions.size());  // the room is still "hallway"
    feedAll(k, inputs, detected, detected + 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), k.state().regions.size());
    CPPUNIT_ASSERT_EQUAL(RegionId(2), k.currentRegionId());
    feedAll(k, inputs, detected + 1, inputs.size());
    checkRepairedRoom(k);
  }

  void doorMissedOnEntryIsRepairedWhenTraversedOut() {
    const std::vector<KernelInput> inputs = missedDoorTour(DoorReports::TraversalsOnly).inputs();
    CPPUNIT_ASSERT_EQUAL(
        std::size_t(1), static_cast<std::size_t>(std::count_if(
                            inputs.begin(), inputs.end(), [](const KernelInput& in) { return in.event.has_value(); })));
    RgMappingKernel k;
    feedAll(k, inputs, 0, inputs.size());
    checkRepairedRoom(k);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().gateways.begin()->second.traversalsFrom[kSideA]);
  }

  void repairedRoomKeepsItsObjectNames() {
    // The cabinet in room 1, named while the room is part of the hallway's region.
    const std::vector<KernelInput> inputs =
        missedDoorTour(DoorReports::All, rgnav::testing::hallwayWithTwoRoomsAndCabinet()).inputs();
    RgMappingKernel k;
    const std::size_t detected = nextEvent(inputs, 0, GatewayEventKind::Detected);
    feedAll(k, inputs, 0, detected);
    const Eigen::Vector2d truth = rgnav::testing::cabinetCentre();
    const Pose2D cabinet = between(k.state().regions.at(RegionId{1}).frame, {truth.x(), truth.y(), 0.0});
    k.nameObject(RegionId{1}, {cabinet.x, cabinet.y}, "cabinet");
    CPPUNIT_ASSERT_EQUAL(RegionId(1), k.objectByName("cabinet")->region);

    feedAll(k, inputs, detected, inputs.size());
    checkRepairedRoom(k);
    const auto named = k.objectByName("cabinet");
    CPPUNIT_ASSERT(named && named->region == RegionId{2});
    const std::vector<std::string> names = objectNamesOf(k.state().regions.at(RegionId{2}), k.description(RegionId{2}).objects);
    CPPUNIT_ASSERT(std::find(names.begin(), names.end(), "cabinet") != names.end());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  void knownDoorPassedWithoutReportIsTraversed() {
    SyntheticTour tour(rgnav::testing::hallwayWithTwoRooms(), rgnav::testing::kTourDrift);
    tour.driveThrough({{1, 0.9}, {4, 0.9}, {4, 4.5}, {4, 0.9}, {1, 0.9}});  // into room 1 and out again
    tour.setReports(DetectorGatewayId{11}, DoorReports::None);
    tour.driveThrough({{4, 0.9}, {4, 4.5}});  // in once more, unreported
    RgMappingKernel k;
    feedAll(k, tour.inputs(), 0, tour.inputs().size());
    checkRoomRevisited(k);
    CPPUNIT_ASSERT(happened(k, RgMapEventKind::GatewayRepaired));
  }

  void lateReportOfAPassedDoorChangesNothing() {
    SyntheticTour tour(rgnav::testing::hallwayWithTwoRooms(), rgnav::testing::kTourDrift);
    tour.driveThrough({{1, 0.9}, {4, 0.9}, {4, 4.5}, {4, 0.9}, {1, 0.9}, {4, 0.9}, {4, 4.5}});
    std::vector<KernelInput> inputs = tour.inputs();
    // The detector reports the second entry when the robot is 1 m beyond the door (four scans on).
    const auto entry = std::find_if(inputs.rbegin(), inputs.rend(), [](const KernelInput& in) {
                         return in.event && in.event->kind == GatewayEventKind::Traversed;
                       }).base() - 1;
    CPPUNIT_ASSERT(std::all_of(entry + 1, entry + 5, [](const KernelInput& in) { return in.scan.has_value(); }));
    std::rotate(entry, entry + 1, entry + 5);
    RgMappingKernel k;
    feedAll(k, inputs, 0, inputs.size());
    checkRoomRevisited(k);
  }

  void doorDetectedAnewIsTheKnownDoor() {
    SyntheticTour tour(rgnav::testing::hallwayWithTwoRooms(), rgnav::testing::kTourDrift);
    tour.driveThrough({{1, 0.9}, {4, 0.9}, {4, 4.5}, {3, 5}});  // in through door 11, out of its range
    tour.redetect(DetectorGatewayId{11}, DetectorGatewayId{111});
    tour.driveThrough({{4, 4.5}, {4, 0.9}, {1, 0.9}});  // out again: door 111, first seen from the room
    RgMappingKernel k;
    feedAll(k, tour.inputs(), 0, tour.inputs().size());
    const RgMapState& s = k.state();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.regions.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), s.gateways.size());
    const Gateway& door = s.gateways.begin()->second;
    CPPUNIT_ASSERT_EQUAL(DetectorGatewayId{11}, door.record.id);
    CPPUNIT_ASSERT(door.aliases == std::vector<DetectorGatewayId>{DetectorGatewayId{111}});
    CPPUNIT_ASSERT(!door.neutralised);
    CPPUNIT_ASSERT(door.traversalsFrom[kSideA] == 1 && door.traversalsFrom[kSideB] == 1);
    CPPUNIT_ASSERT_EQUAL(door.sides[kSideA].region, k.currentRegionId());  // back in the hallway
  }

  void doorDetectedAnewClosesTheRing() {
    SyntheticTour tour(rgnav::testing::ringCorridor(), rgnav::testing::kTourDrift);
    tour.driveThrough({{1.1, 1}, {9, 1}, {9, 9}, {1, 9}});
    tour.redetect(DetectorGatewayId{21}, DetectorGatewayId{121});
    tour.driveThrough({{1, 1}, {4.2, 1}});  // the door seen from its west side, not traversed
    RgMappingKernel k;
    feedAll(k, tour.inputs(), 0, tour.inputs().size());
    const RgMapState& s = k.state();
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), s.regions.size());
    const Gateway& door = s.gateways.begin()->second;
    CPPUNIT_ASSERT(door.aliases == std::vector<DetectorGatewayId>{DetectorGatewayId{121}});
    CPPUNIT_ASSERT(door.neutralised);
    CPPUNIT_ASSERT(happened(k, RgMapEventKind::RegionsMerged));
  }

  void doorSeenThroughAnotherDoorClosesNothing() {
    // Room 1 split by an inner wall at y = 2.9 with door 13 above door 11.
    rgnav::testing::TourWorld world = rgnav::testing::hallwayWithTwoRooms();
    world.walls.push_back({{2, 2.9}, {3.55, 2.9}});
    world.walls.push_back({{4.45, 2.9}, {6, 2.9}});
    world.doors.push_back({DetectorGatewayId{13}, {3.55, 2.9}, {4.45, 2.9}, DoorReports::All});
    SyntheticTour tour(world, rgnav::testing::kTourDrift, 0.25, 1.2);
    tour.driveThrough({{1, 0.9}, {4, 0.9}, {4, 4.6}});  // through doors 11 and 13
    tour.redetect(DetectorGatewayId{11}, DetectorGatewayId{111});
    // Door 11 seen again from (4, 3.1), 0.6 m from its room-side crossing point, through door 13.
    tour.driveThrough({{4, 3.1}});
    RgMappingKernel k;
    feedAll(k, tour.inputs(), 0, tour.inputs().size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), k.state().regions.size());
    CPPUNIT_ASSERT(!happened(k, RgMapEventKind::RegionsMerged));
    CPPUNIT_ASSERT(k.state().gateways.at(GatewayId{1}).aliases == std::vector<DetectorGatewayId>{DetectorGatewayId{111}});
  }

  void noTransitionAfterAllIsDropped() {
    const std::vector<KernelInput> inputs = rgnav::testing::ringTour().inputs();
    RgMappingKernel k;
    const std::size_t detected = nextEvent(inputs, 0, GatewayEventKind::Detected);
    feedAll(k, inputs, 0, detected + 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().gateways.size());
    // The detector changes its mind before the robot gets there: a dead end, not a gateway.
    relabel(k, inputs[detected], {{"Deadend", 0.9}, {kNarrowPassageClass, 0.1}});
    CPPUNIT_ASSERT(k.state().gateways.empty());
    CPPUNIT_ASSERT(k.state().regions.at(RegionId{1}).gateways.empty());
    CPPUNIT_ASSERT_EQUAL(RgMapEventKind::GatewayDropped, k.state().events.back().kind);
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  void traversedWiderTwinJoinsItsSides() {
    const std::vector<KernelInput> inputs = rgnav::testing::ringTour().inputs();
    RgMappingKernel k;
    const std::size_t traversed = nextEvent(inputs, 0, GatewayEventKind::Traversed);
    feedAll(k, inputs, 0, traversed + 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), k.state().regions.size());
    // The detector finds the door beside it: this passage was the same opening seen askew.
    relabel(k, inputs[traversed], {{kWiderTwinClass, 0.9}});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().regions.size());
    const Gateway& twin = k.state().gateways.begin()->second;
    CPPUNIT_ASSERT(twin.neutralised);
    CPPUNIT_ASSERT_EQUAL(std::string(kWiderTwinClass), twin.record.label());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  void traversalReportedAsWiderTwinIsTheRelabelling() {
    std::vector<KernelInput> inputs = rgnav::testing::ringTour().inputs();
    const std::size_t traversed = nextEvent(inputs, 0, GatewayEventKind::Traversed);
    inputs[traversed].event->gateway.classes = {{kWiderTwinClass, 0.9}};  // superseded as it was crossed
    RgMappingKernel k;
    feedAll(k, inputs, 0, traversed + 1);
    CPPUNIT_ASSERT(k.state().gateways.empty());  // never traversed: dropped
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().regions.size());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  void widerTwinLabelOnAnAliasTakesOnlyTheAlias() {
    SyntheticTour tour(rgnav::testing::hallwayWithTwoRooms(), rgnav::testing::kTourDrift);
    tour.driveThrough({{1, 0.9}, {4, 0.9}, {4, 4.5}, {3, 5}});
    tour.redetect(DetectorGatewayId{11}, DetectorGatewayId{111});
    tour.driveThrough({{4, 4.5}, {4, 0.9}, {1, 0.9}});
    const std::vector<KernelInput>& inputs = tour.inputs();
    RgMappingKernel k;
    feedAll(k, inputs, 0, inputs.size());
    const auto last111 = std::find_if(inputs.rbegin(), inputs.rend(),
                                      [](const KernelInput& in) { return in.event && in.event->gateway.id == DetectorGatewayId{111}; });
    CPPUNIT_ASSERT(last111 != inputs.rend());
    relabel(k, *last111, {{kWiderTwinClass, 0.9}});
    const RgMapState& s = k.state();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), s.regions.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), s.gateways.size());
    const Gateway& door = s.gateways.begin()->second;
    CPPUNIT_ASSERT(door.aliases.empty());
    CPPUNIT_ASSERT(!door.neutralised);
    CPPUNIT_ASSERT_EQUAL(std::string(kNarrowPassageClass), door.record.label());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMapLoopsTest);
