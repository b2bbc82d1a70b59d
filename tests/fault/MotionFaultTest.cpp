// rgnav-faulttest-motion: fault injection on motion (issue 27, `rgctl faulttest motion`): the crowd
// evaluation's run (tests/eval/crowd: the office with walking people, goals sent by driveTo) while
// the Low-Level Drive and the Collision Avoidance are SIGKILLed in turn (20 times by default, by
// the PID the watchdog reports, each while the robot drives, a seeded 3-8 s after the previous
// victim is back). After each kill the robot must not be driven blind: it must stand, or be
// commanded again by a restarted module, within what a dead module may leave behind:
//  - the Low-Level Drive killed: its last command holds until the Base's command timeout (0.5 s),
//    then the robot brakes: allowed 0.5 s + v / max deceleration;
//  - the Collision Avoidance killed: the drive finishes the last chain it was given, which ends at
//    a standstill the CAM checked: allowed the chain's remaining time at the kill + v / max
//    deceleration (the robot brakes behind its reference);
// each plus kToleranceS for the 10 Hz true-pose sampling. "Commanded again": the restarted drive
// sends velocity commands / the restarted CAM has sent chains (its health's chains_sent). Every goal must still be
// reached and the robot must not drive into anything. Lines: one per kill, the crowd line, last:
//   motion_faults: kills=… lld_kills=… cam_kills=… recovered=… max_overrun_s=… goals=… reached=…
//   robot_collisions=… result=PASS
// Exit code 0 only if every check held.
#include <signal.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <random>
#include <thread>

#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"
#include "clientlibs/lowleveldrive/LowLevelDriveClient.h"
#include "core/sim/SimulationConfigYaml.h"
#include "tests/eval/crowd/CrowdEvaluation.h"
#include "tests/eval/crowd/TruePoseProbe.h"
#include "tests/fault/FaultSchedule.h"
#include "tests/support/cluster/Interruption.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kCommandTimeoutS = 0.5;   // the simulator's Base: a command holds this long
constexpr double kToleranceS = 0.3;        // true poses come at 10 Hz; a speed needs two
constexpr double kStandingMps = 0.02;
constexpr double kDrivingMps = 0.15;       // kill only while the robot drives at least this fast
constexpr double kScanPeriodS = 0.1;

struct KillRecord {
  std::string target;
  double speedAtKill = 0.0;
  double allowedS = 0.0;
  double safeAfterS = 0.0;  // until standing or commanded again
  std::string how;          // "stood" / "commanded again"
};

// The robot's true speed over its latest scan interval.
class SpeedProbe {
 public:
  explicit SpeedProbe(const ClientSettings& settings) : probe_(settings) {}
  // The newest speed (waits for a new scan).
  double speed() {
    for (;;) {
      const TrueSample now = probe_.latest();
      if (last_ && now.scan > last_->scan) {
        const double v = std::hypot(now.pose.x - last_->pose.x, now.pose.y - last_->pose.y) /
                         (kScanPeriodS * double(now.scan - last_->scan));
        last_ = now;
        return v;
      }
      last_ = now;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

 private:
  TruePoseProbe probe_;
  std::optional<TrueSample> last_;
};

class MotionFaults {
 public:
  MotionFaults(TestCluster& cluster, int kills, double decelerationMps2, unsigned seed)
      : cluster_(cluster), kills_(kills), deceleration_(decelerationMps2), random_(seed) {}

  void run(const std::atomic<bool>& finished) {
    SpeedProbe speed(cluster_.clientSettings());
    LowLevelDriveClient drive(cluster_.clientSettings());
    CollisionAvoidanceClient cam(cluster_.clientSettings());
    std::uniform_real_distribution<double> pause(3.0, 8.0);
    for (int i = 0; i < kills_ && !finished; ++i) {
      const std::string target = i % 2 == 0 ? "LowLevelDrive" : "CollisionAvoidance";
      const auto pauseUntil = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                 std::chrono::duration<double>(pause(random_)));
      while (!finished && (Clock::now() < pauseUntil || speed.speed() < kDrivingMps))
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      if (finished) break;
      records_.push_back(killOnce(target, speed, drive, cam));
    }
  }

  const std::vector<KillRecord>& records() const { return records_; }

 private:
  KillRecord killOnce(const std::string& target, SpeedProbe& speed, LowLevelDriveClient& drive,
                      CollisionAvoidanceClient& cam) {
    KillRecord r;
    r.target = target;
    const auto victim = cluster_.waitFor(target, isRunning, "running");
    r.speedAtKill = speed.speed();
    const DriveReport before = drive.driveStatus();
    const auto hit = Clock::now();
    ::kill(static_cast<pid_t>(victim.pid), SIGKILL);
    const double braking = r.speedAtKill / deceleration_;
    r.allowedS = (target == "LowLevelDrive" ? kCommandTimeoutS : before.drive.remainingSeconds) + braking + kToleranceS;
    for (;;) {
      const double v = speed.speed();
      r.safeAfterS = std::chrono::duration<double>(Clock::now() - hit).count();
      if (v < kStandingMps) {
        r.how = "stood";
        break;
      }
      if (commandedAgain(target, victim.pid, drive, cam)) {
        r.how = "commanded again";
        break;
      }
    }
    cluster_.waitFor(target, [&](const ModuleProcessInfo& m) { return isRunning(m) && m.pid != victim.pid; },
                     "restarted", std::chrono::seconds(30));
    std::printf("kill %2zu %-18s at %.2f m/s: safe after %.2f s (%s), allowed %.2f s\n", records_.size() + 1,
                target.c_str(), r.speedAtKill, r.safeAfterS, r.how.c_str(), r.allowedS);
    std::fflush(stdout);
    return r;
  }

  // Whether the restarted module drives the robot again: the drive sends velocity commands, the
  // CAM has sent chains.
  bool commandedAgain(const std::string& target, std::int64_t deadPid, LowLevelDriveClient& drive,
                      CollisionAvoidanceClient& cam) {
    const ModuleProcessInfo now = cluster_.describe(target);
    if (!isRunning(now) || now.pid == deadPid) return false;
    try {
      if (target == "LowLevelDrive") return drive.driveStatus().commandsSent > 0;
      const ModuleStatusInfo status = cam.status();
      const auto sent = status.counters.find("chains_sent");
      return static_cast<std::int64_t>(status.pid) != deadPid && sent != status.counters.end() && sent->second > 0;
    } catch (const ModuleUnavailableError&) {
      return false;
    }
  }

  TestCluster& cluster_;
  int kills_;
  double deceleration_;
  std::mt19937 random_;
  std::vector<KillRecord> records_;
};

}  // namespace

int main(int argc, char** argv) {
  CrowdEvaluationOptions options;
  int kills = 20;
  unsigned faultSeed = 7;
  po::options_description description("rgnav-faulttest-motion [options]");
  description.add_options()("help", "this text")
      ("kills", po::value(&kills)->default_value(kills), "SIGKILLs, LowLevelDrive and CollisionAvoidance in turn")
      ("fault-seed", po::value(&faultSeed)->default_value(faultSeed), "seed of the pauses between kills");
  options.addTo(description);
  try {
    if (!parseCommandLine(argc, argv, description)) return 0;
    catchInterruptions();
    const PreparedCrowd prepared = prepareCrowd(options);
    CrowdSet set(crowdSetOptions(options, prepared), &prepared.map);
    set.start();
    const double deceleration = loadSimulationConfig(options.simConfig).robot.maxTranslationalAcceleration;
    MotionFaults faults(set.cluster(), kills, deceleration, faultSeed);
    std::atomic<bool> finished{false};
    std::exception_ptr faultError;
    std::thread injector([&] {
      try {
        faults.run(finished);
      } catch (...) {
        faultError = std::current_exception();
      }
    });
    CrowdOutcome outcome;
    try {
      outcome = driveGoals(set.cluster().clientSettings(), prepared.goals, options.run);
    } catch (...) {
      finished = true;
      injector.join();
      throw;
    }
    finished = true;
    injector.join();
    if (faultError) std::rethrow_exception(faultError);
    const SimulatorCounters counters = simulatorCounters(set.cluster().clientSettings());
    std::cout << crowdLine(outcome, counters) << std::endl;

    int lldKills = 0, camKills = 0;
    double maxOverrun = -std::numeric_limits<double>::infinity();
    for (const KillRecord& r : faults.records()) {
      (r.target == "LowLevelDrive" ? lldKills : camKills)++;
      maxOverrun = std::max(maxOverrun, r.safeAfterS - r.allowedS);
    }
    const int done = static_cast<int>(faults.records().size());
    const bool pass = done == kills && maxOverrun <= 0.0 && outcome.reached() == outcome.goals.size() &&
                      counters.robotCollisions == 0;
    std::printf("motion_faults: kills=%d lld_kills=%d cam_kills=%d recovered=%d max_overrun_s=%.2f goals=%zu "
                "reached=%zu robot_collisions=%llu result=%s\n",
                done, lldKills, camKills, done, done > 0 ? maxOverrun : 0.0, outcome.goals.size(), outcome.reached(),
                static_cast<unsigned long long>(counters.robotCollisions), pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-faulttest-motion: " << e.what() << std::endl;
    return 1;
  }
}
