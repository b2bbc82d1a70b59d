// rgnav-eval-rooms: the room evaluation of issue 7 ("rgctl eval rooms") on furnished IPA floor
// plans X_furnitures.png (floorplans/SOURCES.md). For each map the simulator drives the room tour
// through every ground-truth room and the scans are mapped in process (MappingRun.h: SLAM ->
// gateway detection -> RG Mapping Kernel, poses revised after every SLAM optimisation and at the
// end); the final regions' freespace is placed into the floor plan, grown by --grow over the
// free pixels no region claims and given the holes up to --max-hole it encloses (RegionPixels.h),
// and scored against the ground-truth rooms with the benchmark's metric (RoomScoring.h). Prints a
// row per map with a line of where it loses (ScoreBreakdown.h) and, last,
//   rooms: maps=… recall_mean=… precision_mean=… recall_pooled=… precision_pooled=…
// where the means are over the maps' means and the pooled figures sum pixels over all maps; the
// line before gives the same figures over the tuning and over the check maps of the IPA split
// (config/eval/ipa-split.yaml: rooms_split: … recall_mean_tuning=… recall_mean_check=…). A
// picture per map goes to --out (DebugImage.h; --region-pictures: one per region too); --list
// prints every room, region and gateway (Listing.h). A line per map and one before the last score
// the regions' 2D objects against the furniture (ObjectScoring.h). Trained HMMs (--models, if the
// file exists) add hallway gateways to the narrow passages. The detector and kernel options
// default to the modules' defaults (what the server set runs); --true-poses replaces SLAM by the
// true poses. --server-set maps each floor plan as the issue asks, online with the full server set
// (ServerSetRun.h: Simulator, ScanMapper, GatewayDetection and RG Mapping Kernel modules with their
// own omniNames and watchdog on free loopback ports), each module with its defaults; without it
// the same chain runs in process (MappingRun.h), which is faster, takes the detector and kernel
// options above and knows which scans each region holds (--list, --region-pictures).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "core/gateways/classify/HmmModelFile.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/SimulationConfigYaml.h"
#include "core/sim/world/FloorPlan.h"
#include "tests/eval/rooms/DebugImage.h"
#include "tests/eval/rooms/Listing.h"
#include "tests/eval/rooms/MappingRun.h"
#include "tests/eval/rooms/ObjectScoring.h"
#include "tests/eval/rooms/RegionPixels.h"
#include "tests/eval/rooms/RoomScoring.h"
#include "tests/eval/rooms/ScoreBreakdown.h"
#include "tests/eval/rooms/ServerSetRun.h"
#include "tests/eval/split/IpaSplit.h"
#include "tests/support/cluster/Interruption.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  MappingRunSetup setup;
  std::string simConfig;
  std::string models = "config/gateways/gateway-hmms.txt";
  std::string outDir = "out/rooms";
  bool list = false;
  bool regionPictures = false;
  bool serverSet = false;
  double growM = 0.3;
  double maxHoleM2 = 2.0;
  std::string split = "config/eval/ipa-split.yaml";
};

// Whether an option that only the in-process run takes differs from its default (`shipped`: the
// modules' parameters the server set runs with).
bool inProcessOptionsGiven(const Options& o, const MappingPipelineConfig& shipped) {
  const Options d;
  const MappingPipelineConfig &p = o.setup.pipeline, &q = shipped;
  return o.list || o.regionPictures || o.setup.truePoses || o.setup.maxTourSeconds != d.setup.maxTourSeconds ||
         p.gateways.hallways.hypotheses.hallwayWidthM != q.gateways.hallways.hypotheses.hallwayWidthM ||
         p.gateways.passages.maxDoorWidthM != q.gateways.passages.maxDoorWidthM ||
         p.gateways.passages.minJambLengthM != q.gateways.passages.minJambLengthM ||
         p.gateways.passageTracking.minSupport != q.gateways.passageTracking.minSupport ||
         p.gateways.passageTracking.associationDistanceM != q.gateways.passageTracking.associationDistanceM ||
         p.kernel.sides.rangeM != q.kernel.sides.rangeM ||
         p.kernel.models.doorFrames.depthM != q.kernel.models.doorFrames.depthM ||
         p.kernel.models.doorFrames.widenM != q.kernel.models.doorFrames.widenM;
}

MappingRun mapOne(const std::string& mapPath, const LoadedWorld& world, const Options& options,
                  const std::optional<HmmClassifier>& classifier) {
  if (!options.serverSet) return mapRoomTour(world.grid, *world.truth, options.setup, classifier);
  const ServerSetSetup setup{classifier ? options.models : std::string(), options.simConfig,
                             options.setup.simulation.seed};
  return mapRoomTourOnServerSet(mapPath, world.grid, *world.truth, setup);
}

struct Totals {
  std::size_t maps = 0, scans = 0;
  double recallMeans = 0.0, precisionMeans = 0.0, ceilingMeans = 0.0, furnitureMeans = 0.0, mappingSeconds = 0.0;
  std::size_t roomOverlap = 0, roomPixels = 0, segmentOverlap = 0, segmentPixels = 0;
  ObjectScore objects;

  void add(const Totals& o) {
    maps += o.maps;
    scans += o.scans;
    recallMeans += o.recallMeans;
    precisionMeans += o.precisionMeans;
    ceilingMeans += o.ceilingMeans;
    furnitureMeans += o.furnitureMeans;
    mappingSeconds += o.mappingSeconds;
    roomOverlap += o.roomOverlap;
    roomPixels += o.roomPixels;
    segmentOverlap += o.segmentOverlap;
    segmentPixels += o.segmentPixels;
    objects.objects += o.objects.objects;
    objects.onFurniture += o.objects.onFurniture;
    objects.blobs += o.objects.blobs;
    objects.blobsFound += o.objects.blobsFound;
  }
  double recallMean() const { return recallMeans / double(std::max<std::size_t>(maps, 1)); }
  double precisionMean() const { return precisionMeans / double(std::max<std::size_t>(maps, 1)); }
};

// Furniture blobs smaller than this (20 cells, 0.05 m2: table and chair legs) are specks for the
// object score: no rectangle describes them.
constexpr int kMinFurnitureCells = 20;

double ratio(std::size_t a, std::size_t b) { return b == 0 ? 0.0 : double(a) / double(b); }

// A default value for --help as a person writes it (2.2, not 2.2000000000000002).
std::string shown(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// The figures of one map.
Totals evaluate(const std::string& mapPath, const Options& options, const std::optional<HmmClassifier>& classifier) {
  const auto started = std::chrono::steady_clock::now();
  const LoadedWorld world = loadWorld(mapPath);
  const IpaFiles files = ipaFilesOf(mapPath);
  if (!world.truth) throw FileError(mapPath + ": no ground-truth rooms beside it (" + files.truth + ")");
  const MappingRun run = mapOne(mapPath, world, options, classifier);
  const std::vector<SegmentPixels> regions =
      regionPixels(run.map, run.mapToWorld, world.grid, options.growM, options.maxHoleM2);
  const RoomScore score = scoreRooms(*world.truth, regions);
  const ScoreBreakdown losses = breakDownScore(*world.truth, world.grid, regions, score, run.unreachableRooms);
  writeRoomImage(options.outDir + "/" + files.name + "_rooms.png", world.grid, *world.truth, run.map, run.mapToWorld,
                 regions);
  if (options.regionPictures)
    for (const SegmentPixels& region : regions) {
      std::vector<Eigen::Vector2d> positions;
      for (const DataId id : run.regionScans.at(RegionId(region.id))) positions.push_back(run.truePath[id - 1]);
      writeRegionImage(options.outDir + "/" + files.name + "_region" + std::to_string(region.id) + ".png", world.grid,
                       *world.truth, run.map, run.mapToWorld, region, positions);
    }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::size_t scans = run.counts.scans;
  std::printf("%-26s %5d %7zu %8zu %11zu %6zu %7.0f | %6.3f %9.3f %7.3f %9.3f | %3zu/%-3zu %4.2f/%-4.2f %5.0fs\n",
              files.name.c_str(), world.truth->roomCount, run.map.summary.regions, run.map.summary.gateways,
              run.map.summary.neutralised, scans, double(scans) / std::max(run.mappingSeconds, 1e-9),
              score.recallMean(), score.precisionMean(), ratio(score.roomOverlapSum(), score.roomPixelSum()),
              ratio(score.segmentOverlapSum(), score.segmentPixelSum()), run.tour.roomsVisited.size(),
              run.tour.roomsVisited.size() + run.tour.roomsMissed.size(),
              run.poseErrors.meanM, run.poseErrors.maxM, seconds);
  std::printf("#   losses: recall ceiling %.3f covered %.3f best %.3f | precision pixels off-room %.3f leaked %.3f "
              "merged %.3f\n", losses.ceilingMean, losses.coveredMean, score.recallMean(), losses.offRoomShare,
              losses.leakedShare, losses.mergedShare);
  const FurnitureTruth furnitureBlobs = furnitureTruth(world.grid, loadFloorPlan(files.empty), kMinFurnitureCells);
  const double furniture = furnitureShareMean(*world.truth, furnitureBlobs);
  const ObjectScore objects = scoreObjects(run.map, run.mapToWorld, world.grid, furnitureBlobs);
  std::printf("#   objects: %zu, on furniture %zu (%.3f) | furniture blobs >= %d cells found %zu of %zu\n",
              objects.objects, objects.onFurniture, ratio(objects.onFurniture, objects.objects), kMinFurnitureCells,
              objects.blobsFound, objects.blobs);
  if (options.list) printListing(score, *world.truth, run);
  std::fflush(stdout);
  Totals one;
  one.maps = 1;
  one.scans = scans;
  one.mappingSeconds = run.mappingSeconds;
  one.recallMeans = score.recallMean();
  one.ceilingMeans = losses.ceilingMean;
  one.furnitureMeans = furniture;
  one.precisionMeans = score.precisionMean();
  one.roomOverlap = score.roomOverlapSum();
  one.roomPixels = score.roomPixelSum();
  one.segmentOverlap = score.segmentOverlapSum();
  one.segmentPixels = score.segmentPixelSum();
  one.objects = objects;
  return one;
}

void printHeader(bool hallways, bool truePoses, bool serverSet, double growM, double maxHoleM2) {
  std::printf("# %s\n", serverSet ? "SERVER SET: the Simulator, ScanMapper, GatewayDetection and RG Mapping Kernel "
                                   "modules map online"
                                 : "in process: the modules' algorithms chained in this program");
  std::printf("# room tour in the simulator -> ScanMapper (odometry-noised scans) -> GatewayDetector (%s)\n"
              "# -> RG Mapping Kernel, poses revised after SLAM optimisations and at the end; region freespace\n"
              "# on the floor plan's free pixels, grown %.2f m into free pixels no region claims (RegionGrowth.h),\n"
              "# with the holes up to %.1f m^2 it encloses (furniture standing free, RegionHoles.h)\n"
              "# vs. the GT rooms (benchmark metric: per-room recall, per-region precision, regions <= 100 px\n"
              "# dropped). tour: rooms visited/planned; pose_m: mean/max distance of\n"
              "# the final corrected positions from the true ones (map frame aligned at the first scan); losses:\n"
              "# mean room shares (ceiling: free in the furnished map and reachable, covered by any region, best\n"
              "# region) and shares of region pixels outside their best room (ScoreBreakdown.h)%s\n",
              hallways ? "narrow passages + hallway gateways" : "narrow passages only, no HMM file", growM,
              maxHoleM2, truePoses ? "\n# TRUE POSES: the kernel gets the true pose of every scan, SLAM is not run" : "");
  std::printf("%-26s %5s %7s %8s %11s %6s %7s | %6s %9s %7s %9s | %7s %9s %5s\n", "map", "rooms", "regions",
              "gateways", "neutralised", "scans", "scans/s", "recall", "precision", "rec_px", "prec_px", "tour",
              "pose_m", "time");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> maps;
  Options options;
  try {
    options.setup.pipeline = shippedPipelineConfig();
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-rooms: " << e.what() << std::endl;
    return 2;
  }
  const MappingPipelineConfig shipped = options.setup.pipeline;
  NarrowPassageConfig& passages = options.setup.pipeline.gateways.passages;
  po::options_description desc("rgnav-eval-rooms <X_furnitures.png>... [options]");
  desc.add_options()
      ("help", "this text")
      ("map", po::value(&maps)->required()->multitoken(), "furnished IPA floor plans (X_furnitures.png)")
      ("out", po::value(&options.outDir)->default_value(options.outDir), "folder for <map>_rooms.png")
      ("list", po::bool_switch(&options.list), "print every room, region and gateway with its match")
      ("region-pictures", po::bool_switch(&options.regionPictures),
       "also write <map>_region<N>.png per region, with its scans' true positions")
      ("grow", po::value(&options.growM)->default_value(options.growM, shown(options.growM)),
       "regions grow this far over free pixels no region claims, m (RegionPixels.h)")
      ("max-hole", po::value(&options.maxHoleM2)->default_value(options.maxHoleM2, shown(options.maxHoleM2)),
       "regions take the holes they enclose up to this size, m^2 (furniture standing free; RegionHoles.h)")
      ("models", po::value(&options.models)->default_value(options.models),
       "trained HMM file; used if it exists (else narrow passages only)")
      ("hallway-width", po::value(&options.setup.pipeline.gateways.hallways.hypotheses.hallwayWidthM)
           ->default_value(options.setup.pipeline.gateways.hallways.hypotheses.hallwayWidthM, shown(options.setup.pipeline.gateways.hallways.hypotheses.hallwayWidthM)),
       "expected hallway width d_hw in m (hallway gateways)")
      ("max-door-width", po::value(&passages.maxDoorWidthM)->default_value(passages.maxDoorWidthM, shown(passages.maxDoorWidthM)),
       "narrow passages: D_lr^max in m")
      ("min-jamb", po::value(&passages.minJambLengthM)->default_value(passages.minJambLengthM, shown(passages.minJambLengthM)),
       "narrow passages: shortest surface a gateway point bounds, m")
      ("min-support", po::value(&options.setup.pipeline.gateways.passageTracking.minSupport)
           ->default_value(options.setup.pipeline.gateways.passageTracking.minSupport),
       "narrow passages: scans before a tracked passage is a gateway")
      ("association", po::value(&options.setup.pipeline.gateways.passageTracking.associationDistanceM)
           ->default_value(options.setup.pipeline.gateways.passageTracking.associationDistanceM, shown(options.setup.pipeline.gateways.passageTracking.associationDistanceM)),
       "narrow passages: largest gateway-point distance of a hypothesis to its track, m")
      ("side-range", po::value(&options.setup.pipeline.kernel.sides.rangeM)
           ->default_value(options.setup.pipeline.kernel.sides.rangeM, shown(options.setup.pipeline.kernel.sides.rangeM)),
       "kernel: farthest robot distance from a crossing point that decides its side, m")
      ("door-frame", po::value(&options.setup.pipeline.kernel.models.doorFrames.depthM)
           ->default_value(options.setup.pipeline.kernel.models.doorFrames.depthM, shown(options.setup.pipeline.kernel.models.doorFrames.depthM)),
       "kernel: beams are also cut this far beyond a region's own doors, m")
      ("door-frame-widen", po::value(&options.setup.pipeline.kernel.models.doorFrames.widenM)
           ->default_value(options.setup.pipeline.kernel.models.doorFrames.widenM, shown(options.setup.pipeline.kernel.models.doorFrames.widenM)),
       "kernel: ... along a line this much longer than the door at each end, m")
      ("sim-config", po::value(&options.simConfig), "simulator parameters (config/sim/*.yaml); default: built-in")
      ("seed", po::value(&options.setup.simulation.seed)->default_value(options.setup.simulation.seed),
       "simulation seed")
      ("server-set", po::bool_switch(&options.serverSet),
       "map online with the real server set (modules, omniNames, watchdog) instead of in process")
      ("true-poses", po::bool_switch(&options.setup.truePoses),
       "the kernel gets the true pose of every scan instead of SLAM's (what SLAM errors cost)")
      ("max-tour-s", po::value(&options.setup.maxTourSeconds)->default_value(options.setup.maxTourSeconds, shown(options.setup.maxTourSeconds)),
       "end each tour after this many simulated seconds (smoke runs)")
      ("split", po::value(&options.split)->default_value(options.split), "the IPA maps' tuning/check split");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    if (!options.simConfig.empty()) {
      const std::uint64_t seed = options.setup.simulation.seed;
      options.setup.simulation = loadSimulationConfig(options.simConfig);
      options.setup.simulation.seed = seed;
    }
    std::optional<HmmClassifier> classifier;
    if (std::filesystem::exists(options.models)) classifier = loadHmmModels(options.models);
    std::filesystem::create_directories(options.outDir);
    if (options.serverSet && inProcessOptionsGiven(options, shipped))
      throw ConfigError("--server-set runs every module with its shipped parameters: the detector and kernel options, "
                        "--true-poses, --max-tour-s, --list and --region-pictures need the in-process run");
    if (options.serverSet) testing::catchInterruptions();  // so that a stopped run removes its server set's directory
    printHeader(classifier.has_value(), options.setup.truePoses, options.serverSet, options.growM, options.maxHoleM2);
    const SplitTotals<Totals> bySet = evaluateMaps<Totals>(
        loadIpaSplit(options.split), maps, [&](const std::string& map) { return evaluate(map, options, classifier); });
    const Totals& totals = bySet.all;
    const auto n = double(std::max<std::size_t>(totals.maps, 1));
    std::printf("# scans=%zu mapping scans/s=%.0f\n", totals.scans,
                double(totals.scans) / std::max(totals.mappingSeconds, 1e-9));
    std::printf("# recall ceiling mean=%.3f: the share of each room's pixels that are free in the furnished map and\n"
                "# reachable by the tour; freespace alone covers no more (regions add only the furniture they\n"
                "# enclose; no region reaches a room the tour does not). furniture_share_mean=%.3f: the share\n"
                "# under furniture (free in X.png, not in X_furnitures.png)\n",
                totals.ceilingMeans / n, totals.furnitureMeans / n);
    std::printf("# objects=%zu on_furniture=%.3f furniture_found=%.3f (RG Map rectangles vs furniture blobs >= %d "
                "cells, ObjectScoring.h)\n", totals.objects.objects,
                ratio(totals.objects.onFurniture, totals.objects.objects),
                ratio(totals.objects.blobsFound, totals.objects.blobs), kMinFurnitureCells);
    const auto figures = [](const Totals& t) {
      return std::vector<Figure>{{"recall_mean", t.recallMean()},
                                 {"precision_mean", t.precisionMean()},
                                 {"recall_pooled", ratio(t.roomOverlap, t.roomPixels)},
                                 {"precision_pooled", ratio(t.segmentOverlap, t.segmentPixels)}};
    };
    std::printf("%s\n", splitFiguresLine("rooms_split", bySet, figures).c_str());
    std::printf("rooms: maps=%zu recall_mean=%.3f precision_mean=%.3f recall_pooled=%.3f precision_pooled=%.3f\n",
                totals.maps, totals.recallMean(), totals.precisionMean(),
                ratio(totals.roomOverlap, totals.roomPixels), ratio(totals.segmentOverlap, totals.segmentPixels));
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-rooms: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-rooms: " << e.what() << std::endl;
  }
  return 2;
}
