// Tests people in the simulation: a person walking into a robot that stands still is a bump, not
// a collision; people the driving robot meets are the robot's collisions (those who walk into it
// from behind or the side are bumps: people/ContactBlame_test.cpp); neither ever overlaps
// the other; the laser sees the people; the people keys of the sim YAML; and SimulatedRobot
// passing people and both counters on.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/sim/SimulatedRobot.h"
#include "core/sim/SimulationConfigYaml.h"

using namespace rgnav;

namespace {

// A corridor 1 m wide (y 0..1) and 12 m long in 0.2 m walls: nobody fits past the robot.
OccupancyGrid corridor() {
  OccupancyGrid grid(248, 28, 0.05, {-0.2, -0.2}, Cell::Occupied);
  for (int row = 4; row < 24; ++row)
    for (int col = 4; col < 244; ++col) grid.set({col, row}, Cell::Free);
  return grid;
}

// An open 10 x 10 m room in 0.2 m walls.
OccupancyGrid room() {
  OccupancyGrid grid(208, 208, 0.05, {-0.2, -0.2}, Cell::Occupied);
  for (int row = 4; row < 204; ++row)
    for (int col = 4; col < 204; ++col) grid.set({col, row}, Cell::Free);
  return grid;
}

SimulationConfig withPeople(int count, std::uint64_t seed) {
  SimulationConfig config;
  config.people.count = count;
  config.people.seed = seed;
  return config;
}

// Neither the robot nor any person overlaps the other.
void assertApart(const Simulation& simulation) {
  for (const Person& p : simulation.people())
    CPPUNIT_ASSERT(!simulation.config().robot.footprint.overlapsDisk(simulation.truePose(), p.position, p.radius));
}

}  // namespace

class SimulationPeopleTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SimulationPeopleTest);
  CPPUNIT_TEST(aPersonWalkingIntoAStandingRobotIsABump);
  CPPUNIT_TEST(peopleTheDrivingRobotMeetsAreItsCollisions);
  CPPUNIT_TEST(theLaserSeesThePeople);
  CPPUNIT_TEST(peopleKeys);
  CPPUNIT_TEST(simulatedRobotPassesPeopleAndCountersOn);
  CPPUNIT_TEST_SUITE_END();

 public:
  void aPersonWalkingIntoAStandingRobotIsABump() {
    const OccupancyGrid grid = corridor();
    Simulation simulation(grid, withPeople(3, 2), {6.0, 0.5, 0.0});
    int bumpedSteps = 0;
    for (int k = 0; k < 2400; ++k) {
      const SimulationStep step = simulation.step();
      bumpedSteps += step.bumped;
      CPPUNIT_ASSERT(!step.collided);
      assertApart(simulation);
    }
    CPPUNIT_ASSERT(simulation.truePose() == (Pose2D{6.0, 0.5, 0.0}));
    CPPUNIT_ASSERT(simulation.personBumps() > 0);
    CPPUNIT_ASSERT(bumpedSteps > 0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), simulation.robotCollisions());
  }

  void peopleTheDrivingRobotMeetsAreItsCollisions() {
    const OccupancyGrid grid = corridor();
    Simulation simulation(grid, withPeople(3, 2), {6.0, 0.5, 0.0});
    double direction = 1.0;
    int collidedSteps = 0;
    for (int k = 0; k < 2400; ++k) {
      // Up and down the corridor, commanded again after every stop.
      if (simulation.truePose().x > 10.0) direction = -1.0;
      if (simulation.truePose().x < 2.0) direction = 1.0;
      simulation.command({0.6 * direction, 0.0});
      collidedSteps += simulation.step().collided;
      assertApart(simulation);
    }
    CPPUNIT_ASSERT(simulation.robotCollisions() > 0);
    CPPUNIT_ASSERT_EQUAL(simulation.robotCollisions(), std::uint64_t(collidedSteps));
  }

  void theLaserSeesThePeople() {
    const OccupancyGrid grid = room();
    SimulationConfig config = withPeople(1, 3);
    config.laser.fieldOfView = 2.0 * M_PI;  // all round, no noise
    config.laser.rangeNoiseSigma = 0.0;
    Simulation simulation(grid, config, {5.0, 5.0, 0.0});
    int scans = 0;
    for (int k = 0; k < 600; ++k) {
      const SimulationStep step = simulation.step();
      if (!step.scan) continue;
      ++scans;
      const Person& person = simulation.people().front();
      const double dx = person.position.x - 5.0, dy = person.position.y - 5.0;
      const double bearing = std::atan2(dy, dx);
      const auto beam = static_cast<std::size_t>(std::lround((bearing - step.scan->startAngle) / step.scan->angleIncrement));
      // The beam nearest the person's centre ends on its near side.
      const double expected = std::hypot(dx, dy) - person.radius;
      CPPUNIT_ASSERT_DOUBLES_EQUAL(expected, step.scan->ranges[beam], 0.01);
    }
    CPPUNIT_ASSERT_EQUAL(300, scans);
  }

  void peopleKeys() {
    const SimulationConfig config = parseSimulationConfig(
        "people: {count: 8, radius_m: 0.3, min_speed_mps: 0.6, max_speed_mps: 1.0, seed: 4}\n");
    CPPUNIT_ASSERT_EQUAL(8, config.people.count);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.3, config.people.radius, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.6, config.people.minSpeed, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, config.people.maxSpeed, 1e-12);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(4), config.people.seed.value_or(0));
    CPPUNIT_ASSERT(!parseSimulationConfig("people: {count: 2}\n").people.seed);
    CPPUNIT_ASSERT_EQUAL(0, SimulationConfig{}.people.count);
    CPPUNIT_ASSERT_THROW(parseSimulationConfig("people: {cuont: 2}\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(parseSimulationConfig("people: {count: -2}\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(parseSimulationConfig("people: {min_speed_mps: 2.0}\n"), ConfigError);
  }

  void simulatedRobotPassesPeopleAndCountersOn() {
    SimulatedRobotOptions options;
    options.clock = SimClock::LockStep;
    SimulatedRobot robot({room(), std::nullopt, std::nullopt}, withPeople(2, 1), {5.0, 5.0, 0.0}, std::nullopt,
                         nullptr, options);
    const std::vector<Person> before = robot.people();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), before.size());
    for (int k = 0; k < 5; ++k) robot.step();
    CPPUNIT_ASSERT(robot.people().front().position.x != before.front().position.x ||
                   robot.people().front().position.y != before.front().position.y);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), robot.robotCollisions());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), robot.personBumps());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(SimulationPeopleTest);
