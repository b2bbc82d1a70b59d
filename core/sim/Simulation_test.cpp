// Tests the simulation glue: determinism for a seed (byte-identical CARMEN logs), different logs
// for different seeds, collisions counted, scan poses kept, configuration files read strictly,
// and a whole room tour in a small two-room world.
#include <cppunit/extensions/HelperMacros.h>

#include <limits>

#include <sstream>

#include "core/sim/GroundTruthTour.h"
#include "core/sim/SimulatedRobot.h"
#include "core/sim/SimulationConfigYaml.h"
#include "core/sim/StartPose.h"
#include "core/sim/TourRun.h"
#include "core/sim/motion/CarmenLogWriter.h"

using namespace rgnav;

namespace {

// A 10 m x 6 m box with a wall at x = 5 m and a 1 m door in it: rooms 0 (left) and 1 (right).
LoadedWorld twoRooms() {
  OccupancyGrid grid(200, 120, 0.05);
  GroundTruth truth{200, 120, 0.05, {}, std::vector<int>(200 * 120, -1), 2, {}};
  for (int row = 0; row < 120; ++row)
    for (int col = 0; col < 200; ++col) {
      const bool border = row < 2 || row >= 118 || col < 2 || col >= 198;
      const bool wall = col >= 98 && col < 102 && !(row >= 50 && row < 70);
      if (border || wall) grid.set({col, row}, Cell::Occupied);
      else if (col < 98 || col >= 102) truth.labels[static_cast<std::size_t>(row * 200 + col)] = col < 98 ? 0 : 1;
    }
  truth.doors.push_back(DoorLine{{5.0, 2.5}, {5.0, 3.5}, 0, 1});
  return {std::move(grid), std::move(truth), std::nullopt};
}

// The CARMEN log of `steps` steps driving a fixed arc.
std::string drivenLog(const OccupancyGrid& grid, std::uint64_t seed, int steps) {
  SimulationConfig config;
  config.seed = seed;
  Simulation simulation(grid, config, {2.0, 3.0, 0.0});
  simulation.command({0.3, 0.1});
  std::ostringstream out;
  CarmenLogWriter writer(out);
  for (int i = 0; i < steps; ++i) {
    const SimulationStep step = simulation.step();
    writer.write(step.odometry);
    if (step.scan) writer.write(*step.scan);
  }
  return out.str();
}

}  // namespace

class SimulationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SimulationTest);
  CPPUNIT_TEST(sameSeedGivesByteIdenticalLogs);
  CPPUNIT_TEST(otherSeedGivesOtherLogs);
  CPPUNIT_TEST(scansComeEveryStepsPerScanWithTheirTruePoses);
  CPPUNIT_TEST(drivingIntoAWallIsACollision);
  CPPUNIT_TEST(startInsideAWallIsRefused);
  CPPUNIT_TEST(tourVisitsBothRoomsWithoutCollision);
  CPPUNIT_TEST(lockStepAdvancesOnlyWhenAsked);
  CPPUNIT_TEST(configFilesAreReadStrictly);
  CPPUNIT_TEST_SUITE_END();

 public:
  void sameSeedGivesByteIdenticalLogs() {
    const LoadedWorld world = twoRooms();
    const std::string a = drivenLog(world.grid, 7, 120);
    CPPUNIT_ASSERT(a.size() > 10000);
    CPPUNIT_ASSERT(a == drivenLog(world.grid, 7, 120));
  }
  void otherSeedGivesOtherLogs() {
    const LoadedWorld world = twoRooms();
    CPPUNIT_ASSERT(drivenLog(world.grid, 7, 120) != drivenLog(world.grid, 8, 120));
  }
  void scansComeEveryStepsPerScanWithTheirTruePoses() {
    const LoadedWorld world = twoRooms();
    Simulation simulation(world.grid, SimulationConfig{}, {2.0, 3.0, 0.0});
    simulation.command({0.2, 0.0});
    int scans = 0;
    for (int i = 1; i <= 10; ++i) {
      const SimulationStep step = simulation.step();
      CPPUNIT_ASSERT_EQUAL(DataId(i), step.odometry.id);
      CPPUNIT_ASSERT_EQUAL(i % 2 == 0, step.scan.has_value());
      if (step.scan) {
        ++scans;
        CPPUNIT_ASSERT(simulation.truePoseOfScan(step.scan->id) == step.truePose);
        CPPUNIT_ASSERT_EQUAL(std::size_t(181), step.scan->ranges.size());
      }
    }
    CPPUNIT_ASSERT_EQUAL(5, scans);
    CPPUNIT_ASSERT_THROW(simulation.truePoseOfScan(6), NotAvailableError);
  }
  void drivingIntoAWallIsACollision() {
    const LoadedWorld world = twoRooms();
    Simulation simulation(world.grid, SimulationConfig{}, {4.0, 1.0, 0.0});
    simulation.command({1.0, 0.0});
    for (int i = 0; i < 200; ++i) simulation.step();
    CPPUNIT_ASSERT(simulation.robotCollisions() > 0);
    CPPUNIT_ASSERT(simulation.truePose().x < 4.9 - 0.25 + 0.05);
  }
  void startInsideAWallIsRefused() {
    const LoadedWorld world = twoRooms();
    CPPUNIT_ASSERT_THROW(Simulation(world.grid, SimulationConfig{}, {5.0, 1.0, 0.0}), InvalidArgumentError);
  }
  void tourVisitsBothRoomsWithoutCollision() {
    const LoadedWorld world = twoRooms();
    const Pose2D start = openestPose(world.grid);
    Simulation simulation(world.grid, SimulationConfig{}, start);
    TourDriver driver(planTour(world.grid, *world.truth, start), PurePursuitConfig{});
    std::size_t steps = 0;
    const TourRunResult run = runTour(simulation, driver, *world.truth, [&](const SimulationStep&) { ++steps; }, 600.0);
    CPPUNIT_ASSERT(run.finished);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), run.roomsVisited.size());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), run.collisions);
    CPPUNIT_ASSERT(steps > 0 && run.scans > 0);
  }
  void lockStepAdvancesOnlyWhenAsked() {
    SimulatedRobotOptions options;
    options.clock = SimClock::LockStep;
    SimulatedRobot robot(twoRooms(), SimulationConfig{}, {2.0, 3.0, 0.0}, std::nullopt, nullptr, options);
    CPPUNIT_ASSERT_EQUAL(DataId(0), robot.latestScanId());
    const auto batch = robot.scansSince(0, 10, "test");
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), batch.records.size());
    CPPUNIT_ASSERT_EQUAL(DataId(2), robot.latestOdometryId());
    CPPUNIT_ASSERT_EQUAL(DataId(2), robot.scansSince(1, 10, "test").records.front().id);
    // A caller ahead of the simulation (even at 2^64-2, where afterId + 1 does not wrap) pulls
    // one scan per call, never the rest of the run.
    CPPUNIT_ASSERT(robot.scansSince(1000, 10, "test").records.empty());
    CPPUNIT_ASSERT(robot.scansSince(std::numeric_limits<DataId>::max() - 1, 10, "test").records.empty());
    CPPUNIT_ASSERT_EQUAL(DataId(4), robot.latestScanId());
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), robot.scansSince(0, 10, "test").records.size());  // behind: no step
    CPPUNIT_ASSERT_EQUAL(DataId(4), robot.latestScanId());
    robot.setVelocity(0.5, 0.0);
    CPPUNIT_ASSERT_THROW(robot.setVelocity(NAN, 0.0), InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(-1, robot.roomAt({-5.0, 0.0}));
    CPPUNIT_ASSERT_EQUAL(0, robot.roomAt({1.0, 1.0}));
  }
  void configFilesAreReadStrictly() {
    const SimulationConfig config = parseSimulationConfig("seed: 9\nlaser: {resolution_deg: 0.5, max_range_m: 20}\n");
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(9), config.seed);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 360.0, config.laser.angularResolution, 1e-12);
    CPPUNIT_ASSERT_THROW(parseSimulationConfig("laser: {max_rnage_m: 20}\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(parseSimulationConfig("step_s: -1\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(loadSimulationConfig("/nonexistent/sim.yaml"), FileError);
    const SimulationConfig shipped = loadSimulationConfig("config/sim/default.yaml");
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.40, shipped.laser.mountingHeight, 1e-12);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(SimulationTest);
