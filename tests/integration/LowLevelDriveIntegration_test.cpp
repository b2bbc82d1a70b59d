// The LowLevelDrive module through the real server set (issue "Motion"): the simulator in real
// time following velocity commands and the drive on its Base. A chain sent through the client
// library (2 m straight, a clothoid into a left arc of 2 m radius) is driven to its end: the
// simulator's ground truth ends within 5 cm and 3 degrees of the chain's end and stays there. The
// same chain sent again (a retry) changes nothing; another chain under the same ID, one with an
// ID not above the last and one the limits cannot drive are refused naming "chain". Beside the
// demo's tour, which refuses velocity commands, the drive stands by idle without an error.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <cstdio>

#include "tests/integration/MotionSet.h"

using namespace rgnav;
using namespace rgnav::testing;

class LowLevelDriveIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LowLevelDriveIntegrationTest);
  CPPUNIT_TEST(drivesAChainToItsEnd);
  CPPUNIT_TEST(standsByBesideATour);
  CPPUNIT_TEST_SUITE_END();

 public:
  void drivesAChainToItsEnd() {
    MotionSet set;
    set.cluster().start();
    LowLevelDriveClient& drive = set.drive();
    const DriveReport idle = drive.driveStatus();
    CPPUNIT_ASSERT(idle.drive.state == DriveState::Idle);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), idle.commandsSent);  // an idle drive commands nothing
    CPPUNIT_ASSERT_EQUAL(MotionLimits{}.maxVelocity, drive.limits().maxVelocity);

    const DriveChain chain = straightThenArc(1, set.latestOdometry(), 2.0, 0.5, 0.5, 0.8);
    drive.setChain(chain);
    waitUntil([&] { return drive.driveStatus().drive.chainFinished; }, "the drive to finish its chain",
              std::chrono::seconds(60), std::chrono::milliseconds(50));
    const DriveReport done = drive.driveStatus();
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(1), done.drive.chainId);
    CPPUNIT_ASSERT(done.commandsSent > 0);

    // It stays there: two scans 0.3 s of simulated time apart see the robot within 2 mm (a robot
    // driving on at even 0.05 m/s would be 15 mm on).
    TrueState first = set.latestTruth();
    waitUntil([&] { return set.latestTruth().stamp > first.stamp + 0.3; }, "the simulation to go on");
    const TrueState still = set.latestTruth();
    const Pose2D end = chain.chain.end();
    const double positionError = std::hypot(still.pose.x - end.x, still.pose.y - end.y);
    const double yawErrorDeg = std::abs(normalizeAngle(still.pose.theta - end.theta)) * 180.0 / M_PI;
    std::printf("\nchain of %.2f m driven: true end %.4f m / %.2f deg from the chain's end, lateral error %.4f m, "
                "%llu commands, loop period p99 %.1f ms\n",
                chain.chain.length(), positionError, yawErrorDeg, done.drive.lateralError,
                static_cast<unsigned long long>(done.commandsSent), done.loopPeriodP99Seconds * 1000.0);
    CPPUNIT_ASSERT(positionError < 0.05);
    CPPUNIT_ASSERT(yawErrorDeg < 3.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(first.pose.x, still.pose.x, 0.002);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(first.pose.y, still.pose.y, 0.002);

    // A retry of the chain accepted last changes nothing: it is not driven again.
    drive.setChain(chain);
    CPPUNIT_ASSERT(drive.driveStatus().drive.chainFinished);
    expectRefused(drive, straightThenArc(1, set.latestOdometry(), 1.0, 0.5, 0.5, 0.8));  // same ID, other chain
    DriveChain tooFast = straightThenArc(2, set.latestOdometry(), 1.0, 0.5, 0.5, 0.8);
    tooFast.startSpeed = 5.0;  // above the limits, and it could not brake within the chain
    expectRefused(drive, tooFast);
    drive.setChain(straightThenArc(5, set.latestOdometry(), 0.3, 0.3, -0.5, 0.3));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(5), drive.driveStatus().drive.chainId);
    expectRefused(drive, straightThenArc(4, set.latestOdometry(), 1.0, 0.5, 0.5, 0.8));  // not above the last
  }

  // As in the demo set: the tour drives, the drive stands by idle, commands nothing and reports no
  // error; a chain sent there is refused by the Base, which the drive reports once as its error.
  void standsByBesideATour() {
    MotionSet set("", SimulatorDriving::Tour);
    set.cluster().start();
    advanceTour(set.laser(), 50);  // 5 s of the tour
    LowLevelDriveClient& drive = set.drive();
    waitUntil([&] { return drive.status().counters.at("loop_ticks") > 20; }, "the drive's loop to tick");
    const ModuleStatusInfo standingBy = drive.status();
    CPPUNIT_ASSERT_EQUAL(std::string(), standingBy.lastError);
    CPPUNIT_ASSERT(standingBy.state == ModuleRunState::Running);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), standingBy.counters.at("commands_sent"));
    CPPUNIT_ASSERT(drive.driveStatus().drive.state == DriveState::Idle);

    drive.setChain(straightThenArc(1, set.latestOdometry(), 1.0, 0.5, 0.5, 0.8));
    waitUntil(
        [&] {
          advanceTour(set.laser(), 1);  // the drive sees new odometry, tracks and commands
          return drive.status().lastError.find("base_commands") == 0;
        },
        "the refused commands reported");
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), drive.driveStatus().commandsSent);
  }

 private:
  // The lock-step simulation goes on by `count` scans (a consumer that has every scan paces it).
  static void advanceTour(LaserClient& laser, DataId count) {
    DataId after = laser.latestId();
    const DataId until = after + count;
    while (after < until) {
      const DataBatch<LaserScan> got = laser.scansSince(after, 10);
      if (!got.records.empty()) after = got.records.back().id;
    }
  }

  static void expectRefused(LowLevelDriveClient& drive, const DriveChain& chain) {
    try {
      drive.setChain(chain);
      CPPUNIT_FAIL("chain " + std::to_string(chain.id) + " was accepted");
    } catch (const BadArgumentError& e) {
      CPPUNIT_ASSERT_EQUAL(std::string("chain"), e.field());
    }
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LowLevelDriveIntegrationTest);
