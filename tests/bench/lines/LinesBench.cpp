// rgnav-bench-lines: figures of the line map and 2D object algorithms (thesis 3.1, 3.1.1, 5.2):
//   compression         valid scan points / merged lines of a region line map built
//                       incrementally from consecutive scans of a real log at their corrected
//                       poses (default: Intel Research Lab, corrected keyframes 215-244, a
//                       corridor corner and a small room; thesis figure 5.4: 5042 -> 38, ~50x);
//                       its addScan rate is printed too (--first 0 --scans 910: the whole log)
//   merge_us_per_line   one batch merge (3.1.1, thesis laser parameters) of all segments
//                       extracted from those scans, median time per input segment
//   grouping_speedup    naive C(N,4) search time / two-stage search time on the same synthetic
//                       line map of N lines (boxes among clutter), both in this run; the two
//                       must give the same hypotheses or the program fails
//   region_map_scans_per_s
//                       RegionLineMap::addScan throughput (extraction and merging, 5.2) over a
//                       long region: region_map_scans synthetic scans (default 3000, 1 cm range
//                       noise) of a 100 m hallway driven to its far end and back; also given
//                       for the first and last tenth of the scans, which differ when the cost
//                       per scan grows with the map, with the merge candidates per scan
// Last line: lines: compression=… merge_us_per_line=… grouping_speedup=… region_map_scans=…
//            region_map_scans_per_s=…
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <numeric>

#include "core/common/Errors.h"
#include "core/lines/RegionLineMap.h"
#include "core/lines/testing/SyntheticHallway.h"
#include "core/logs/LogTestFiles.h"
#include "core/logs/OpenLog.h"
#include "core/objects/QuadrangleGrouping.h"
#include "core/objects/testing/SyntheticLines.h"
#include "tools/common/CommandLine.h"
#include "tests/support/Statistics.h"

namespace po = boost::program_options;
using namespace rgnav;
using rgnav::testing::median;
using Clock = std::chrono::steady_clock;

namespace {

template <class F>
double seconds(F&& f) {
  const auto start = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The scans with IDs first .. first + count - 1 of the log.
std::vector<LaserScan> readScans(const std::string& path, DataId first, std::size_t count) {
  const auto log = openLog(path);
  std::vector<LaserScan> scans;
  while (scans.size() < count) {
    const auto record = log->next();
    if (!record) throw NotAvailableError(path + ": fewer than " + std::to_string(first + count - 1) + " scans");
    if (const auto* scan = std::get_if<LaserScan>(&*record); scan != nullptr && scan->id >= first)
      scans.push_back(*scan);
  }
  return scans;
}

bool sameHypotheses(const std::vector<Quadrangle>& a, const std::vector<Quadrangle>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const Quadrangle& x, const Quadrangle& y) { return x.sides == y.sides; });
}

}  // namespace

int main(int argc, char** argv) {
  std::string log = testing::sharedData("laser/corrected/intel-corrected.log.gz");
  DataId first = 215;
  std::size_t scanCount = 30, lineCount = 200, repeats = 200, hallwayScans = 3000;
  double hallwayM = 100.0;
  unsigned seed = 1;
  po::options_description options("rgnav-bench-lines: line map compression, merge time, grouping speed-up");
  // clang-format off
  options.add_options()
      ("help", "this text")
      ("log", po::value(&log)->default_value(log), "CARMEN log with corrected poses")
      ("first", po::value(&first)->default_value(first), "ID of the first scan of the region")
      ("scans", po::value(&scanCount)->default_value(scanCount), "number of consecutive scans")
      ("lines", po::value(&lineCount)->default_value(lineCount), "N, lines in the grouping comparison")
      ("seed", po::value(&seed)->default_value(seed), "seed of the synthetic line map")
      ("repeats", po::value(&repeats)->default_value(repeats), "timed runs of merge and two-stage grouping")
      ("hallway", po::value(&hallwayM)->default_value(hallwayM), "length of the synthetic hallway region (m)")
      ("hallway-scans", po::value(&hallwayScans)->default_value(hallwayScans), "scans added to the hallway region map");
  // clang-format on
  try {
    if (!parseCommandLine(argc, argv, options)) return 0;
    if (scanCount == 0 || lineCount < 4 || repeats == 0 || hallwayScans < 10)
      throw InvalidArgumentError("need --scans >= 1, --lines >= 4, --repeats >= 1, --hallway-scans >= 10");

    // Compression of an incrementally built region line map.
    const auto scans = readScans(log, first, scanCount);
    RegionLineMap map;
    const double buildTime = seconds([&] {
      for (const auto& scan : scans) map.addScan(scan, scan.sensorPose);
    });
    const double compression = double(map.pointCount()) / double(std::max<std::size_t>(1, map.lines().size()));
    std::cout << "region: " << std::filesystem::path(log).filename().string() << " scans " << first << "-"
              << first + scanCount - 1 << " at their corrected poses: " << map.pointCount() << " points -> "
              << map.segmentCount() << " scan segments -> " << map.lines().size() << " lines (" << std::setprecision(0)
              << std::fixed << double(scanCount) / std::max(1e-12, buildTime) << " scans/s)\n"
              << std::defaultfloat << std::setprecision(6);

    // One batch merge of all segments of those scans.
    std::vector<LineSegment> segments;
    const LineExtractor extractor;
    for (const auto& scan : scans) {
      auto some = extractor.extract(scan, scan.sensorPose, segments.size() + 1);
      segments.insert(segments.end(), some.begin(), some.end());
    }
    const LineMerger merger;
    std::vector<double> mergeTimes;
    std::size_t merged = 0;
    for (std::size_t r = 0; r < repeats; ++r) {
      auto input = segments;
      mergeTimes.push_back(seconds([&] { merged = merger.merge(std::move(input)).size(); }));
    }
    const double mergeUsPerLine = 1e6 * median(mergeTimes) / double(std::max<std::size_t>(1, segments.size()));
    std::cout << "merge: " << segments.size() << " segments -> " << merged << " lines in one batch, median of "
              << repeats << " runs\n";

    // Two-stage against naive grouping on the same lines.
    const auto lines = testing::syntheticLineMap(lineCount, seed);
    const QuadrangleGrouping grouping;
    std::vector<Quadrangle> fast, slow;
    std::vector<double> fastTimes;
    for (std::size_t r = 0; r < repeats; ++r) fastTimes.push_back(seconds([&] { fast = grouping.twoStage(lines); }));
    const double slowTime = seconds([&] { slow = grouping.naive(lines); });
    if (!sameHypotheses(fast, slow)) {
      std::cerr << "rgnav-bench-lines: two-stage and naive grouping disagree (" << fast.size() << " vs " << slow.size()
                << " hypotheses)\n";
      return 1;
    }
    const double speedup = slowTime / std::max(1e-12, median(fastTimes));
    std::cout << "grouping: N=" << lineCount << " synthetic lines (seed " << seed << "), " << fast.size()
              << " hypotheses from both; two-stage " << std::setprecision(3) << 1e3 * median(fastTimes)
              << " ms (median of " << repeats << "), naive C(N,4) " << slowTime << " s\n";

    // addScan throughput on a long region, per scan so that growth with the map shows.
    testing::ScanSpec laser;
    laser.noiseSigmaM = 0.01;
    const auto hallway = testing::hallwayScans(hallwayM, hallwayScans, laser);
    RegionLineMap hallwayMap;
    std::vector<double> addTimes;
    for (const auto& scan : hallway) addTimes.push_back(seconds([&] { hallwayMap.addScan(scan, scan.sensorPose); }));
    const std::size_t tenth = addTimes.size() / 10;
    const auto scansPerSecond = [&](std::size_t from, std::size_t to) {
      return double(to - from) / std::accumulate(addTimes.begin() + from, addTimes.begin() + to, 1e-12);
    };
    const double regionScansPerS = scansPerSecond(0, addTimes.size());
    std::cout << std::setprecision(0) << std::fixed << "region map: synthetic hallway " << hallwayM << " m, "
              << hallwayScans << " scans to its end and back -> " << hallwayMap.segmentCount() << " scan segments -> "
              << hallwayMap.lines().size() << " lines; addScan " << regionScansPerS << " scans/s, first " << tenth
              << " scans " << scansPerSecond(0, tenth) << " scans/s, last " << tenth << " scans "
              << scansPerSecond(addTimes.size() - tenth, addTimes.size()) << " scans/s; " << std::setprecision(1)
              << double(hallwayMap.mergeCandidateCount()) / double(hallwayScans) << " merge candidates per scan\n";

    std::cout << std::fixed << std::setprecision(1) << "lines: compression=" << compression
              << " merge_us_per_line=" << std::setprecision(2) << mergeUsPerLine
              << " grouping_speedup=" << std::setprecision(0) << speedup << " region_map_scans=" << hallwayScans
              << " region_map_scans_per_s=" << regionScansPerS << std::endl;
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-bench-lines: " << e.what() << "\n";
    return 1;
  }
}
