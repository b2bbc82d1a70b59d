// Tests the pure pursuit follower closed-loop with the simulated robot: it reaches the goal of a
// planned path through an L-shaped corridor without collisions, slows down before the goal,
// follows a path that returns to its start in order, stops at sharp corners instead of cutting
// them, and rejects bad input.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/grid/GridPlanner.h"
#include "core/nav/grid/PurePursuit.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "core/sim/scenarios/GridDrawing.h"

using rgnav::Cell;
using rgnav::DiffDriveRobot;
using rgnav::OccupancyGrid;
using rgnav::PurePursuit;
using rgnav::PurePursuitConfig;
using rgnav::WorldPoint;

namespace {

struct Drive {
  bool reached = false;
  int collisions = 0;
  double seconds = 0.0;
  double farthestX = -1e9;
};

// Runs follower and robot at 20 Hz for at most `limit` seconds.
Drive drive(PurePursuit& follower, DiffDriveRobot& robot, const OccupancyGrid& grid, double limit) {
  Drive d;
  const double dt = 0.05;
  while (!follower.reached() && d.seconds < limit) {
    robot.command(follower.command(robot.pose()));
    if (robot.step(dt, grid) == rgnav::StepOutcome::Collided) ++d.collisions;
    d.seconds += dt;
    d.farthestX = std::max(d.farthestX, robot.pose().x);
  }
  d.reached = follower.reached();
  return d;
}

double distance(const rgnav::Pose2D& p, WorldPoint q) { return std::hypot(p.x - q.x, p.y - q.y); }

}  // namespace

class PurePursuitTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PurePursuitTest);
  CPPUNIT_TEST(reachesGoalThroughLCorridor);
  CPPUNIT_TEST(slowsDownBeforeGoal);
  CPPUNIT_TEST(followsOutAndBackInOrder);
  CPPUNIT_TEST(stopsAtSharpCornersAndTurnsOnTheSpot);
  CPPUNIT_TEST(badInputIsTypedError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void reachesGoalThroughLCorridor() {
    OccupancyGrid grid(200, 200, 0.05, {0.0, 0.0}, Cell::Occupied);
    rgnav::fillRect(grid, {0.5, 1.0, 8.0, 2.2}, Cell::Free);  // 1.2 m wide corridor along x
    rgnav::fillRect(grid, {6.8, 1.0, 8.0, 9.0}, Cell::Free);  // and up along y
    const WorldPoint goal{7.4, 8.3};
    const auto path = rgnav::GridPlanner(grid).plan({1.1, 1.6}, goal);
    PurePursuit follower(PurePursuitConfig{}, path);
    DiffDriveRobot robot(rgnav::DiffDriveConfig{}, {1.1, 1.6, M_PI / 2});  // facing the wall
    const Drive d = drive(follower, robot, grid, 120.0);
    CPPUNIT_ASSERT(d.reached);
    CPPUNIT_ASSERT_EQUAL(0, d.collisions);
    CPPUNIT_ASSERT(distance(robot.pose(), goal) <= PurePursuitConfig{}.goalTolerance);
    CPPUNIT_ASSERT(d.seconds < 60.0);
    const auto stop = follower.command(robot.pose());
    CPPUNIT_ASSERT_EQUAL(0.0, stop.translational);
    CPPUNIT_ASSERT_EQUAL(0.0, stop.rotational);
  }

  // Full speed far from the goal, proportionally slower within the slowdown distance (measured
  // along the path plus the distance off it).
  void slowsDownBeforeGoal() {
    PurePursuitConfig config;
    PurePursuit follower(config, {{0.0, 0.0}, {5.0, 0.0}});
    for (double x = 0.0; x <= 4.0; x += 0.1) {
      CPPUNIT_ASSERT_DOUBLES_EQUAL(config.maxTranslationalVelocity,
                                   follower.command({x, 0.0, 0.0}).translational, 1e-12);
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.25, follower.command({4.5, 0.0, 0.0}).translational, 1e-9);
    const auto curve = follower.command({4.8, 0.05, 0.0});
    const double curvature = 2.0 * -0.05 / (0.2 * 0.2 + 0.05 * 0.05);  // 2 y / d^2
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.125, curve.translational, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(curvature * 0.125, curve.rotational, 1e-9);
    CPPUNIT_ASSERT(!follower.reached());
    follower.command({4.99, 0.0, 0.0});
    CPPUNIT_ASSERT(follower.reached());
  }

  void followsOutAndBackInOrder() {
    const OccupancyGrid grid(240, 120, 0.05, {-1.0, -3.0});
    PurePursuit follower(PurePursuitConfig{}, {{0.0, 0.0}, {4.0, 0.0}, {4.0, 1.0}, {0.0, 1.0}, {0.0, 0.0}});
    DiffDriveRobot robot(rgnav::DiffDriveConfig{}, {0.0, 0.0, 0.0});
    const Drive d = drive(follower, robot, grid, 120.0);
    CPPUNIT_ASSERT(d.reached);
    CPPUNIT_ASSERT(d.farthestX > 3.6);
    CPPUNIT_ASSERT(distance(robot.pose(), {0.0, 0.0}) <= 0.1);
  }

  // A square: the robot reaches every corner (it does not cut them) and turns there on the spot.
  void stopsAtSharpCornersAndTurnsOnTheSpot() {
    const OccupancyGrid grid(240, 240, 0.05, {-3.0, -3.0});
    const std::vector<WorldPoint> corners = {{0.0, 0.0}, {3.0, 0.0}, {3.0, 3.0}, {0.0, 3.0}, {0.0, 0.5}};
    PurePursuitConfig config;
    PurePursuit follower(config, corners);
    DiffDriveRobot robot(rgnav::DiffDriveConfig{}, {0.0, 0.0, 0.0});
    std::vector<double> closest(corners.size(), 1e9);
    double worstOffPath = 0.0;
    for (int k = 0; k < 20 * 120 && !follower.reached(); ++k) {
      robot.command(follower.command(robot.pose()));
      robot.step(0.05, grid);
      const rgnav::Pose2D p = robot.pose();
      for (std::size_t i = 0; i < corners.size(); ++i) closest[i] = std::min(closest[i], distance(p, corners[i]));
      // Distance to the square's outline (the path never leaves it by more than a few cm).
      const double toSides = std::min({std::abs(p.y), std::abs(p.x - 3.0), std::abs(p.y - 3.0), std::abs(p.x)});
      worstOffPath = std::max(worstOffPath, toSides);
    }
    CPPUNIT_ASSERT(follower.reached());
    for (const double d : closest) CPPUNIT_ASSERT(d <= config.goalTolerance + 1e-9);
    CPPUNIT_ASSERT(worstOffPath < 0.03);
    // Facing away from the path: a turn on the spot towards it.
    PurePursuit fresh(config, corners);
    const auto turn = fresh.command({0.0, 0.0, M_PI / 2});
    CPPUNIT_ASSERT_EQUAL(0.0, turn.translational);
    CPPUNIT_ASSERT(turn.rotational < 0.0);
  }

  void badInputIsTypedError() {
    CPPUNIT_ASSERT_THROW(PurePursuit(PurePursuitConfig{}, {}), rgnav::InvalidArgumentError);
    PurePursuitConfig bad;
    bad.lookahead = 0.0;
    CPPUNIT_ASSERT_THROW(PurePursuit(bad, {{0.0, 0.0}}), rgnav::ConfigError);
    bad = PurePursuitConfig{};
    bad.minApproachVelocity = 2.0 * bad.maxTranslationalVelocity;
    CPPUNIT_ASSERT_THROW(PurePursuit(bad, {{0.0, 0.0}}), rgnav::ConfigError);
    bad = PurePursuitConfig{};
    bad.alignedBearing = 2.0 * bad.rotateInPlaceBearing;
    CPPUNIT_ASSERT_THROW(PurePursuit(bad, {{0.0, 0.0}}), rgnav::ConfigError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(PurePursuitTest);
