// rgnav-sim: the simulator as modules: Laser and Base (served exactly like a log playback, so
// consumers cannot tell them apart) and GroundTruth (evaluation only), for a world given as a
// floor plan image, a map_server YAML or a vector world. The robot follows velocity commands
// (Base::setVelocity) or drives a tour through every ground-truth room (--tour). Clocks: real
// time, or lock-step (it advances when a laser consumer asks for the next scan: as fast as the
// consumers allow, deterministic for a seed). --record writes the run as a CARMEN log. --people N
// lets N people walk through the world (moving obstacles); the module's health counts
// robot_collisions (the robot drove into a wall or person) and person_bumps (a person walked into
// the robot: standing, driving away or passing); each collision is also a line on stderr.
#include <atomic>
#include <fstream>
#include <iostream>
#include <thread>

#include "core/sim/GroundTruthTour.h"
#include "core/sim/SimulatedRobot.h"
#include "core/sim/SimulationConfigYaml.h"
#include "core/sim/StartPose.h"
#include "drivers/sim/GroundTruthImpl.h"
#include "servers/sensors/SensorServants.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

Pose2D parsePose(const std::string& text) {
  Pose2D pose;
  char c1 = 0, c2 = 0;
  std::istringstream in(text);
  if (!(in >> pose.x >> c1 >> pose.y >> c2 >> pose.theta) || c1 != ',' || c2 != ',')
    throw ConfigError("--start wants x,y,theta (metres, metres, radians), not '" + text + "'");
  return pose;
}

SimClock parseClock(const std::string& text) {
  if (text == "realtime") return SimClock::RealTime;
  if (text == "lockstep") return SimClock::LockStep;
  throw ConfigError("--clock is realtime or lockstep, not '" + text + "'");
}

}  // namespace

int main(int argc, char** argv) {
  std::string world, config, start, clock, record, laserObject, baseObject, truthObject;
  bool tour = false;
  long long seed = -1;
  int people = -1;
  std::size_t buffer = 0;
  std::uint32_t maxBatch = 0;
  po::options_description options("Simulator options");
  options.add_options()
      ("world", po::value(&world)->required(), "floor plan image (.png/.pgm), map_server .yaml or vector world .yaml")
      ("config", po::value(&config)->default_value(""), "simulation parameters (config/sim/*.yaml); built-in defaults if empty")
      ("seed", po::value(&seed)->default_value(-1), "overrides the configured seed")
      ("people", po::value(&people)->default_value(-1), "people walking through the world (overrides the configured count)")
      ("clock", po::value(&clock)->default_value("realtime"), "realtime or lockstep")
      ("tour", po::bool_switch(&tour), "drive a tour through every ground-truth room (else: follow setVelocity)")
      ("start", po::value(&start)->default_value(""), "x,y,theta; default: the world's task start, else the free cell farthest from walls")
      ("record", po::value(&record)->default_value(""), "write the run as a CARMEN log")
      ("buffer", po::value(&buffer)->default_value(20000), "scans and odometry readings held for consumers")
      ("max-batch", po::value(&maxBatch)->default_value(500), "most records one call returns")
      ("laser-object", po::value(&laserObject)->default_value("Laser"), "object name of the Laser interface")
      ("base-object", po::value(&baseObject)->default_value("Base"), "object name of the Base interface")
      ("truth-object", po::value(&truthObject)->default_value("GroundTruth"), "object name of the GroundTruth interface");
  std::ofstream recording;
  std::atomic<bool> stop{false};
  std::thread ticker;
  const int code = runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    SimulationConfig simulation = config.empty() ? SimulationConfig{} : loadSimulationConfig(config);
    if (seed >= 0) simulation.seed = static_cast<std::uint64_t>(seed);
    if (people >= 0) simulation.people.count = people;
    LoadedWorld loaded = loadWorld(world);
    const Pose2D startPose = !start.empty() ? parsePose(start) : loaded.task ? loaded.task->start : openestPose(loaded.grid);
    std::optional<Tour> route;
    if (tour) {
      if (!loaded.truth) throw ConfigError(world + ": --tour needs ground-truth rooms, and this world has none");
      route = planTour(loaded.grid, *loaded.truth, startPose);
    }
    if (!record.empty()) {
      recording.open(record, std::ios::trunc);
      if (!recording) throw FileError(record + ": cannot write");
    }
    SimulatedRobotOptions robotOptions;
    robotOptions.clock = parseClock(clock);
    robotOptions.bufferCapacity = buffer;
    robotOptions.collisionLog = &std::cerr;
    auto robot = std::make_shared<SimulatedRobot>(std::move(loaded), simulation, startPose, std::move(route),
                                                  record.empty() ? nullptr : &recording, robotOptions);
    runtime.activate(laserObject, new LaserImpl(runtime, robot, maxBatch));
    runtime.activate(baseObject, new BaseImpl(runtime, robot, maxBatch));
    runtime.activate(truthObject, new GroundTruthImpl(runtime, robot));
    runtime.health().addReporter([robot](ModuleHealth& health) {
      health.set("robot_collisions", robot->robotCollisions());
      health.set("person_bumps", robot->personBumps());
      health.set("simulated_ms", static_cast<std::uint64_t>(robot->simulatedSeconds() * 1000));
    });
    if (robotOptions.clock == SimClock::RealTime) {
      ticker = std::thread([robot, &stop, period = std::chrono::duration<double>(simulation.stepSeconds)] {
        auto next = std::chrono::steady_clock::now();
        while (!stop) {
          robot->step();
          next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
          std::this_thread::sleep_until(next);
        }
      });
      runtime.onShutdown([&] {
        stop = true;
        ticker.join();
      });
    }
    std::cerr << "simulating " << world << " (" << clock << (tour ? ", tour" : ", velocity commands") << ", seed "
              << simulation.seed << ", " << simulation.people.count << " people) serving on " << runtime.server().endpoint.str() << std::endl;
  });
  if (ticker.joinable()) {
    stop = true;
    ticker.join();
  }
  return code;
}
