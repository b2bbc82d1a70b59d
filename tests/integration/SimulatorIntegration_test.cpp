// The simulator through the real server set: in lock-step on a tour, a consumer gets exactly the
// scans an in-process simulation with the same seed makes (the servers add nothing and lose
// nothing), with ground truth per scan; in real time with velocity commands, the robot moves
// while commanded and stops when the commands lapse; a BARN task world starts the Jackal at the
// task's start, and the ground truth and health report the walking people and both counters.
#include <cppunit/extensions/HelperMacros.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <thread>

#include "clientlibs/base/BaseClient.h"
#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "core/config/ShippedConfig.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/TourRun.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {
std::string freiburg52() {
  return TestCluster::shared("data/floorplans/ipa_room_segmentation/test_maps/Freiburg52_scan_furnitures.png");
}

std::string barn000() { return TestCluster::shared("data/planning/barn/barn_000.yaml"); }

std::vector<std::string> simulatorCommand(const std::vector<std::string>& extra) {
  std::vector<std::string> command{TestCluster::program("rgnav-sim"), "--world", freiburg52(), "--seed", "5"};
  command.insert(command.end(), extra.begin(), extra.end());
  return command;
}
}  // namespace

class SimulatorIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SimulatorIntegrationTest);
  CPPUNIT_TEST(testLockStepTourServesExactlyTheInProcessScans);
  CPPUNIT_TEST(testVelocityCommandsDriveAndLapse);
  CPPUNIT_TEST(testTaskWorldWithPeople);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testLockStepTourServesExactlyTheInProcessScans() {
    TestCluster cluster({{"Simulator", simulatorCommand({"--clock", "lockstep", "--tour"}), {"Laser", "Base", "GroundTruth"}}});
    cluster.start();
    LaserClient laser(cluster.clientSettings());
    const std::vector<LaserScan> served = readAllScans(laser, 200);

    const LoadedWorld world = loadWorld(freiburg52());
    SimulationConfig config;
    config.seed = 5;
    std::vector<LaserScan> local;
    driveRoomTour(world.grid, *world.truth, config, [&](const SimulationStep& s) { if (s.scan) local.push_back(*s.scan); });

    CPPUNIT_ASSERT(served.size() > 1000);
    CPPUNIT_ASSERT_EQUAL(local.size(), served.size());
    for (std::size_t i = 0; i < local.size(); i += 97) {
      CPPUNIT_ASSERT_EQUAL(local[i].id, served[i].id);
      CPPUNIT_ASSERT(local[i].ranges == served[i].ranges);
    }
    GroundTruthClient truth(cluster.clientSettings());
    CPPUNIT_ASSERT_EQUAL(static_cast<unsigned>(world.truth->roomCount), truth.roomCount());
    CPPUNIT_ASSERT_EQUAL(world.truth->doors.size(), truth.doorLines().size());
    const Pose2D pose = truth.truePose(served[500].id);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(served[500].sensorPose.x, pose.x, 0.5);
    CPPUNIT_ASSERT(truth.roomAt(pose.x, pose.y) >= -1);
    // A NaN or infinite point is refused naming the coordinate (it was undefined behaviour).
    try {
      truth.roomAt(std::nan(""), pose.y);
      CPPUNIT_FAIL("roomAt(NaN) answered");
    } catch (const BadArgumentError& e) {
      CPPUNIT_ASSERT_EQUAL(std::string("x"), e.field());
    }
    CPPUNIT_ASSERT_THROW(truth.roomAt(pose.x, std::numeric_limits<double>::infinity()), BadArgumentError);
    CPPUNIT_ASSERT_THROW(truth.truePose(0), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(truth.truePose(10000000), NotAvailableError);
    BaseClient base(cluster.clientSettings());
    CPPUNIT_ASSERT_THROW(base.setVelocity(0.2, 0.0), NotSupportedError);
  }

  void testVelocityCommandsDriveAndLapse() {
    TestCluster cluster({{"Simulator", simulatorCommand({"--clock", "realtime"}), {"Laser", "Base", "GroundTruth"}}});
    cluster.start();
    BaseClient base(cluster.clientSettings());
    auto latestPose = [&] {
      const auto batch = base.odometrySince(std::max<DataId>(base.latestOdometryId(), 1) - 1, 1);
      return batch.records.back().pose;
    };
    const Pose2D before = latestPose();
    for (int i = 0; i < 20; ++i) {  // 1 s of commands at 20 Hz: the pace is the scenario
      base.setVelocity(0.0, 0.5);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    const auto lastCommand = std::chrono::steady_clock::now();
    const Pose2D turned = latestPose();
    CPPUNIT_ASSERT(std::abs(normalizeAngle(turned.theta - before.theta)) > 0.1);
    // Commands lapse after 0.5 s: then the robot comes to rest (two readings 0.25 s apart agree).
    std::optional<Pose2D> settled;
    waitUntil(
        [&] {
          const Pose2D now = latestPose();
          const bool lapsed = std::chrono::steady_clock::now() - lastCommand > std::chrono::milliseconds(500);
          const bool still = lapsed && settled && std::abs(normalizeAngle(now.theta - settled->theta)) < 1e-9;
          settled = now;
          return still;
        },
        "the robot to stop after its commands lapsed", std::chrono::seconds(10), std::chrono::milliseconds(250));
    // Waiting out half a second more is the scenario: it proves the robot stays at rest.
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(settled->theta, latestPose().theta, 1e-9);
    CPPUNIT_ASSERT_THROW(base.setVelocity(NAN, 0.0), InvalidArgumentError);
  }

  void testTaskWorldWithPeople() {
    TestCluster cluster({{"Simulator",
                          {TestCluster::program("rgnav-sim"), "--world", barn000(), "--config", shippedConfigFile("sim/jackal.yaml"),
                           "--clock", "lockstep", "--people", "2"},
                          {"Laser", "Base", "GroundTruth"}}});
    cluster.start();
    LaserClient laser(cluster.clientSettings());
    const auto batch = laser.scansSince(0, 10);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), batch.records.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(720), batch.records.front().ranges.size());
    GroundTruthClient truth(cluster.clientSettings());
    const LoadedWorld world = loadWorld(barn000());
    const Pose2D start = truth.truePose(batch.records.front().id);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(world.task->start.x, start.x, 1e-9);  // the robot has not moved
    CPPUNIT_ASSERT_DOUBLES_EQUAL(world.task->start.y, start.y, 1e-9);
    const std::vector<Person> people = truth.people();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), people.size());
    for (const Person& p : people) CPPUNIT_ASSERT_DOUBLES_EQUAL(0.25, p.radius, 1e-12);
    const ModuleStatusInfo status = laser.status();
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), status.counters.at("robot_collisions"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), status.counters.at("person_bumps"));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(SimulatorIntegrationTest);
