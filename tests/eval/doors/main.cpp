// rgnav-eval-doors: the narrow-passage evaluation of issue 6 ("rgctl eval doors") on furnished
// IPA floor plans X_furnitures.png. The robot drives the room tour of rgnav-sim-tour in the
// simulator; the NarrowPassageDetector (thesis 4.2.1) and the PassageTracker run on its scans at
// their TRUE poses (TourPassages.h: detection is scored, not SLAM); the confirmed gateways are
// matched to the ground-truth door lines by midpoint distance (DoorMatching.h), counting only
// the lines DoorTruth.h accepts as doors. A second score keeps only what an RG map would hold
// (thesis table 6.1): the gateways the robot traversed against the counted doors it crossed.
// Prints a row per map, the same figures pooled over the tuning and over the check maps of the
// IPA split (config/eval/ipa-split.yaml: doors_laser_split: … precision_tuning=… recall_check=…)
// and, last,
//   doors_laser: precision=… recall=…
// pooled over all maps. --list-doors prints every GT line with its class and match,
// --list-gateways every confirmed gateway with its outcome, --debug-dir writes a picture per
// map (DebugImage.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#include "core/config/ShippedConfig.h"
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/world/FloorPlan.h"
#include "tests/eval/doors/DebugImage.h"
#include "tests/eval/doors/DoorMatching.h"
#include "tests/eval/doors/DoorTruth.h"
#include "tests/eval/doors/TourPassages.h"
#include "tests/eval/split/IpaSplit.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

struct Options {
  TourDetectionSetup setup;
  DoorRule rule;
  double matchDistanceM = 0.5;
  bool listDoors = false;
  bool listGateways = false;
  std::string debugDir;
  std::string split = "config/eval/ipa-split.yaml";
};

struct Counts {
  std::size_t lines = 0, notBetweenRooms = 0, unreachable = 0, notNarrow = 0, notApproached = 0;
  DoorMatch all, traversed;  // counts only
  std::size_t gateways = 0, traversedGateways = 0, scans = 0, hypotheses = 0, traversals = 0;

  void add(const Counts& o) {
    lines += o.lines;
    notBetweenRooms += o.notBetweenRooms;
    unreachable += o.unreachable;
    notNarrow += o.notNarrow;
    notApproached += o.notApproached;
    for (auto [mine, theirs] : {std::pair{&all, &o.all}, std::pair{&traversed, &o.traversed}}) {
      mine->doors += theirs->doors;
      mine->detections += theirs->detections;
      mine->matches += theirs->matches;
    }
    gateways += o.gateways;
    traversedGateways += o.traversedGateways;
    scans += o.scans;
    hypotheses += o.hypotheses;
    traversals += o.traversals;
  }
};

double ratio(std::size_t a, std::size_t b) { return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b); }

std::size_t countExcluded(const std::vector<TruthDoor>& doors, DoorExclusion exclusion) {
  return static_cast<std::size_t>(
      std::count_if(doors.begin(), doors.end(), [&](const TruthDoor& d) { return d.exclusion == exclusion; }));
}

const char* outcomeName(DetectionOutcome o) {
  return o == DetectionOutcome::kMatch ? "match" : o == DetectionOutcome::kFalse ? "false" : "ignored";
}

void listDoors(const std::vector<TruthDoor>& doors, const std::vector<Eigen::Vector2d>& midpoints, const DoorMatch& m) {
  for (std::size_t d = 0; d < doors.size(); ++d) {
    const TruthDoor& door = doors[d];
    const int k = m.detectionOfDoor[d];
    std::printf("#   line %2zu at (%6.2f, %6.2f) width %.2f m, rooms %2d|%2d, beside %5.2f|%5.2f m%s: %-17s %s", d,
                door.midpoint.x(), door.midpoint.y(), door.widthM, door.line.roomA, door.line.roomB,
                door.sideWidthM[0], door.sideWidthM[1], door.traversed ? ", crossed" : "",
                exclusionName(door.exclusion).c_str(), k >= 0 ? "matched" : "-");
    if (k >= 0) std::printf(" (%.2f m)", (midpoints[static_cast<std::size_t>(k)] - door.midpoint).norm());
    std::printf("\n");
  }
}

void listGateways(const std::vector<TrackedGateway>& gateways, const std::vector<TruthDoor>& doors, const DoorMatch& m) {
  for (std::size_t k = 0; k < gateways.size(); ++k) {
    const TrackedGateway& g = gateways[k];
    std::printf("#   gateway %3zu (%6.2f, %6.2f)-(%6.2f, %6.2f) width %.2f m, support %4zu, confidence %.2f, "
                "traversals %zu: %-7s",
                static_cast<std::size_t>(g.id.value()), g.right.x(), g.right.y(), g.left.x(), g.left.y(), g.widthM(),
                g.support, g.meanConfidence, g.traversals, outcomeName(m.outcomes[k]));
    const auto nearest = std::min_element(doors.begin(), doors.end(), [&](const TruthDoor& a, const TruthDoor& b) {
      return (a.midpoint - g.midpoint()).norm() < (b.midpoint - g.midpoint()).norm();
    });
    if (nearest != doors.end())
      std::printf(" nearest GT line %td at %.2f m", nearest - doors.begin(), (nearest->midpoint - g.midpoint()).norm());
    std::printf("\n");
  }
}

Counts evaluate(const std::string& map, const Options& options) {
  const auto started = std::chrono::steady_clock::now();
  const LoadedWorld world = loadWorld(map);
  if (!world.truth) throw FileError(map + ": no ground-truth rooms beside it (" + ipaFilesOf(map).truth + ")");
  const IpaFiles files = ipaFilesOf(map);
  const TourPassages found = detectAlongTour(world.grid, *world.truth, options.setup);
  const std::vector<TruthDoor> doors =
      doorTruth(*world.truth, loadFloorPlan(files.empty), found.unreachableRooms, found.path, options.rule);
  std::vector<Eigen::Vector2d> midpoints, traversedMidpoints;
  for (const TrackedGateway& g : found.gateways) {
    midpoints.push_back(g.midpoint());
    if (g.traversals > 0) traversedMidpoints.push_back(g.midpoint());
  }
  const DoorMatch all = matchDoors(doors, midpoints, options.matchDistanceM);
  Counts row;
  row.lines = doors.size();
  row.notBetweenRooms = countExcluded(doors, DoorExclusion::kNotBetweenRooms);
  row.unreachable = countExcluded(doors, DoorExclusion::kUnreachable);
  row.notNarrow = countExcluded(doors, DoorExclusion::kNotNarrow);
  row.notApproached = countExcluded(doors, DoorExclusion::kNotApproached);
  row.all = all;
  row.traversed = matchDoors(doors, traversedMidpoints, options.matchDistanceM, /*traversedOnly=*/true);
  row.gateways = midpoints.size();
  row.traversedGateways = traversedMidpoints.size();
  row.scans = found.scansDetected;
  row.hypotheses = found.hypotheses;
  row.traversals = found.traversals;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("%-26s %5zu %7zu %4zu %5zu %4zu %5zu | %8zu %7zu %5zu %6zu %9.3f %6.3f | %5zu %5zu %5zu %9.3f | %6zu %4.0fs\n",
              files.name.c_str(), row.lines, row.notBetweenRooms, row.notNarrow, row.unreachable, row.notApproached,
              all.doors, row.gateways, row.gateways - all.detections, all.matches, all.doors - all.matches,
              ratio(all.matches, all.detections), ratio(all.matches, all.doors), row.traversed.doors,
              row.traversedGateways, row.traversed.matches, ratio(row.traversed.matches, row.traversed.detections),
              row.scans, seconds);
  if (options.listDoors) listDoors(doors, midpoints, all);
  if (options.listGateways) listGateways(found.gateways, doors, all);
  if (!options.debugDir.empty())
    writeDoorImage(options.debugDir + "/" + files.name + "_doors.png", world.grid, doors, found.gateways, all);
  return row;
}

void printHeader(const Options& options) {
  const NarrowPassageConfig& d = options.setup.detector;
  std::printf("# scans at their TRUE poses (detection is evaluated, not SLAM); detector on 1 of every %zu scans;\n"
              "# D_lr in (%.2f, %.2f) m, D_NP < %.1f m, alpha_NP >= %.0f deg, viewing directions every %.0f deg;\n"
              "# gateway points bound surfaces >= %.2f m, one a wall end continuing the line >= %.2f m;\n"
              "# a gateway: seen in %zu scans, hypotheses associated within %.2f m, not a wider twin (a point\n"
              "# within %.2f m of a narrower gateway's, within %.0f deg of its direction, >= %.2f times as wide)\n",
              options.setup.everyScans, minPassageWidthM(d), d.maxDoorWidthM, d.maxDistanceM,
              d.minApertureRad * 180.0 / M_PI, d.viewingStepRad * 180.0 / M_PI, d.minJambLengthM,
              d.minWallEndLengthM, options.setup.tracker.minSupport, options.setup.tracker.associationDistanceM,
              options.setup.tracker.sharedPointM, options.setup.tracker.twinMaxAngleRad * 180.0 / M_PI,
              options.setup.tracker.twinWidthFactor);
  std::printf("# GT doors: separator lines of X_gt_segmentation.png with two different rooms beside them (else\n"
              "# no-pair), door-like and a narrowing: at most %.1f m wide and narrower than %.0f %% of the free space\n"
              "# beside them, %.1f m off the line on X.png (else wide), both rooms reachable by the tour (else unrch)\n"
              "# and approached by the robot within %.1f m = D_NP^max (else far); a match: midpoints within %.2f m,\n"
              "# one to one; detections at unrch/far doors are ignored, all other unmatched detections are false.\n"
              "# traversed: only gateways the robot crossed vs. counted doors it crossed (an RG map's gateways)\n",
              options.rule.maxDoorWidthM, 100.0 * options.rule.narrowerFactor, options.rule.sideOffsetM,
              options.rule.approachM, options.matchDistanceM);
  std::printf("%-26s %5s %7s %4s %5s %4s %5s | %8s %7s %5s %6s %9s %6s | %5s %5s %5s %9s | %6s %5s\n", "", "GT",
              "", "", "", "", "", "all", "", "", "", "", "", "trav.", "", "", "", "", "");
  std::printf("%-26s %5s %7s %4s %5s %4s %5s | %8s %7s %5s %6s %9s %6s | %5s %5s %5s %9s | %6s %5s\n", "map",
              "lines", "no-pair", "wide", "unrch", "far", "doors", "gateways", "ignored", "match", "missed",
              "precision", "recall", "doors", "gatew", "match", "precision", "scans", "time");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> maps;
  Options options;
  try {  // the detector and tracker as the GatewayDetection module runs them (its shipped parameters)
    const GatewayDetectorConfig detection =
        loadGatewayDetectorConfig(shippedConfigFile("modules/gatewaydetection.yaml"));
    options.setup.detector = detection.passages;
    options.setup.tracker = detection.passageTracking;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-doors: " << e.what() << std::endl;
    return 2;
  }
  po::options_description desc("rgnav-eval-doors <X_furnitures.png>... [options]");
  desc.add_options()
      ("help", "this text")
      ("map", po::value(&maps)->required()->multitoken(), "furnished IPA floor plans (X_furnitures.png)")
      ("every", po::value(&options.setup.everyScans)->default_value(options.setup.everyScans),
       "run the detector on every n-th scan")
      ("min-support", po::value(&options.setup.tracker.minSupport)->default_value(options.setup.tracker.minSupport),
       "scans before a tracked passage is a gateway")
      ("min-jamb", po::value(&options.setup.detector.minJambLengthM)->default_value(options.setup.detector.minJambLengthM),
       "shortest surface a gateway point bounds, m")
      ("min-wall-end", po::value(&options.setup.detector.minWallEndLengthM)->default_value(options.setup.detector.minWallEndLengthM),
       "how far a wall end continues the gateway line, m")
      ("match-distance-m", po::value(&options.matchDistanceM)->default_value(options.matchDistanceM),
       "largest midpoint distance of a match")
      ("list-doors", po::bool_switch(&options.listDoors), "print every ground-truth line with its class and match")
      ("list-gateways", po::bool_switch(&options.listGateways), "print every confirmed gateway with its outcome")
      ("debug-dir", po::value(&options.debugDir), "write <map>_doors.png here")
      ("split", po::value(&options.split)->default_value(options.split), "the IPA maps' tuning/check split")
      ("seed", po::value(&options.setup.seed)->default_value(options.setup.seed), "simulation seed");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    if (!options.debugDir.empty()) std::filesystem::create_directories(options.debugDir);
    options.rule.approachM = options.setup.detector.maxDistanceM;
    printHeader(options);
    const SplitTotals<Counts> totals = evaluateMaps<Counts>(
        loadIpaSplit(options.split), maps, [&](const std::string& map) { return evaluate(map, options); });
    const Counts& total = totals.all;
    std::printf("# GT lines=%zu no-pair=%zu wide=%zu unreachable=%zu far=%zu counted=%zu; scans=%zu "
                "single-scan hypotheses=%zu traversal events=%zu\n",
                total.lines, total.notBetweenRooms, total.notNarrow, total.unreachable, total.notApproached,
                total.all.doors, total.scans, total.hypotheses, total.traversals);
    std::printf("# traversed: doors=%zu gateways=%zu matches=%zu precision=%.3f recall=%.3f (thesis table 6.1: RG maps)\n",
                total.traversed.doors, total.traversedGateways, total.traversed.matches,
                ratio(total.traversed.matches, total.traversed.detections),
                ratio(total.traversed.matches, total.traversed.doors));
    const auto figures = [](const Counts& c) {
      return std::vector<Figure>{{"precision", ratio(c.all.matches, c.all.detections)},
                                 {"recall", ratio(c.all.matches, c.all.doors)}};
    };
    std::printf("%s\n", splitFiguresLine("doors_laser_split", totals, figures).c_str());
    std::printf("doors_laser: precision=%.3f recall=%.3f\n", ratio(total.all.matches, total.all.detections),
                ratio(total.all.matches, total.all.doors));
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-doors: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-doors: " << e.what() << std::endl;
  }
  return 2;
}
