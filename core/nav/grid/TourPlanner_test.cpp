// Tests the room tour on a constructed floor: a corridor with three rooms below and, above it,
// one room with a wide door, one whose door is too narrow for a 0.5 m robot and one without a
// door. The tour visits every reachable room once at a point inside it, lists the other two as
// unreachable, and the robot drives the whole route with pure pursuit without a collision.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/grid/PurePursuit.h"
#include "core/nav/grid/TourPlanner.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "core/sim/scenarios/GridDrawing.h"

using rgnav::Cell;
using rgnav::OccupancyGrid;
using rgnav::WorldPoint;
using rgnav::WorldRect;

namespace {

struct Floor {
  OccupancyGrid grid;
  std::vector<int> rooms;  // per cell, row-major
  int roomCount = 0;

  int roomAt(WorldPoint p) const { return rooms[rgnav::rowMajor(*grid.cellOf(p), grid.width())]; }
};

// Rooms: 0 corridor, 1-3 below it, 4 above (wide door), 5 above (0.35 m door), 6 above (sealed).
Floor makeFloor() {
  const std::vector<WorldRect> rooms = {
      {0.0, 4.0, 16.0, 6.0},  {0.0, 0.0, 4.9, 3.9},   {5.0, 0.0, 9.9, 3.9},  {10.0, 0.0, 16.0, 3.9},
      {0.0, 6.1, 7.9, 10.0},  {8.0, 6.1, 11.9, 10.0}, {12.0, 6.1, 16.0, 10.0}};
  const std::vector<WorldRect> doors = {{2.0, 3.85, 2.9, 4.05},  {6.0, 3.85, 6.9, 4.05},
                                        {14.0, 3.85, 14.9, 4.05}, {3.0, 5.95, 3.9, 6.15},
                                        {9.0, 5.95, 9.35, 6.15}};
  Floor f{OccupancyGrid(328, 208, 0.05, {-0.2, -0.2}, Cell::Occupied), {}, static_cast<int>(rooms.size())};
  for (const WorldRect& r : rooms) rgnav::fillRect(f.grid, r, Cell::Free);
  for (const WorldRect& d : doors) rgnav::fillRect(f.grid, d, Cell::Free);
  f.rooms.assign(f.grid.cells().size(), -1);
  for (int row = 0; row < f.grid.height(); ++row) {
    for (int col = 0; col < f.grid.width(); ++col) {
      const WorldPoint p = f.grid.center({col, row});
      for (std::size_t room = 0; room < rooms.size(); ++room) {
        const WorldRect& r = rooms[room];
        if (p.x >= r.minX && p.x <= r.maxX && p.y >= r.minY && p.y <= r.maxY) {
          f.rooms[rgnav::rowMajor({col, row}, f.grid.width())] = static_cast<int>(room);
        }
      }
    }
  }
  return f;
}

}  // namespace

class TourPlannerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TourPlannerTest);
  CPPUNIT_TEST(visitsEveryReachableRoomOnce);
  CPPUNIT_TEST(robotDrivesTheTourWithoutCollision);
  CPPUNIT_TEST(badInputIsTypedError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void visitsEveryReachableRoomOnce() {
    const Floor f = makeFloor();
    const rgnav::Tour tour = rgnav::planTour(f.grid, f.rooms, f.roomCount, {1.0, 5.0, 0.0});
    CPPUNIT_ASSERT((tour.unreachableRooms == std::vector<int>{5, 6}));
    CPPUNIT_ASSERT_EQUAL(std::size_t{5}, tour.visits.size());
    std::vector<int> rooms;
    std::size_t previous = 0;
    for (const rgnav::RoomVisit& v : tour.visits) {
      rooms.push_back(v.room);
      CPPUNIT_ASSERT_EQUAL(v.room, f.roomAt(v.goal));
      CPPUNIT_ASSERT(v.routeIndex > previous || (previous == 0 && v.routeIndex >= 1));
      previous = v.routeIndex;
      CPPUNIT_ASSERT_DOUBLES_EQUAL(v.goal.x, tour.route[v.routeIndex].x, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(v.goal.y, tour.route[v.routeIndex].y, 1e-12);
    }
    std::sort(rooms.begin(), rooms.end());
    CPPUNIT_ASSERT((rooms == std::vector<int>{0, 1, 2, 3, 4}));
    CPPUNIT_ASSERT_EQUAL(tour.route.size() - 1, tour.visits.back().routeIndex);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, tour.route.front().x, 1e-12);
    // Visiting points lie deep inside: a 4.9 x 3.9 m room's farthest point from the walls is
    // about 1.9 m from them.
    for (const rgnav::RoomVisit& v : tour.visits) {
      if (v.room == 1) {
        CPPUNIT_ASSERT(v.goal.y > 1.5 && v.goal.y < 2.4);
      }
    }
  }

  void robotDrivesTheTourWithoutCollision() {
    const Floor f = makeFloor();
    const rgnav::Pose2D start{1.0, 5.0, 0.0};
    const rgnav::Tour tour = rgnav::planTour(f.grid, f.rooms, f.roomCount, start);
    rgnav::PurePursuit follower(rgnav::PurePursuitConfig{}, tour.route);
    rgnav::DiffDriveRobot robot(rgnav::DiffDriveConfig{}, start);
    std::vector<double> closest(tour.visits.size(), 1e9);
    int collisions = 0;
    for (int k = 0; k < 20 * 600 && !follower.reached(); ++k) {
      robot.command(follower.command(robot.pose()));
      if (robot.step(0.05, f.grid) == rgnav::StepOutcome::Collided) ++collisions;
      for (std::size_t i = 0; i < tour.visits.size(); ++i) {
        const WorldPoint g = tour.visits[i].goal;
        closest[i] = std::min(closest[i], std::hypot(robot.pose().x - g.x, robot.pose().y - g.y));
      }
    }
    CPPUNIT_ASSERT(follower.reached());
    CPPUNIT_ASSERT_EQUAL(0, collisions);
    for (const double d : closest) CPPUNIT_ASSERT(d < 0.5);
  }

  void badInputIsTypedError() {
    const Floor f = makeFloor();
    CPPUNIT_ASSERT_THROW(rgnav::planTour(f.grid, f.rooms, f.roomCount, {0.0, 5.0, 0.0}), rgnav::StartBlockedError);
    const std::vector<int> tooFew(f.rooms.begin() + 1, f.rooms.end());
    CPPUNIT_ASSERT_THROW(rgnav::planTour(f.grid, tooFew, f.roomCount, {1.0, 5.0, 0.0}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::planTour(f.grid, f.rooms, -1, {1.0, 5.0, 0.0}), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(TourPlannerTest);
