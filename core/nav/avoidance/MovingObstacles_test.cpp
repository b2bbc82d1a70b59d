// Tests the laser obstacle grid's moving layer on the simulated office with 8 walking people: the
// robot drives up and down the main hallway (odometry noise on), and at every scan each person
// the laser sees within 4 m ahead must mostly show moving cells on it (recall; nearly every one
// walking towards the robot, most of the others: people walking away show only cells they hid
// before and are followed from where they were seen moving), while moving cells away from every
// person (walls, door jambs, corners) stay few (precision).
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <cstdio>

#include "core/nav/avoidance/LaserObstacleMap.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/Simulation.h"
#include "core/sim/SimulationConfigYaml.h"

using namespace rgnav;

class MovingObstaclesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(MovingObstaclesTest);
  CPPUNIT_TEST(walkingPeopleAreMovingAndWallsAreNot);
  CPPUNIT_TEST_SUITE_END();

 public:
  void walkingPeopleAreMovingAndWallsAreNot() {
    const LoadedWorld world = loadWorld("config/worlds/office.yaml");
    SimulationConfig config = loadSimulationConfig("config/sim/default.yaml");
    config.people.count = 8;
    Simulation sim(world.grid, config, {1.5, 7.0, 0.0});
    LaserObstacleMap map(LaserObstacleMapConfig{});
    int seen = 0, detected = 0, movingCells = 0, strayCells = 0, approaching = 0, approachingDetected = 0;
    double direction = 1.0;
    while (sim.time() < 120.0) {
      if (sim.truePose().x > 30.0) direction = -1.0;
      if (sim.truePose().x < 2.0) direction = 1.0;
      const double heading = direction > 0.0 ? 0.0 : M_PI;
      sim.command({0.6, 1.5 * normalizeAngle(heading - sim.truePose().theta) + 1.0 * (7.0 - sim.truePose().y) * direction});
      const SimulationStep step = sim.step();
      if (!step.scan) continue;
      map.add(*step.scan);
      if (sim.time() < 3.0) continue;
      const ObstacleGrid grid = map.grid();
      // The people in the odometry frame (the grid's).
      const Pose2D toOdometry = compose(step.odometry.pose, inverse(step.truePose));
      std::vector<WorldPoint> people;
      for (const Person& p : sim.people()) {
        const Pose2D at = compose(toOdometry, {p.position.x, p.position.y, 0.0});
        people.push_back({at.x, at.y});
        // Seen: within 4 m ahead, and the beam towards its centre ends on it.
        const Pose2D rel = between(step.truePose, {p.position.x, p.position.y, 0.0});
        const double range = std::hypot(rel.x, rel.y), bearing = std::atan2(rel.y, rel.x);
        if (range > 4.0 || std::abs(bearing) > M_PI / 2 - 0.05) continue;
        const auto beam = static_cast<std::size_t>(std::lround((bearing - step.scan->startAngle) / step.scan->angleIncrement));
        if (beam >= step.scan->ranges.size() || std::abs(step.scan->ranges[beam] - (range - p.radius)) > 0.1) continue;
        ++seen;
        bool found = false;
        for (int dr = -8; dr <= 8 && !found; ++dr)
          for (int dc = -8; dc <= 8 && !found; ++dc) {
            const auto c = grid.moving.cellOf({at.x + dc * 0.05, at.y + dr * 0.05});
            found = c && grid.moving.at(*c) == Cell::Occupied && std::hypot(dc * 0.05, dr * 0.05) < p.radius + 0.1;
          }
        detected += found;
        // Walking towards the robot (the people the robot must stop for).
        const double towards = -(p.velocity.x * (p.position.x - step.truePose.x) + p.velocity.y * (p.position.y - step.truePose.y)) / range;
        if (towards > 0.3) {
          ++approaching;
          approachingDetected += found;
        }
      }
      for (int row = 0; row < grid.moving.height(); ++row)
        for (int col = 0; col < grid.moving.width(); ++col) {
          if (grid.moving.at({col, row}) != Cell::Occupied) continue;
          ++movingCells;
          const WorldPoint c = grid.moving.center({col, row});
          bool nearPerson = false;
          for (const WorldPoint& p : people) nearPerson = nearPerson || std::hypot(c.x - p.x, c.y - p.y) < 0.6;
          strayCells += !nearPerson;
        }
    }
    const double recall = static_cast<double>(detected) / seen;
    const double stray = static_cast<double>(strayCells) / movingCells;
    std::printf("\nmoving layer: people seen=%d detected=%d recall=%.3f approaching=%d detected=%d moving cells=%d stray=%d (%.3f)\n", seen, detected,
                recall, approaching, approachingDetected, movingCells, strayCells, stray);
    CPPUNIT_ASSERT(approaching > 100);
    CPPUNIT_ASSERT(static_cast<double>(approachingDetected) / approaching > 0.95);
    CPPUNIT_ASSERT(recall > 0.75);
    CPPUNIT_ASSERT(stray < 0.02);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(MovingObstaclesTest);
