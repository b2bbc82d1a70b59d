// rgnav-eval-barn: the BARN evaluation of issue 27 ("rgctl eval barn <barn_*.yaml...>"): each
// world driven in process by the Low-Level Drive and the Collision Avoidance with the map-less
// goal seeking (BarnRun.h), on --threads worlds at a time. Prints a line per world (in the order
// given) and, last,
//   barn: worlds=... success=... collisions=... timeouts=... score_mean=...
// success, collisions and timeouts as shares of the worlds; score_mean over all worlds (a failed
// run scores 0), the benchmark's metric (SOURCES.md beside the worlds).
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <thread>
#include <vector>

#include "core/nav/avoidance/CollisionAvoidanceConfigYaml.h"
#include "core/sim/SimulationConfigYaml.h"
#include "tests/eval/barn/BarnRun.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

// The robot's motion limits are the simulated robot's; braking as fast as it speeds up.
MotionLimits limitsOf(const DiffDriveConfig& robot, double lateralAcceleration) {
  MotionLimits limits;
  limits.maxVelocity = robot.maxTranslationalVelocity;
  limits.maxAcceleration = robot.maxTranslationalAcceleration;
  limits.maxDeceleration = robot.maxTranslationalAcceleration;
  limits.maxRotationalVelocity = robot.maxRotationalVelocity;
  limits.maxRotationalAcceleration = robot.maxRotationalAcceleration;
  limits.maxLateralAcceleration = lateralAcceleration;
  return limits;
}

void printResult(const BarnResult& r) {
  std::printf("%s: success=%d collision=%d timeout=%d time_s=%.2f optimal_s=%.2f score=%.3f blocked=%zu\n",
              r.name.c_str(), r.success, r.collided, r.timedOut, r.seconds, r.optimalSeconds, r.score, r.blocked);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> worlds;
  std::string simConfig = "config/sim/jackal.yaml";
  std::string avoidanceConfig = "config/modules/collisionavoidance.yaml";
  double lateralAcceleration = 3.0;
  double maxSpeed = 1.5;
  unsigned threads = 2;
  bool trace = false;
  PostureGains gains;
  po::options_description desc("rgnav-eval-barn [options] <barn_NNN.yaml...>: the BARN navigation benchmark");
  desc.add_options()
      ("world", po::value(&worlds)->required(), "BARN worlds (map_server YAML with a task)")
      ("sim-config", po::value(&simConfig)->default_value(simConfig), "the simulated robot (footprint, limits, laser)")
      ("config", po::value(&avoidanceConfig)->default_value(avoidanceConfig), "the Collision Avoidance's parameters")
      ("max-speed", po::value(&maxSpeed)->default_value(maxSpeed), "m/s the chains may ask (at most the robot's)")
      ("lateral-acceleration", po::value(&lateralAcceleration)->default_value(lateralAcceleration),
       "m/s^2 the chains may ask on turns")
      ("kx", po::value(&gains.kx)->default_value(gains.kx), "tracking gain K_x, 1/s (PostureController.h)")
      ("ky", po::value(&gains.ky)->default_value(gains.ky), "tracking gain K_y, 1/m^2")
      ("ktheta", po::value(&gains.ktheta)->default_value(gains.ktheta), "tracking gain K_theta, 1/m")
      ("threads", po::value(&threads)->default_value(threads), "worlds run at a time")
      ("trace", po::bool_switch(&trace), "print every decision of the Collision Avoidance but keep");
  po::positional_options_description positional;
  positional.add("world", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    BarnSetup setup;
    setup.sim = loadSimulationConfig(simConfig);
    setup.avoidance = loadCollisionAvoidanceConfig(avoidanceConfig);
    setup.avoidance.obstacleMap.laserForwardOffsetM = setup.sim.laser.forwardOffset;
    setup.drive.limits = limitsOf(setup.sim.robot, lateralAcceleration);
    setup.drive.limits.maxVelocity = std::min(maxSpeed, setup.drive.limits.maxVelocity);
    setup.drive.periodSeconds = setup.sim.stepSeconds;
    setup.trace = trace;
    setup.drive.gains = gains;

    std::vector<BarnResult> results(worlds.size());
    std::vector<bool> done(worlds.size(), false);
    std::atomic<std::size_t> next{0};
    std::size_t printed = 0;
    std::mutex mutex;
    std::exception_ptr failure;
    const auto work = [&] {
      for (std::size_t i = next++; i < worlds.size(); i = next++) {
        try {
          BarnResult r = runBarnWorld(worlds[i], setup);
          const std::lock_guard lock(mutex);
          results[i] = std::move(r);
          done[i] = true;
          while (printed < worlds.size() && done[printed]) printResult(results[printed++]);
        } catch (...) {
          const std::lock_guard lock(mutex);
          if (!failure) failure = std::current_exception();
          next = worlds.size();
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < std::max(1u, threads); ++t) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);

    std::size_t success = 0, collisions = 0, timeouts = 0;
    double scoreSum = 0.0;
    for (const BarnResult& r : results) {
      success += r.success;
      collisions += r.collided;
      timeouts += r.timedOut;
      scoreSum += r.score;
    }
    const double n = static_cast<double>(results.size());
    std::printf("barn: worlds=%zu success=%.3f collisions=%.3f timeouts=%.3f score_mean=%.3f\n", results.size(),
                success / n, collisions / n, timeouts / n, scoreSum / n);
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-barn: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-barn: " << e.what() << std::endl;
  }
  return 2;
}
