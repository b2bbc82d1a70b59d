// Killing the LowLevelDrive module mid-chain (issue "Motion": "killing the LLD: the simulator's
// Base commands lapse after 0.5 s and the robot stops; the watchdog restarts it"): the drive
// follows a long straight down the office's main hallway; once it has passed 2 m it is killed
// (SIGKILL). The simulator's ground truth shows the robot at rest within the command timeout
// (0.5 s) plus braking from the speed it had at the kill (at the simulated base's deceleration,
// 0.5 m/s^2), measured on the simulation's clock (the scans' stamps), never on the wall clock.
// The watchdog restarts the drive, which comes back idle (commands nothing) and drives a new
// chain from where the robot stands.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include <cmath>
#include <cstdio>

#include "tests/integration/MotionSet.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

constexpr double kCommandTimeoutS = 0.5;       // SimulatedRobotOptions::commandTimeoutSeconds
constexpr double kBaseDecelerationMps2 = 0.5;  // the simulated robot's max_acceleration_mps2
constexpr double kMarginS = 0.2;               // a simulation step, a scan interval and rounding

bool samePose(const Pose2D& a, const Pose2D& b) {
  return std::abs(a.x - b.x) < 1e-9 && std::abs(a.y - b.y) < 1e-9 && std::abs(normalizeAngle(a.theta - b.theta)) < 1e-9;
}

}  // namespace

class LowLevelDriveKillTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LowLevelDriveKillTest);
  CPPUNIT_TEST(robotStopsWhenTheDriveIsKilled);
  CPPUNIT_TEST_SUITE_END();

 public:
  void robotStopsWhenTheDriveIsKilled() {
    MotionSet set(kFastBackoff);
    TestCluster& cluster = set.cluster();
    cluster.start();
    LowLevelDriveClient& drive = set.drive();
    const DriveChain chain = straightThenArc(1, set.latestOdometry(), 7.0, 0.3, 0.3, 0.2);
    drive.setChain(chain);
    waitUntil([&] { return drive.driveStatus().drive.progress > 2.0; }, "the drive to pass 2 m",
              std::chrono::seconds(60), std::chrono::milliseconds(20));

    const ModuleProcessInfo before = cluster.describe("LowLevelDrive");
    CPPUNIT_ASSERT_EQUAL(0, ::kill(static_cast<pid_t>(before.pid), SIGKILL));
    const OdometryReading atKill = set.latestOdometry();  // on the simulation's clock, after the last command
    CPPUNIT_ASSERT(atKill.translationalVelocity > 0.3);   // killed while driving

    // At rest: the true pose of the scans stays the same over 0.5 s of simulated time.
    TrueState rest = set.latestTruth();
    waitUntil(
        [&] {
          const TrueState now = set.latestTruth();
          if (!samePose(now.pose, rest.pose)) rest = now;
          return now.stamp - rest.stamp >= 0.5;
        },
        "the robot to come to rest", std::chrono::seconds(30), std::chrono::milliseconds(20));
    // The first scan at rest, however late the polling saw it.
    for (TrueState earlier = set.truthAt(rest.scan - 1); samePose(earlier.pose, rest.pose);
         earlier = set.truthAt(rest.scan - 1))
      rest = earlier;
    const double stoppedAfterS = rest.stamp - atKill.stamp;
    const double boundS = kCommandTimeoutS + atKill.translationalVelocity / kBaseDecelerationMps2 + kMarginS;
    const double rolledM = std::hypot(rest.pose.x - atKill.pose.x, rest.pose.y - atKill.pose.y);
    CPPUNIT_ASSERT(rest.pose.x < chain.chain.end().x - 1.0);  // it stopped, it did not finish the chain

    const ModuleProcessInfo after = cluster.waitFor("LowLevelDrive", runningAgainAfter(before.pid), "a restart");
    CPPUNIT_ASSERT(after.restarts > before.restarts);
    const DriveReport restarted = drive.driveStatus();
    CPPUNIT_ASSERT(restarted.drive.state == DriveState::Idle);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), restarted.drive.chainId);
    CPPUNIT_ASSERT(samePose(rest.pose, set.latestTruth().pose));  // the restarted drive commands nothing

    const DriveChain resumed = straightThenArc(1, set.latestOdometry(), 1.0, 0.3, -0.3, 0.3);
    drive.setChain(resumed);
    waitUntil([&] { return drive.driveStatus().drive.chainFinished; }, "the restarted drive to finish a chain",
              std::chrono::seconds(60), std::chrono::milliseconds(50));
    const Pose2D end = resumed.chain.end();
    const TrueState finished = set.latestTruth();
    const double endErrorM = std::hypot(finished.pose.x - end.x, finished.pose.y - end.y);
    std::printf("\nLowLevelDrive pid %lld killed at %.2f m/s: robot at rest %.2f s (simulated) later (bound %.2f s), "
                "%.2f m on; restarted as pid %lld, drove a new chain to %.4f m of its end\n",
                static_cast<long long>(before.pid), atKill.translationalVelocity, stoppedAfterS, boundS, rolledM,
                static_cast<long long>(after.pid), endErrorM);
    CPPUNIT_ASSERT(stoppedAfterS <= boundS);
    CPPUNIT_ASSERT(endErrorM < 0.05);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LowLevelDriveKillTest);
