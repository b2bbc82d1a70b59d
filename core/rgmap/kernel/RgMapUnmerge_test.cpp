// Tests undoing merges on request (RgMappingKernel::unmergeRegions, RevertibleMerges.h) on the
// synthetic floor of a hallway with two rooms: an undo gives back the map as it was before the
// merge (regions with their IDs, names, scans and object names, gateway sides, neutralisation);
// scans taken since go with the region the robot was in, so that the map equals one that was
// never merged; merges undo in reverse order; and every unsafe undo is refused with a typed
// error that says why, changing nothing: no such merge kept, only the latest N kept, the region
// renamed or merged again since, the robot left it after taking scans, the absorbed region's
// name taken since, a record that does not fit the map (a damaged checkpoint).
#include <cppunit/extensions/HelperMacros.h>

#include <functional>
#include <string>

#include "core/common/Errors.h"
#include "core/rgmap/kernel/RgMappingKernel.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;
using rgnav::testing::KernelInput;

namespace {

constexpr RegionId kHallway{1}, kRoom1{2}, kRoom2{3};
constexpr GatewayId kDoor1{1}, kDoor2{2};

std::vector<KernelInput> tourWithCabinet() {
  return rgnav::testing::twoRoomTour(rgnav::testing::hallwayWithTwoRoomsAndCabinet()).inputs();
}

// The structure of the map: what an undo must give back (events and learned costs aside).
void assertSameStructure(const RgMapState& expected, const RgMapState& actual) {
  CPPUNIT_ASSERT(expected.regions == actual.regions);
  CPPUNIT_ASSERT(expected.gateways == actual.gateways);
  CPPUNIT_ASSERT_EQUAL(expected.current, actual.current);
  CPPUNIT_ASSERT_EQUAL(expected.visitStart, actual.visitStart);
  CPPUNIT_ASSERT_EQUAL(expected.nextRegionId, actual.nextRegionId);
}

// Asks for the undo, which must be refused with a message containing `why` and change nothing.
void assertRefused(RgMappingKernel& k, RegionId merged, const std::string& why) {
  const std::size_t events = k.state().events.size(), kept = k.state().revertibleMerges.size();
  const auto regions = k.state().regions;
  try {
    k.unmergeRegions(merged);
    CPPUNIT_FAIL("the undo of a merge into region " + std::to_string(merged.value()) + " was not refused");
  } catch (const InvalidArgumentError& e) {
    CPPUNIT_ASSERT_MESSAGE(e.what(), std::string(e.what()).find(why) != std::string::npos);
  }
  CPPUNIT_ASSERT_EQUAL(events, k.state().events.size());
  CPPUNIT_ASSERT_EQUAL(kept, k.state().revertibleMerges.size());
  CPPUNIT_ASSERT(regions == k.state().regions);
}

// The number of inputs after which the robot has taken a few scans in room 2 on its first visit.
std::size_t inRoom2(const std::vector<KernelInput>& inputs) {
  RgMappingKernel k;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    rgnav::testing::feed(k, inputs[i]);
    if (k.currentRegionId() == kRoom2 && k.state().regions.at(kRoom2).scans.size() >= 5) return i + 1;
  }
  throw std::logic_error("the tour never enters room 2");
}

}  // namespace

class RgMapUnmergeTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMapUnmergeTest);
  CPPUNIT_TEST(undoGivesBackTheMapBeforeTheMerge);
  CPPUNIT_TEST(undoSeparatesRegionsJoinedByADoor);
  CPPUNIT_TEST(scansTakenSinceGoWithTheRobotsRegion);
  CPPUNIT_TEST(mergesUndoInReverseOrder);
  CPPUNIT_TEST(onlyTheLatestMergesAreKept);
  CPPUNIT_TEST(unsafeUndosAreRefused);
  CPPUNIT_TEST(recordsThatDoNotFitAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  // Rooms on opposite sides of the hallway, one named with a named object, merged by force and
  // the merge undone: the map is what it was, and the undo is an event of its own.
  void undoGivesBackTheMapBeforeTheMerge() {
    const std::vector<KernelInput> inputs = tourWithCabinet();
    RgMappingKernel k = rgnav::testing::mapped(inputs, inputs.size());
    const Pose2D cabinet = k.description(kRoom1).objects.at(0).pose;
    k.nameObject(kRoom1, {cabinet.x, cabinet.y}, "files");
    k.nameRegion(kRoom2, "lab");
    const RgMapState before = k.state();

    CPPUNIT_ASSERT_EQUAL(kRoom1, k.mergeRegions(kRoom2, kRoom1, true));
    CPPUNIT_ASSERT_EQUAL(kRoom1, *k.regionByName("lab"));
    CPPUNIT_ASSERT_EQUAL(kRoom2, k.unmergeRegions(kRoom1));

    assertSameStructure(before, k.state());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
    CPPUNIT_ASSERT_EQUAL(kRoom2, *k.regionByName("lab"));
    CPPUNIT_ASSERT_EQUAL(kRoom1, k.objectByName("files")->region);
    const RgMapEvent& undone = k.state().events.back();
    CPPUNIT_ASSERT_EQUAL(RgMapEventKind::RegionsUnmerged, undone.kind);
    CPPUNIT_ASSERT(undone.region == kRoom1 && undone.other == kRoom2);
    CPPUNIT_ASSERT(k.state().revertibleMerges.empty());
    CPPUNIT_ASSERT_EQUAL(before.regions.at(kRoom1).scans.size(), k.description(kRoom1).scanCount);
  }

  // A merge across a door neutralises it; the undo makes it join its two regions again.
  void undoSeparatesRegionsJoinedByADoor() {
    RgMappingKernel k = rgnav::testing::mapped(tourWithCabinet(), tourWithCabinet().size());
    const RgMapState before = k.state();
    k.mergeRegions(kHallway, kRoom1, false);
    CPPUNIT_ASSERT(k.state().gateways.at(kDoor1).neutralised);
    CPPUNIT_ASSERT_EQUAL(kRoom1, k.unmergeRegions(kHallway));
    assertSameStructure(before, k.state());
    CPPUNIT_ASSERT(!k.state().gateways.at(kDoor1).neutralised);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), k.graph().nodes().size());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  // The robot is in room 2 when it is merged into room 1 and goes on taking scans there: the
  // undo gives them to room 2 (the current region again), as if the merge had not been made.
  void scansTakenSinceGoWithTheRobotsRegion() {
    const std::vector<KernelInput> inputs = tourWithCabinet();
    const std::size_t mergedAt = inRoom2(inputs);
    std::size_t end = mergedAt;
    while (end < mergedAt + 5 && inputs[end].scan && !inputs[end].event) ++end;
    CPPUNIT_ASSERT(end > mergedAt);
    const RgMappingKernel neverMerged = rgnav::testing::mapped(inputs, end);
    CPPUNIT_ASSERT_EQUAL(kRoom2, neverMerged.currentRegionId());

    RgMappingKernel k = rgnav::testing::mapped(inputs, mergedAt);
    k.mergeRegions(kRoom1, kRoom2, true);
    CPPUNIT_ASSERT_EQUAL(std::string(), rgnav::testing::feedChecked(k, inputs, mergedAt, end));
    CPPUNIT_ASSERT_EQUAL(kRoom1, k.currentRegionId());
    CPPUNIT_ASSERT_EQUAL(kRoom2, k.unmergeRegions(kRoom1));
    assertSameStructure(neverMerged.state(), k.state());
    CPPUNIT_ASSERT_EQUAL(kRoom2, k.currentRegionId());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
  }

  // Room 2 into room 1, then room 1 into the hallway: the first merge cannot be undone while the
  // second stands; undone in reverse order, both come back.
  void mergesUndoInReverseOrder() {
    RgMappingKernel k = rgnav::testing::mapped(tourWithCabinet(), tourWithCabinet().size());
    const RgMapState before = k.state();
    k.mergeRegions(kRoom1, kRoom2, true);
    k.mergeRegions(kHallway, kRoom1, false);
    assertRefused(k, kRoom1, "region 2 was merged into another region since");
    CPPUNIT_ASSERT_EQUAL(kRoom1, k.unmergeRegions(kHallway));
    CPPUNIT_ASSERT_EQUAL(kRoom2, k.unmergeRegions(kRoom1));
    assertSameStructure(before, k.state());
    CPPUNIT_ASSERT(k.checkConsistency().empty());
    assertRefused(k, kRoom1, "none is among the latest 8 merges");
  }

  void onlyTheLatestMergesAreKept() {
    RgMappingKernelConfig config;
    config.revertibleMerges = 1;
    RgMappingKernel k(config);
    for (const KernelInput& in : tourWithCabinet()) rgnav::testing::feed(k, in);
    k.mergeRegions(kRoom1, kRoom2, true);
    k.mergeRegions(kHallway, kRoom1, false);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), k.state().revertibleMerges.size());
    CPPUNIT_ASSERT_EQUAL(kRoom1, k.unmergeRegions(kHallway));
    assertRefused(k, kRoom1, "none is among the latest 1 merges");

    config.revertibleMerges = 0;
    RgMappingKernel none(config, k.state());
    none.mergeRegions(kHallway, kRoom1, false);
    assertRefused(none, kHallway, "none is among the latest 0 merges");
  }

  void unsafeUndosAreRefused() {
    const std::vector<KernelInput> inputs = tourWithCabinet();
    RgMappingKernel k = rgnav::testing::mapped(inputs, inputs.size());
    assertRefused(k, kRoom1, "no merge into region 2 can be undone");
    assertRefused(k, RegionId{99}, "no merge into region 99 can be undone");
    k.mergeRegions(kRoom1, kRoom2, true);
    assertRefused(k, kRoom2, "region 3 was merged into region 2: undo that merge");
    k.unmergeRegions(kRoom1);

    // Renamed since; named back, the undo is safe again.
    k.mergeRegions(kRoom1, kRoom2, true);
    k.nameRegion(kRoom1, "offices");
    assertRefused(k, kRoom1, "region 2 was renamed since");
    k.nameRegion(kRoom1, "");
    CPPUNIT_ASSERT_EQUAL(kRoom2, k.unmergeRegions(kRoom1));

    // The absorbed region's name went to another region since.
    k.nameRegion(kRoom2, "lab");
    k.nameRegion(kRoom1, "office");
    k.mergeRegions(kRoom1, kRoom2, true);  // keeps "office"
    k.nameRegion(kHallway, "lab");
    assertRefused(k, kRoom1, "region 1 is named \"lab\" since");
    k.nameRegion(kHallway, "");
    CPPUNIT_ASSERT_EQUAL(kRoom2, k.unmergeRegions(kRoom1));
    CPPUNIT_ASSERT_EQUAL(kRoom2, *k.regionByName("lab"));

    // Objects named in the merged region since.
    k.mergeRegions(kRoom1, kRoom2, true);
    const Pose2D cabinet = k.description(kRoom1).objects.at(0).pose;
    k.nameObject(kRoom1, {cabinet.x, cabinet.y}, "files");
    assertRefused(k, kRoom1, "objects of region 2 were named since");

    // The robot took scans in the merged region and left it: they cannot be divided.
    const std::size_t mergedAt = inRoom2(inputs);
    RgMappingKernel walking = rgnav::testing::mapped(inputs, mergedAt);
    walking.mergeRegions(kRoom1, kRoom2, true);
    std::size_t i = mergedAt;
    while (walking.currentRegionId() == kRoom1) rgnav::testing::feed(walking, inputs.at(i++));
    assertRefused(walking, kRoom1, "the robot took scans in region 2 and left it since");
  }

  // A record a damaged checkpoint could hold, which an undo would turn into an inconsistent map.
  void recordsThatDoNotFitAreRefused() {
    RgMappingKernel k = rgnav::testing::mapped(tourWithCabinet(), tourWithCabinet().size());
    k.nameRegion(kRoom1, "office");
    k.mergeRegions(kRoom1, kRoom2, true);
    const auto damaged = [&](const std::function<void(RevertibleMerge&)>& damage) {
      RgMapState state = k.state();
      damage(state.revertibleMerges.back());
      return RgMappingKernel({}, state);
    };
    const std::string why = "the record of the merge does not fit the map";
    RgMappingKernel extraGateway = damaged([](RevertibleMerge& m) { m.sides[GatewayId{77}] = {RegionId{9}, RegionId{}}; });
    assertRefused(extraGateway, kRoom1, why);
    RgMappingKernel sameName = damaged([](RevertibleMerge& m) { m.absorbed.name = "office"; });
    assertRefused(sameName, kRoom1, why);
    RgMappingKernel unlisted = damaged([](RevertibleMerge& m) { m.absorbed.gateways.clear(); });
    assertRefused(unlisted, kRoom1, why);
    CPPUNIT_ASSERT_EQUAL(kRoom2, k.unmergeRegions(kRoom1));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMapUnmergeTest);
