// rgnav-sim-tour: drives the simulated robot on a tour through every ground-truth room of one or
// more worlds with ground truth (IPA floor plans X.png / X_furnitures.png with
// X_gt_segmentation.png beside them, or vector worlds),
// writes each run as a CARMEN log, and prints a row per map and a summary:
//   tour: maps=10 rooms_reachable=… rooms_visited=… unreachable=… collisions=0
// Exit code 0 only if every reachable room was visited without a collision.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/sim/TourRun.h"
#include "core/sim/motion/CarmenLogWriter.h"
#include "core/sim/LoadedWorld.h"
#include "tools/common/CommandLine.h"
#include "tools/common/StrictArguments.h"

namespace po = boost::program_options;
namespace fs = std::filesystem;
using namespace rgnav;

int main(int argc, char** argv) {
  std::vector<std::string> maps;
  std::string outDir;
  std::uint64_t seed = 1;
  po::options_description desc("rgnav-sim-tour <map.png>... [options]");
  desc.add_options()
      ("help", "this text")
      ("map", po::value(&maps)->required()->multitoken(), "IPA-format floor plans (X.png or X_furnitures.png)")
      ("out", po::value(&outDir)->default_value("out/tours"), "folder for the CARMEN logs")
      ("seed", rgnav::strictOption(&seed, "--seed")->default_value(std::to_string(seed)), "simulation seed");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    fs::create_directories(outDir);
    std::size_t reachable = 0, visited = 0, unreachable = 0, collisions = 0, failures = 0;
    std::printf("%-32s %6s %9s %7s %11s %10s %8s %9s\n", "map", "rooms", "reachable", "visited", "unreachable",
                "collisions", "scans", "distance");
    for (const std::string& map : maps) {
      const LoadedWorld world = loadWorld(map);
      if (!world.truth) throw FileError(map + ": no ground-truth rooms beside it (" + ipaFilesOf(map).truth + ")");
      const OccupancyGrid& grid = world.grid;
      const GroundTruth& truth = *world.truth;
      const std::string name = ipaFilesOf(map).name;
      SimulationConfig config;
      config.seed = seed;
      std::ofstream log(outDir + "/" + name + ".log");
      CarmenLogWriter writer(log);
      const RoomTour roomTour = driveRoomTour(grid, truth, config, [&](const SimulationStep& step) {
        writer.write(step.odometry);
        if (step.scan) writer.write(*step.scan);
      });
      const Tour& tour = roomTour.plan;
      const TourRunResult& run = roomTour.run;
      std::printf("%-32s %6d %9zu %7zu %11zu %10llu %8llu %8.0fm\n", name.c_str(), truth.roomCount,
                  tour.visits.size(), run.roomsVisited.size(), tour.unreachableRooms.size(),
                  static_cast<unsigned long long>(run.collisions), static_cast<unsigned long long>(run.scans),
                  run.distance);
      reachable += tour.visits.size();
      visited += run.roomsVisited.size();
      unreachable += tour.unreachableRooms.size();
      collisions += run.collisions;
      failures += !run.finished || run.collisions > 0;
    }
    std::printf("tour: maps=%zu rooms_reachable=%zu rooms_visited=%zu unreachable=%zu collisions=%zu\n", maps.size(),
                reachable, visited, unreachable, collisions);
    return failures == 0 ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-sim-tour: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-sim-tour: " << e.what() << std::endl;
  }
  return 2;
}
