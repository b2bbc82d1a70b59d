// rgnav-sim-hallways: records the labelled hallway scenarios for gateway classification (thesis
// 4.1.4): for every environment (width x clutter), gateway class, clutter layout and approach
// (start distance x lateral offset), the simulated laser scan at every sampled pose. Writes per
// environment a CARMEN log (<env>.log: FLASER with the true pose, one ODOM per scan) and a label
// file (<env>.labels.tsv: scan ID, class, distance to the gateway centre in m, layout, approach,
// start distance, lateral offset), then a summary line:
//   hallways: environments=8 classes=8 layouts=… sequences=… scans=…
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "core/sim/SimulationConfigYaml.h"
#include "core/sim/motion/CarmenLogWriter.h"
#include "core/sim/scenarios/HallwayScenarios.h"
#include "core/sim/world/Raycaster.h"
#include "tools/common/CommandLine.h"
#include "tools/common/StrictArguments.h"

namespace po = boost::program_options;
namespace fs = std::filesystem;
using namespace rgnav;

namespace {

std::string fileStem(const std::string& environment) {
  std::string stem;
  for (char c : environment) stem += c == ' ' ? '_' : c;
  return stem;
}

struct EnvironmentOutput {
  std::ofstream log;
  std::ofstream labels;
  std::unique_ptr<CarmenLogWriter> writer;
  DataId nextId = 1;
};

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seed = 1;
  int layouts = 3;
  std::string outDir, config;
  po::options_description desc("rgnav-sim-hallways [options]");
  desc.add_options()
      ("help", "this text")
      ("seed", rgnav::strictOption(&seed, "--seed")->default_value(std::to_string(seed)),
       "seed of the clutter layouts and the laser noise")
      ("layouts", rgnav::strictOption(&layouts, "--layouts")->default_value(std::to_string(layouts)),
       "clutter layouts per environment and class")
      ("config", po::value(&config)->default_value(""), "simulation parameters (laser) from config/sim/*.yaml")
      ("out", po::value(&outDir)->default_value("out/hallways"), "output folder");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    const SimulationConfig simulation = config.empty() ? SimulationConfig{} : loadSimulationConfig(config);
    const LaserModel laser(simulation.laser);
    std::mt19937_64 rng(seed);
    fs::create_directories(outDir);
    std::map<std::string, EnvironmentOutput> outputs;
    std::size_t sequences = 0, scans = 0;
    int layout = 0;
    for (const ScenarioSpec& spec : scenarioSet(seed, layouts)) {
      const HallwayScenario scenario = buildScenario(spec);
      const Raycaster raycaster(scenario.world);
      EnvironmentOutput& out = outputs[spec.environment.name];
      if (!out.writer) {
        const std::string stem = outDir + "/" + fileStem(spec.environment.name);
        out.log.open(stem + ".log");
        out.labels.open(stem + ".labels.tsv");
        if (!out.log || !out.labels) throw FileError(stem + ".*: cannot write");
        out.labels << "scan_id\tclass\tdistance_m\tlayout\tapproach\tstart_distance_m\tlateral_offset_m\n";
        out.writer = std::make_unique<CarmenLogWriter>(out.log);
      }
      const Pose2D gateway{scenario.gatewayCentre.x, scenario.gatewayCentre.y, 0.0};
      for (std::size_t a = 0; a < scenario.approaches.size(); ++a) {
        const Approach& approach = scenario.approaches[a];
        for (const LabelledPose& labelled : approach.poses) {
          const Pose2D pose = compose(gateway, labelled.pose);
          const DataId id = out.nextId++;
          const LaserScan scan = laser.simulate(pose, pose, id, double(id) * 0.1, raycaster, rng);
          out.writer->write(OdometryReading{id, scan.stamp, pose, 0.0, 0.0});
          out.writer->write(scan);
          char row[256];
          std::snprintf(row, sizeof row, "%llu\t%s\t%.3f\t%d\t%zu\t%.2f\t%.3f\n", static_cast<unsigned long long>(id),
                        std::string(gatewayClassName(labelled.gatewayClass)).c_str(), labelled.distance, layout, a,
                        approach.startDistance, approach.lateralOffset);
          out.labels << row;
          ++scans;
        }
        ++sequences;
      }
      ++layout;
    }
    std::printf("hallways: environments=%zu classes=%zu layouts=%d sequences=%zu scans=%zu out=%s\n", outputs.size(),
                kGatewayClasses.size(), layouts, sequences, scans, outDir.c_str());
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-sim-hallways: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-sim-hallways: " << e.what() << std::endl;
  }
  return 2;
}
