// rgnav-eval-objects: the 2D object evaluation of issue 4 ("rgctl eval objects") on furnished
// IPA floor plans X_furnitures.png. Ground truth: the furniture blobs (FurnitureTruth), less
// those no place the robot can reach sees (Visibility). The robot drives the room tour of
// rgnav-sim-tour in the simulator; its scans, at their TRUE poses, go through the detection
// pipeline (ObjectDetection.h); detections are matched to the blobs by grid IoU (Matching.h).
// Prints a row per map, where the errors come from (ErrorBreakdown), the figures pooled over the
// tuning and over the check maps of the IPA split (config/eval/ipa-split.yaml: objects2d_split: …
// precision_tuning=… recall_check=…) and, last,
//   objects2d: maps=… precision=… recall=…
// pooled over all maps. --debug-dir writes a PNG per map (DebugImage.h). Exit code 0 when every
// map was evaluated, whatever the figures.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#include "core/sim/LoadedWorld.h"
#include "core/sim/world/FloorPlan.h"
#include "tests/eval/objects/DebugImage.h"
#include "tests/eval/objects/ErrorBreakdown.h"
#include "tests/eval/objects/Matching.h"
#include "tests/eval/objects/ObjectDetection.h"
#include "tests/eval/objects/TourScans.h"
#include "tests/eval/objects/Visibility.h"
#include "tests/eval/split/IpaSplit.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  int minBlobCells = 1;
  double minIoU = 0.5;
  std::uint64_t seed = 1;
  std::string debugDir;
  std::string split = "config/eval/ipa-split.yaml";
};

// Counts of one map, or pooled over maps.
struct Totals {
  std::size_t blobs = 0, specks = 0, invisible = 0, truthObjects = 0, detections = 0, matches = 0;
  std::array<std::size_t, kDetectionKinds> detectionsByKind{}, matchesByKind{};
  ErrorBreakdown errors;

  void add(const Totals& o) {
    blobs += o.blobs;
    specks += o.specks;
    invisible += o.invisible;
    truthObjects += o.truthObjects;
    detections += o.detections;
    matches += o.matches;
    for (std::size_t k = 0; k < kDetectionKinds; ++k) {
      detectionsByKind[k] += o.detectionsByKind[k];
      matchesByKind[k] += o.matchesByKind[k];
    }
    errors += o.errors;
  }
};

double ratio(std::size_t a, std::size_t b) { return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b); }

std::size_t countExcluded(const FurnitureTruth& truth, Exclusion why) {
  return static_cast<std::size_t>(std::count_if(truth.blobs.begin(), truth.blobs.end(),
                                                [&](const FurnitureBlob& b) { return b.exclusion == why; }));
}

// The counts of one map.
Totals evaluate(const std::string& map, const Options& options) {
  const auto started = std::chrono::steady_clock::now();
  const LoadedWorld world = loadWorld(map);
  const IpaFiles files = ipaFilesOf(map);
  if (!world.truth) throw FileError(map + ": no ground-truth rooms beside it (" + files.truth + ")");
  FurnitureTruth truth = furnitureTruth(world.grid, loadFloorPlan(files.empty), options.minBlobCells);
  const TourScans tour = scanTour(world.grid, *world.truth, options.seed);
  markInvisible(truth, world.grid, tour.reachable, SimulationConfig{}.laser.maxRange);
  const DetectionSummary found = detectObjects(tour, world.grid);
  const MatchResult m = matchDetections(found.detections, truth, options.minIoU);
  const ErrorBreakdown errors = breakDownErrors(found.detections, m, truth, world.grid, found.hitCells);
  if (!options.debugDir.empty())
    writeDebugImage(options.debugDir + "/" + files.name + "_objects.png", world.grid, truth, found.detections, m,
                    found.hitCells);

  const std::size_t specks = countExcluded(truth, Exclusion::kSpeck);
  const std::size_t invisible = countExcluded(truth, Exclusion::kNotVisible);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("%-26s %2zu/%-2d %6zu %5zu %5zu | %5zu %5zu %5zu | %5zu %5zu %5zu %5zu | %5zu %9.3f %6.3f | %4.0fs\n",
              files.name.c_str(), tour.run.roomsVisited.size(), world.truth->roomCount, found.scans,
              found.keyScans, found.mapLines, truth.blobs.size(), specks + invisible, m.truthObjects,
              m.detectionsByKind[0], m.detectionsByKind[1], m.detectionsByKind[2], m.detections, m.matches,
              ratio(m.matches, m.detections), ratio(m.matches, m.truthObjects), seconds);
  std::fflush(stdout);
  Totals counts;
  counts.blobs = truth.blobs.size();
  counts.specks = specks;
  counts.invisible = invisible;
  counts.truthObjects = m.truthObjects;
  counts.detections = m.detections;
  counts.matches = m.matches;
  for (std::size_t k = 0; k < kDetectionKinds; ++k) {
    counts.detectionsByKind[k] = m.detectionsByKind[k];
    counts.matchesByKind[k] = m.matchesByKind[k];
  }
  counts.errors = errors;
  return counts;
}

void printSummary(const SplitTotals<Totals>& totals, std::size_t maps) {
  const Totals& t = totals.all;
  for (std::size_t k = 0; k < kDetectionKinds; ++k)
    std::printf("# %-9s detections=%zu matches=%zu precision=%.3f\n", kindName(static_cast<DetectionKind>(k)).c_str(),
                t.detectionsByKind[k], t.matchesByKind[k], ratio(t.matchesByKind[k], t.detectionsByKind[k]));
  const ErrorBreakdown& e = t.errors;
  std::printf("# GT blobs=%zu not counted: specks=%zu, seen from no reachable place=%zu; counted=%zu\n", t.blobs,
              t.specks, t.invisible, t.truthObjects);
  std::printf("# false detections=%zu: on a GT object with IoU too small=%zu, on the building=%zu, elsewhere=%zu\n",
              t.detections - t.matches, e.falseOnBlob, e.falseOnBuilding, e.falseElsewhere);
  std::printf("# missed GT objects=%zu: never hit by a beam of the tour=%zu, hit but not detected=%zu, "
              "detected with IoU too small=%zu\n",
              t.truthObjects - t.matches, e.missedUnseen, e.missedUndetected, e.missedPoorFit);
  const auto figures = [](const Totals& s) {
    return std::vector<Figure>{{"precision", ratio(s.matches, s.detections)},
                               {"recall", ratio(s.matches, s.truthObjects)}};
  };
  std::printf("%s\n", splitFiguresLine("objects2d_split", totals, figures).c_str());
  std::printf("objects2d: maps=%zu precision=%.3f recall=%.3f\n", maps, ratio(t.matches, t.detections),
              ratio(t.matches, t.truthObjects));
}

void printHeader(const Options& options) {
  std::printf(
      "# scans at their TRUE poses (object detection is evaluated, not SLAM); one line map per GT room\n"
      "# GT objects: 8-connected blobs occupied in X_furnitures.png, free in X.png (every table or chair leg, bin,\n"
      "# cabinet is one); not counted: blobs of < %d cells (specks), blobs no cell reachable by the 0.5 m robot\n"
      "# sees; a match needs grid IoU >= %.2f, one detection per blob\n",
      options.minBlobCells, options.minIoU);
  std::printf("%-26s %5s %6s %5s %5s | %5s %5s %5s | %5s %5s %5s %5s | %5s %9s %6s | %5s\n", "map", "rooms", "scans",
              "key", "lines", "blobs", "excl", "gt", "rect", "circ", "clust", "det", "match", "precision", "recall",
              "time");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> maps;
  Options options;
  po::options_description desc("rgnav-eval-objects <X_furnitures.png>... [options]");
  desc.add_options()
      ("help", "this text")
      ("map", po::value(&maps)->required()->multitoken(), "furnished IPA floor plans (X_furnitures.png)")
      ("debug-dir", po::value(&options.debugDir), "write <map>_objects.png here")
      ("min-blob-cells", po::value(&options.minBlobCells)->default_value(options.minBlobCells),
       "smaller ground-truth blobs are specks (not counted)")
      ("min-iou", po::value(&options.minIoU)->default_value(options.minIoU), "IoU for a match")
      ("seed", po::value(&options.seed)->default_value(options.seed), "simulation seed")
      ("split", po::value(&options.split)->default_value(options.split), "the IPA maps' tuning/check split");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    if (!options.debugDir.empty()) std::filesystem::create_directories(options.debugDir);
    printHeader(options);
    printSummary(evaluateMaps<Totals>(loadIpaSplit(options.split), maps,
                                      [&](const std::string& map) { return evaluate(map, options); }),
                 maps.size());
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-objects: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-objects: " << e.what() << std::endl;
  }
  return 2;
}
