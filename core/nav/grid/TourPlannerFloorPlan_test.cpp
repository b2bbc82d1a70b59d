// Tests the room tour on real furnished floor plans of the IPA room segmentation benchmark
// (shared data, floorplans/SOURCES.md): from the most open spot of the map, the tour visits every
// ground-truth room reachable for a 0.5 m wide robot (and lists Freiburg79's closed-off rooms as
// unreachable); the simulated robot drives the whole route with pure pursuit at 20 Hz, reaching
// every visiting point without a collision.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <string>

#include "core/logs/LogTestFiles.h"
#include "core/nav/grid/PurePursuit.h"
#include "core/nav/grid/TourPlanner.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/IpaGroundTruth.h"

using rgnav::OccupancyGrid;
using rgnav::WorldPoint;

namespace {

std::string mapFile(const std::string& name) {
  return rgnav::testing::sharedData("floorplans/ipa_room_segmentation/test_maps/" + name);
}

// The cell farthest from any obstacle.
WorldPoint mostOpenSpot(const OccupancyGrid& grid) {
  const rgnav::GridPlanner planner(grid);
  rgnav::CellIndex best;
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col)
      if (planner.clearance().at({col, row}) > planner.clearance().at(best)) best = {col, row};
  return grid.center(best);
}

// Plans and drives the tour of map `name`; returns the number of rooms visited.
std::size_t driveTour(const std::string& name, std::size_t expectedUnreachable) {
  const OccupancyGrid grid = rgnav::loadFloorPlan(mapFile(name + "_furnitures.png"));
  const rgnav::GroundTruth truth =
      rgnav::loadIpaGroundTruth(mapFile(name + "_gt_segmentation.png"), mapFile(name + ".png"), grid);
  const WorldPoint s = mostOpenSpot(grid);
  const rgnav::Tour tour = rgnav::planTour(grid, truth.labels, truth.roomCount, {s.x, s.y, 0.0});
  CPPUNIT_ASSERT_EQUAL(expectedUnreachable, tour.unreachableRooms.size());
  CPPUNIT_ASSERT_EQUAL(static_cast<std::size_t>(truth.roomCount) - expectedUnreachable, tour.visits.size());

  const rgnav::PurePursuitConfig config;
  rgnav::PurePursuit follower(config, tour.route);
  rgnav::DiffDriveRobot robot(rgnav::DiffDriveConfig{}, {s.x, s.y, 0.0});
  std::vector<double> closest(tour.visits.size(), 1e9);
  int collisions = 0;
  for (int k = 0; k < 20 * 7200 && !follower.reached(); ++k) {
    robot.command(follower.command(robot.pose()));
    if (robot.step(0.05, grid) == rgnav::StepOutcome::Collided) ++collisions;
    for (std::size_t i = 0; i < tour.visits.size(); ++i) {
      const WorldPoint g = tour.visits[i].goal;
      closest[i] = std::min(closest[i], std::hypot(robot.pose().x - g.x, robot.pose().y - g.y));
    }
  }
  CPPUNIT_ASSERT(follower.reached());
  CPPUNIT_ASSERT_EQUAL(0, collisions);
  for (const double d : closest) CPPUNIT_ASSERT(d <= config.goalTolerance + 1e-9);
  return tour.visits.size();
}

}  // namespace

class TourPlannerFloorPlanTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TourPlannerFloorPlanTest);
  CPPUNIT_TEST(freiburg52VisitsAllRooms);
  CPPUNIT_TEST(labAVisitsAllRoomsThroughTightFurniture);
  CPPUNIT_TEST(freiburg79FlagsClosedOffRooms);
  CPPUNIT_TEST_SUITE_END();

 public:
  void freiburg52VisitsAllRooms() { CPPUNIT_ASSERT_EQUAL(std::size_t{10}, driveTour("Freiburg52_scan", 0)); }
  void labAVisitsAllRoomsThroughTightFurniture() { CPPUNIT_ASSERT_EQUAL(std::size_t{46}, driveTour("lab_a_scan", 0)); }
  // Four rooms of Freiburg79 have no free connection at all to the rest of the map.
  void freiburg79FlagsClosedOffRooms() { CPPUNIT_ASSERT_EQUAL(std::size_t{16}, driveTour("Freiburg79_scan", 4)); }
};
CPPUNIT_TEST_SUITE_REGISTRATION(TourPlannerFloorPlanTest);
