// rgnav-eval-objects: the 2D object evaluation of issue 4 ("rgctl eval objects") on furnished
// IPA floor plans X_furnitures.png. Ground truth: the furniture blobs (FurnitureTruth). The
// robot drives the room tour of rgnav-sim-tour in the simulator; its scans, at their TRUE poses,
// go through the detection pipeline (ObjectDetection.h); detections are matched to the blobs
// by grid IoU (Matching.h). Prints a row per map and, last,
//   objects2d: maps=… precision=… recall=…
// pooled over all maps. --debug-dir writes a PNG per map (DebugImage.h).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/sim/LoadedWorld.h"
#include "core/sim/world/FloorPlan.h"
#include "tests/eval/objects/DebugImage.h"
#include "tests/eval/objects/Matching.h"
#include "tests/eval/objects/ObjectDetection.h"
#include "tests/eval/objects/TourScans.h"
#include "tests/eval/objects/Visibility.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  int minBlobCells = 2;
  double minIoU = 0.5;
  std::uint64_t seed = 1;
  std::string debugDir;
};

struct Totals {
  std::size_t blobs = 0, specks = 0, invisible = 0, unseen = 0;
  MatchResult match;  // counts only
};

double ratio(std::size_t a, std::size_t b) { return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b); }

void add(Totals& totals, const FurnitureTruth& truth, std::size_t unseen, const MatchResult& m) {
  totals.blobs += truth.blobs.size();
  for (const FurnitureBlob& b : truth.blobs) {
    totals.specks += b.exclusion == Exclusion::kSpeck;
    totals.invisible += b.exclusion == Exclusion::kNotVisible;
  }
  totals.unseen += unseen;
  totals.match.truthObjects += m.truthObjects;
  totals.match.detections += m.detections;
  totals.match.matches += m.matches;
  for (std::size_t k = 0; k < kDetectionKinds; ++k) {
    totals.match.detectionsByKind[k] += m.detectionsByKind[k];
    totals.match.matchesByKind[k] += m.matchesByKind[k];
  }
}

// Counted blobs no scan point of the tour landed in.
std::size_t unseenBlobs(const FurnitureTruth& truth, const std::vector<bool>& hitCells) {
  std::size_t unseen = 0;
  for (const FurnitureBlob& b : truth.blobs)
    if (b.exclusion == Exclusion::kNone &&
        std::none_of(b.cells.begin(), b.cells.end(), [&](std::size_t c) { return hitCells[c]; }))
      ++unseen;
  return unseen;
}

void evaluate(const std::string& map, const Options& options, Totals& totals) {
  const auto started = std::chrono::steady_clock::now();
  const LoadedWorld world = loadWorld(map);
  if (!world.truth) throw FileError(map + ": no ground-truth rooms beside it (" + ipaFilesOf(map).truth + ")");
  const IpaFiles files = ipaFilesOf(map);
  FurnitureTruth truth = furnitureTruth(world.grid, loadFloorPlan(files.empty), options.minBlobCells);
  const TourScans tour = scanTour(world.grid, *world.truth, options.seed);
  markInvisible(truth, world.grid, tour.reachable, SimulationConfig{}.laser.maxRange);
  const DetectionSummary found = detectObjects(tour, world.grid);
  std::vector<std::vector<std::size_t>> footprints;
  for (const Detection& d : found.detections) footprints.push_back(footprint(d, world.grid));
  const MatchResult m = matchDetections(found.detections, footprints, truth, options.minIoU);
  const std::size_t unseen = unseenBlobs(truth, found.hitCells);
  add(totals, truth, unseen, m);
  Totals row;
  add(row, truth, unseen, m);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("%-26s %5zu %6zu %9zu %6zu %6zu | %5zu %5zu %5zu %5zu | %5zu %9.3f %6.3f | %6zu %4.0fs\n",
              files.name.c_str(), row.blobs, row.specks, row.invisible, m.truthObjects, unseen,
              m.detectionsByKind[0], m.detectionsByKind[1], m.detectionsByKind[2], m.detections, m.matches,
              ratio(m.matches, m.detections), ratio(m.matches, m.truthObjects), found.scans, seconds);
  if (!options.debugDir.empty())
    writeDebugImage(options.debugDir + "/" + files.name + "_objects.png", world.grid, truth, footprints, m);
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
      ("seed", po::value(&options.seed)->default_value(options.seed), "simulation seed");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    if (!options.debugDir.empty()) std::filesystem::create_directories(options.debugDir);
    std::printf("# scans at their TRUE poses (object detection is evaluated, not SLAM); one line map per GT room\n");
    std::printf("# GT objects: 8-connected blobs occupied in X_furnitures.png, free in X.png; not counted: blobs of\n"
                "# < %d cells (specks) and blobs no cell reachable by the 0.5 m robot sees; a match needs IoU >= %.2f\n",
                options.minBlobCells, options.minIoU);
    std::printf("%-26s %5s %6s %9s %6s %6s | %5s %5s %5s %5s | %5s %9s %6s | %6s %5s\n", "map", "blobs", "specks",
                "invisible", "gt", "unseen", "rect", "circ", "clust", "det", "match", "precision", "recall", "scans",
                "time");
    Totals totals;
    for (const std::string& map : maps) evaluate(map, options, totals);
    const MatchResult& m = totals.match;
    for (std::size_t k = 0; k < kDetectionKinds; ++k)
      std::printf("# %-9s detections=%zu matches=%zu precision=%.3f\n",
                  kindName(static_cast<DetectionKind>(k)).c_str(), m.detectionsByKind[k], m.matchesByKind[k],
                  ratio(m.matchesByKind[k], m.detectionsByKind[k]));
    std::printf("# GT blobs=%zu specks=%zu invisible=%zu counted=%zu (never hit by a beam of the tour: %zu)\n",
                totals.blobs, totals.specks, totals.invisible, m.truthObjects, totals.unseen);
    std::printf("objects2d: maps=%zu precision=%.3f recall=%.3f\n", maps.size(), ratio(m.matches, m.detections),
                ratio(m.matches, m.truthObjects));
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-objects: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-objects: " << e.what() << std::endl;
  }
  return 2;
}
