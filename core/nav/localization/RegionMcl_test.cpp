// Tests of the region MCL on the two-room map (testing/TwoRooms.h): tracking through the door
// with drifting odometry, the hand-over of particles into the second room's frame, the confirmed
// traversal, and the global-map baseline on the same walk.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/localization/RegionMcl.h"
#include "core/nav/localization/testing/TwoRooms.h"

using namespace rgnav;

namespace {

struct Walk {
  double finalError = 0.0, maxError = 0.0;
  RegionId finalRegion;
  std::vector<ConfirmedTraversal> traversals;
  bool allParticlesInRoom2 = false;
};

// Drives from (1, 2) through the door to (7, 2) in 5 cm steps; the odometry reports 8 % too much
// distance and turns 0.02 rad per metre to the left.
Walk walkThroughTheDoor(const LocalizationMap& map, const testing::TwoRooms& rooms, std::uint64_t seed) {
  MclConfig config;
  RegionMcl mcl(config, map, seed);
  Pose2D truth{1.0, 2.0, 0.0}, odometry{10.0, -3.0, 1.0};
  mcl.setPose(truth, Eigen::Vector3d(0.1, 0.1, 0.05), RegionId{1});
  Walk walk;
  DataId id = 1;
  for (; truth.x < 7.0; truth.x += 0.05) {
    if (id > 1) odometry = compose(odometry, Pose2D{0.05 * 1.08, 0.0, 0.05 * 0.02});
    mcl.update(testing::simulatedScan(rooms.walls, truth, odometry, id++));
    const PoseEstimate e = mcl.estimate();
    walk.finalError = std::hypot(e.mapPose.x - truth.x, e.mapPose.y - truth.y);
    walk.maxError = std::max(walk.maxError, walk.finalError);
    walk.finalRegion = e.region;
    for (const ConfirmedTraversal& t : mcl.takeTraversals()) walk.traversals.push_back(t);
  }
  walk.allParticlesInRoom2 = std::all_of(mcl.particles().begin(), mcl.particles().end(),
                                         [](const Particle& p) { return p.region == RegionId{2}; });
  return walk;
}

}  // namespace

class RegionMclTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionMclTest);
  CPPUNIT_TEST(tracksThroughTheDoorIntoTheNextRegion);
  CPPUNIT_TEST(handsParticlesOverIntoTheNeighboursFrame);
  CPPUNIT_TEST(wholeFloorBaselineTracksTheSameWalk);
  CPPUNIT_TEST(stacksTheLinesOfARegionMappedOverItsFreespace);
  CPPUNIT_TEST(refusesBadInitialPoses);
  CPPUNIT_TEST(doesNotUpdateAStandingRobot);
  CPPUNIT_TEST_SUITE_END();

 public:
  void tracksThroughTheDoorIntoTheNextRegion() {
    const testing::TwoRooms rooms = testing::twoRooms();
    const LocalizationMap map = LocalizationMap::fromViews(rooms.regions, rooms.gateways, BeamModelConfig{});
    const Walk walk = walkThroughTheDoor(map, rooms, 1);
    CPPUNIT_ASSERT(walk.maxError < 0.15);
    CPPUNIT_ASSERT(walk.finalError < 0.05);
    CPPUNIT_ASSERT_EQUAL(RegionId{2}, walk.finalRegion);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, walk.traversals.size());
    CPPUNIT_ASSERT_EQUAL(GatewayId{1}, walk.traversals[0].gateway);
    CPPUNIT_ASSERT_EQUAL(RegionId{1}, walk.traversals[0].from);
    CPPUNIT_ASSERT_EQUAL(RegionId{2}, walk.traversals[0].to);
    CPPUNIT_ASSERT(walk.allParticlesInRoom2);
  }

  void handsParticlesOverIntoTheNeighboursFrame() {
    const testing::TwoRooms rooms = testing::twoRooms();
    const LocalizationMap map = LocalizationMap::fromViews(rooms.regions, rooms.gateways, BeamModelConfig{});
    CPPUNIT_ASSERT_EQUAL(RegionId{1}, map.handOver(RegionId{1}, Eigen::Vector2d(3.9, 2.0), 3.0));
    CPPUNIT_ASSERT_EQUAL(RegionId{2}, map.handOver(RegionId{1}, Eigen::Vector2d(4.1, 2.0), 3.0));
    CPPUNIT_ASSERT_EQUAL(RegionId{1}, map.handOver(RegionId{2}, Eigen::Vector2d(3.9, 2.0), 3.0));
    // A particle in the other room's freespace belongs to it, wherever it crossed; one outside
    // every freespace and far from the door stays where it was.
    CPPUNIT_ASSERT_EQUAL(RegionId{2}, map.handOver(RegionId{1}, Eigen::Vector2d(7.5, 3.5), 3.0));
    CPPUNIT_ASSERT_EQUAL(RegionId{1}, map.handOver(RegionId{1}, Eigen::Vector2d(20.0, 20.0), 3.0));
    CPPUNIT_ASSERT_EQUAL(RegionId{1}, map.handOver(RegionId{1}, Eigen::Vector2d(3.9, 2.0), 3.0));
    // A particle keeps its map pose across the hand-over.
    RegionMcl mcl(MclConfig{}, map, 3);
    mcl.setParticles({{RegionId{1}, Pose2D{3.95, 2.0, 0.0}, 1.0}});
    const Pose2D before = mcl.mapPose(mcl.particles()[0]);
    const Pose2D inTwo = between(map.region(RegionId{2}).frame, before);
    mcl.setParticles({{RegionId{2}, inTwo, 1.0}});
    const Pose2D after = mcl.mapPose(mcl.particles()[0]);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(before.x, after.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(before.y, after.y, 1e-9);
  }

  void wholeFloorBaselineTracksTheSameWalk() {
    const testing::TwoRooms rooms = testing::twoRooms();
    const LocalizationMap map = LocalizationMap::wholeFloor(rooms.regions, BeamModelConfig{});
    const Walk walk = walkThroughTheDoor(map, rooms, 2);
    CPPUNIT_ASSERT(walk.finalError < 0.05);
    CPPUNIT_ASSERT_EQUAL(RegionId{1}, walk.finalRegion);
    CPPUNIT_ASSERT(walk.traversals.empty());
  }

  void stacksTheLinesOfARegionMappedOverItsFreespace() {
    // Region 3 maps room 1 a second time (no gateway joins them, as when the kernel did not
    // recognise a return); only region 3 holds the top wall. Region 1's field must have it.
    testing::TwoRooms rooms = testing::twoRooms();
    RegionView twin = rooms.regions[0];
    twin.summary.id = RegionId{3};
    twin.summary.gateways.clear();
    twin.lines = {{{0, 4}, {4, 4}}};
    std::erase_if(rooms.regions[0].lines, [](const Segment2& l) { return l.a.y() == 4.0 && l.b.y() == 4.0; });
    const Eigen::Vector2d onTopWall(2.0, 4.0);
    std::vector<RegionView> regions = rooms.regions;
    regions.push_back(twin);
    const LocalizationMap overlapping = LocalizationMap::fromViews(regions, rooms.gateways, BeamModelConfig{});
    twin.freespace = FreespaceBitmap::allOccupied(0.15, Eigen::Vector2d::Zero(), 1, 1);
    regions.back() = twin;
    const LocalizationMap apart = LocalizationMap::fromViews(regions, rooms.gateways, BeamModelConfig{});
    CPPUNIT_ASSERT(overlapping.field(RegionId{1}).logLikelihood(onTopWall) > 1.0);
    CPPUNIT_ASSERT(apart.field(RegionId{1}).logLikelihood(onTopWall) < -1.0);
  }

  void refusesBadInitialPoses() {
    const testing::TwoRooms rooms = testing::twoRooms();
    const LocalizationMap map = LocalizationMap::fromViews(rooms.regions, rooms.gateways, BeamModelConfig{});
    RegionMcl mcl(MclConfig{}, map, 4);
    CPPUNIT_ASSERT_THROW(mcl.update(LaserScan{}), NotAvailableError);
    CPPUNIT_ASSERT_THROW(mcl.setPose(Pose2D{NAN, 0, 0}, Eigen::Vector3d(0.1, 0.1, 0.1), RegionId{1}), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(mcl.setPose(Pose2D{1, 1, 0}, Eigen::Vector3d(-0.1, 0.1, 0.1), RegionId{1}), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(mcl.setPose(Pose2D{50, 50, 0}, Eigen::Vector3d(0.1, 0.1, 0.1), RegionId{9}), NotAvailableError);
    CPPUNIT_ASSERT_THROW(mcl.setParticles({{RegionId{9}, Pose2D{}, 1.0}}), InvalidArgumentError);
  }

  void doesNotUpdateAStandingRobot() {
    const testing::TwoRooms rooms = testing::twoRooms();
    const LocalizationMap map = LocalizationMap::fromViews(rooms.regions, rooms.gateways, BeamModelConfig{});
    RegionMcl mcl(MclConfig{}, map, 5);
    const Pose2D pose{2, 2, 0};
    mcl.setPose(pose, Eigen::Vector3d(0.1, 0.1, 0.05), RegionId{1});
    CPPUNIT_ASSERT(mcl.update(testing::simulatedScan(rooms.walls, pose, pose, 1)));
    CPPUNIT_ASSERT(!mcl.update(testing::simulatedScan(rooms.walls, pose, pose, 2)));
    CPPUNIT_ASSERT(mcl.update(testing::simulatedScan(rooms.walls, pose, Pose2D{2.1, 2, 0}, 3)));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RegionMclTest);
