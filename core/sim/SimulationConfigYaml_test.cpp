// Tests the simulator's YAML keys added for motion: the robot footprint (disk or rectangle, one
// way of giving it, strict keys), the shipped Jackal configuration (BARN's robot: rectangle,
// limits, 720 beams over 270 degrees) and that the Jackal fits at a BARN world's task start.
#include <cppunit/extensions/HelperMacros.h>

#include "core/logs/LogTestFiles.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/Simulation.h"
#include "core/sim/SimulationConfigYaml.h"

using namespace rgnav;

class SimulationConfigYamlTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SimulationConfigYamlTest);
  CPPUNIT_TEST(footprintKeys);
  CPPUNIT_TEST(badFootprintsAreConfigErrors);
  CPPUNIT_TEST(jackalConfiguration);
  CPPUNIT_TEST(jackalStartsAtTheBarnTaskStart);
  CPPUNIT_TEST_SUITE_END();

 public:
  void footprintKeys() {
    CPPUNIT_ASSERT(SimulationConfig{}.robot.footprint.shape == Footprint::Shape::Disk);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.25, SimulationConfig{}.robot.footprint.radius, 1e-12);
    const Footprint disk = parseSimulationConfig("robot: {radius_m: 0.3}\n").robot.footprint;
    CPPUNIT_ASSERT(disk.shape == Footprint::Shape::Disk);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.3, disk.radius, 1e-12);
    const Footprint disk2 = parseSimulationConfig("robot: {footprint: {shape: disk, radius_m: 0.2}}\n").robot.footprint;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2, disk2.radius, 1e-12);
    const Footprint rect = parseSimulationConfig(
        "robot: {footprint: {shape: rectangle, length_m: 0.6, width_m: 0.4, center_offset_m: 0.1}}\n").robot.footprint;
    CPPUNIT_ASSERT(rect.shape == Footprint::Shape::Rectangle);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.6, rect.length, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.4, rect.width, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, rect.centerOffset, 1e-12);
    const Footprint centred =
        parseSimulationConfig("robot: {footprint: {shape: rectangle, length_m: 0.6, width_m: 0.4}}\n").robot.footprint;
    CPPUNIT_ASSERT_EQUAL(0.0, centred.centerOffset);
  }

  void badFootprintsAreConfigErrors() {
    const auto fails = [](const std::string& yaml, const std::string& mention) {
      try {
        parseSimulationConfig(yaml);
        CPPUNIT_FAIL("no error for " + yaml);
      } catch (const ConfigError& e) {
        CPPUNIT_ASSERT_MESSAGE(e.what(), std::string(e.what()).find(mention) != std::string::npos);
      }
    };
    fails("robot: {radius_m: 0.3, footprint: {shape: disk, radius_m: 0.2}}\n", "robot");
    fails("robot: {footprint: {shape: triangle}}\n", "shape");
    fails("robot: {footprint: {radius_m: 0.2}}\n", "shape");
    fails("robot: {footprint: {shape: disk, radius_m: 0.2, width_m: 0.3}}\n", "footprint");
    fails("robot: {footprint: {shape: rectangle, length_m: 0.6, width_m: 0.4, radius_m: 0.2}}\n", "footprint");
    fails("robot: {footprint: {shape: rectangle, length_m: 0.6}}\n", "width_m");
    fails("robot: {footprint: {shape: rectangle, length_m: 0.6, width_m: 0}}\n", "width");
    fails("robot: {footprint: {shape: rectangle, length_m: 0.6, width_m: 0.4, colour: red}}\n", "colour");
    fails("robot: {radius_m: -1}\n", "radius");
  }

  void jackalConfiguration() {
    const SimulationConfig jackal = loadSimulationConfig("config/sim/jackal.yaml");
    CPPUNIT_ASSERT(jackal.robot.footprint.shape == Footprint::Shape::Rectangle);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.508, jackal.robot.footprint.length, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.430, jackal.robot.footprint.width, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, jackal.robot.maxTranslationalVelocity, 1e-12);
    CPPUNIT_ASSERT_EQUAL(std::size_t(720), LaserModel(jackal.laser).beamCount());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(270.0, jackal.laser.fieldOfView * 180.0 / M_PI, 1e-9);
    CPPUNIT_ASSERT_EQUAL(0.0, jackal.odometry.alpha1);
  }

  void jackalStartsAtTheBarnTaskStart() {
    const SimulationConfig jackal = loadSimulationConfig("config/sim/jackal.yaml");
    const LoadedWorld world = loadWorld(rgnav::testing::sharedData("planning/barn/barn_000.yaml"));
    CPPUNIT_ASSERT(world.task.has_value());
    Simulation simulation(world.grid, jackal, world.task->start);
    const SimulationStep first = simulation.step();
    CPPUNIT_ASSERT(first.truePose == world.task->start);
    CPPUNIT_ASSERT(!first.scan);
    CPPUNIT_ASSERT_EQUAL(std::size_t(720), simulation.step().scan->ranges.size());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(SimulationConfigYamlTest);
