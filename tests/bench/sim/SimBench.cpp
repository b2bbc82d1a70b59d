// rgnav-bench-sim: raycasting speed of the simulator's laser (issue 3: >= 5000 scans/s of 361
// beams on one core in a 2000 x 2000 px map). The map is a real floor plan, the furnished IPA
// office_c (1683 x 965 px, the largest of the ten benchmark maps), tiled from the top-left
// corner into a 2000 x 2000 canvas at 0.05 m per cell; sensor poses are random free cells with
// random headings (seeded). Single thread.
// Last line: sim: raycast_scans_per_s=… mean_range_m=… (the mean range of the beams that return: a
// check of the scans, since the poses are seeded)
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

#include "core/raster/ImageFile.h"
#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/LaserModel.h"
#include "core/sim/world/Raycaster.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

constexpr int kCanvasSize = 2000;

std::string defaultMap() {
  const char* shared = std::getenv("RGNAV_SHARED");
  return std::string(shared != nullptr ? shared : "../shared") +
         "/data/floorplans/ipa_room_segmentation/test_maps/office_c_furnitures.png";
}

cv::Mat tiled(const cv::Mat& tile, int size) {
  cv::Mat canvas;
  cv::repeat(tile, size / tile.rows + 1, size / tile.cols + 1, canvas);
  return canvas(cv::Rect(0, 0, size, size)).clone();
}

std::vector<Pose2D> randomFreePoses(const OccupancyGrid& grid, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> col(0, grid.width() - 1), row(0, grid.height() - 1);
  std::uniform_real_distribution<double> heading(-M_PI, M_PI);
  std::vector<Pose2D> poses;
  while (poses.size() < count) {
    const CellIndex cell{col(rng), row(rng)};
    if (grid.at(cell) != Cell::Free) continue;
    const WorldPoint p = grid.center(cell);
    poses.push_back({p.x, p.y, heading(rng)});
  }
  return poses;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t scans = 20000;
  std::uint64_t seed = 1;
  std::string mapPath = defaultMap();
  po::options_description desc("rgnav-bench-sim [options]");
  desc.add_options()
      ("help", "this text")
      ("scans", po::value(&scans)->default_value(scans), "361-beam scans to time")
      ("seed", po::value(&seed)->default_value(seed), "seed of the random sensor poses")
      ("map", po::value(&mapPath)->default_value(mapPath), "floor plan tiled into the 2000 x 2000 canvas");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    const cv::Mat plan = readGrayImage(mapPath);
    const OccupancyGrid grid = floorPlanFromImage(tiled(plan, kCanvasSize), kFloorPlanResolution, {});
    const auto setupStart = std::chrono::steady_clock::now();
    const Raycaster raycaster(grid);
    const double setupSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setupStart).count();

    LaserConfig config;
    config.angularResolution = M_PI / 360.0;
    const LaserModel laser(config);
    const std::vector<Pose2D> poses = randomFreePoses(grid, std::max<std::size_t>(scans, 1), seed);
    std::vector<float> ranges(laser.beamCount());

    std::size_t returns = 0, within20 = 0;
    double rangeSum = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (const Pose2D& pose : poses) {
      raycaster.scan(pose, laser.startAngle(), config.angularResolution, config.maxRange, ranges);
      for (const float r : ranges) {
        if (std::isinf(r)) continue;
        ++returns;
        within20 += r <= 20.0f;
        rangeSum += r;
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double beams = double(poses.size()) * double(ranges.size());
    const double meanRangeM = returns > 0 ? rangeSum / double(returns) : 0.0;

    std::cout << "map: " << mapPath << " (" << plan.cols << "x" << plan.rows << " px) tiled into "
              << kCanvasSize << "x" << kCanvasSize << " cells of " << kFloorPlanResolution << " m\n"
              << "scans: " << poses.size() << " x " << ranges.size() << " beams, max range " << config.maxRange
              << " m, random free poses (seed " << seed << "), one thread\n"
              << "leap table: " << setupSeconds << " s\n"
              << "beams: mean range " << meanRangeM << " m, "
              << 100.0 * double(within20) / beams << " % end within 20 m, "
              << 100.0 * (1.0 - double(returns) / beams) << " % no return\n"
              << "sim: raycast_scans_per_s=" << static_cast<long long>(double(poses.size()) / seconds)
              << " mean_range_m=" << meanRangeM << std::endl;
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-bench-sim: " << e.what() << std::endl;
    return 1;
  }
}
