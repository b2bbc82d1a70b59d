// rgnav-eval-slam: runs the SLAM core (core/slam ScanMapper) in-process on a log of
// data/laser/ and scores the corrected poses with the relative-pose metric of Kümmerle et al.
// 2009 against a relations file (relations whose both stamps match scans), or, if none match,
// against relations derived from the log's own (corrected) trajectory. Raw odometry and, for
// relation files, the log's own poses are scored the same way. With --odometry-noise the log's
// odometry is first replaced by its corrected poses plus seeded odometry noise.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/config/ShippedConfig.h"
#include "core/logs/OpenLog.h"
#include "core/slam/ScanMapper.h"
#include "core/slam/SlamConfigYaml.h"
#include "core/slam/eval/OdometryNoise.h"
#include "core/slam/eval/Relations.h"
#include "core/slam/eval/RelativePoseMetric.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;

namespace {

struct Options {
  std::string log;
  std::string config = rgnav::shippedConfigFile("modules/scanmapper.yaml");
  std::string relations;
  std::string corrected;
  std::string posesOut;
  std::optional<std::uint64_t> noiseSeed;
  std::size_t maxScans = 0;
  double stampOffset = 0.0;
  double stampTolerance = 0.002;
};

struct Relations {
  std::vector<rgnav::ScanRelation> relations;
  bool fromFile = false;
  std::string source;
};

struct Timing {
  double wallSeconds = 0.0;
  double cpuSeconds = 0.0;
};

std::string formatError(const rgnav::RelativePoseError& e) {
  char text[160];
  std::snprintf(text, sizeof text, "relations=%zu trans_err_m=%.4f±%.4f rot_err_deg=%.3f±%.3f", e.relations,
                e.translationMean, e.translationStd, e.rotationMean * 180.0 / M_PI, e.rotationStd * 180.0 / M_PI);
  return text;
}

std::vector<rgnav::LaserScan> readScans(const Options& options) {
  rgnav::LogReaderOptions readerOptions;
  readerOptions.correctedPosesPath = options.corrected;
  return rgnav::readLaserScans(options.log, readerOptions, options.maxScans);
}

void addOdometryNoise(std::vector<rgnav::LaserScan>& scans, std::uint64_t seed) {
  std::vector<rgnav::Pose2D> reference;
  for (const auto& scan : scans) reference.push_back(scan.sensorPose);
  const rgnav::OdometryNoiseConfig noise;
  const auto odometry = rgnav::noisyOdometry(reference, noise, seed);
  for (std::size_t i = 0; i < scans.size(); ++i) scans[i].odometry = odometry[i];
  std::cout << "odometry: the log's poses plus noise, seed " << seed << ", " << noise.translationPerSqrtMetre
            << " m/sqrt(m), " << noise.rotationPerSqrtMetre << " rad/sqrt(m), " << noise.rotationPerSqrtRadian
            << " rad/sqrt(rad)\n";
}

Timing run(rgnav::ScanMapper& mapper, const std::vector<rgnav::LaserScan>& scans) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t startCpu = std::clock();
  for (const auto& scan : scans) mapper.addScan(scan);
  mapper.optimize();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
          static_cast<double>(std::clock() - startCpu) / CLOCKS_PER_SEC};
}

void writePoses(const std::string& path, const rgnav::ScanMapper& mapper, const std::vector<rgnav::LaserScan>& scans) {
  std::ofstream out(path);
  out.precision(17);
  for (const auto& scan : scans) {
    const rgnav::Pose2D p = mapper.correctedPose(scan.id);
    out << scan.id << ' ' << scan.stamp << ' ' << p.x << ' ' << p.y << ' ' << p.theta << '\n';
  }
  if (!out.flush()) throw rgnav::FileError("cannot write " + path);
}

Relations chooseRelations(const Options& options, const std::vector<rgnav::LaserScan>& scans) {
  if (!options.relations.empty()) {
    std::vector<rgnav::StampedScan> stamps;
    for (const auto& scan : scans) stamps.push_back({scan.id, scan.stamp});
    auto matched = rgnav::matchRelations(rgnav::readRelations(options.relations), stamps, options.stampOffset,
                                         options.stampTolerance);
    if (!matched.empty()) return {std::move(matched), true, std::filesystem::path(options.relations).filename().string()};
    std::cout << "no relation of " << options.relations << " matches two scans\n";
  }
  std::vector<rgnav::TrajectoryPose> reference;
  for (const auto& scan : scans) reference.push_back({scan.id, scan.stamp, scan.sensorPose});
  return {rgnav::relationsFromTrajectory(reference), false, "derived from the log's (corrected) trajectory"};
}

void report(const Options& options, const rgnav::ScanMapper& mapper, const std::vector<rgnav::LaserScan>& scans,
            const Timing& timing) {
  const Relations chosen = chooseRelations(options, scans);
  std::map<rgnav::DataId, const rgnav::LaserScan*> byId;
  for (const auto& scan : scans) byId[scan.id] = &scan;
  const auto score = [&](const auto& pose) { return formatError(rgnav::relativePoseError(chosen.relations, pose)); };
  const std::string name = std::filesystem::path(options.log).filename().string();
  const auto& state = mapper.state();
  std::cout << "relations: " << chosen.source << "\n"
            << "scans=" << scans.size() << " keyframes=" << state.keyframes.size()
            << " loop_constraints=" << state.counters.loopClosures << " optimizations=" << state.counters.optimizations
            << " odometry_only_keyframes=" << state.counters.failedRegistrations << " seconds=" << timing.wallSeconds
            << " cpu_seconds=" << timing.cpuSeconds << "\n";
  if (chosen.fromFile)
    std::cout << "log poses " << name << ": " << score([&](rgnav::DataId id) { return byId.at(id)->sensorPose; }) << "\n";
  std::cout << "odometry " << name << ": " << score([&](rgnav::DataId id) { return byId.at(id)->odometry; }) << "\n";
  char throughput[64];
  std::snprintf(throughput, sizeof throughput, " scans_per_s=%.1f", static_cast<double>(scans.size()) / timing.wallSeconds);
  std::cout << "slam " << name << ": " << score([&](rgnav::DataId id) { return mapper.correctedPose(id); })
            << throughput << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  po::options_description desc(
      "rgnav-eval-slam <log> [--relations file] [--odometry-noise seed] [--corrected file] [--max-scans N]");
  desc.add_options()
      ("help", "this text")
      ("log", po::value(&options.log)->required(), "CARMEN or Intel JSON log")
      ("config", po::value(&options.config)->default_value(options.config), "ScanMapper parameters")
      ("relations", po::value(&options.relations), "SLAM benchmark relations file")
      ("odometry-noise", po::value<std::uint64_t>()->notifier([&](std::uint64_t s) { options.noiseSeed = s; }),
       "replace the odometry by the log's poses plus noise drawn with this seed")
      ("corrected", po::value(&options.corrected), "Intel JSON: the corrected-pose companion file")
      ("max-scans", po::value(&options.maxScans), "process only the first N scans (0: all)")
      ("stamp-offset", po::value(&options.stampOffset)->default_value(0.0),
       "s added to the scan stamps to give relation stamps (976052857.3373 for corrected/intel-corrected.log.gz)")
      ("stamp-tolerance", po::value(&options.stampTolerance)->default_value(0.002),
       "s between a relation stamp and its scan (2 ms: the figures quoted in issue 5)")
      ("poses-out", po::value(&options.posesOut), "write 'id stamp x y theta' of every corrected pose to this file");
  po::positional_options_description positional;
  positional.add("log", 1);
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc, positional)) return 0;
    std::vector<rgnav::LaserScan> scans = readScans(options);
    if (options.noiseSeed) addOdometryNoise(scans, *options.noiseSeed);
    rgnav::ScanMapper mapper(rgnav::loadSlamConfig(options.config));
    const Timing timing = run(mapper, scans);
    if (!options.posesOut.empty()) writePoses(options.posesOut, mapper, scans);
    report(options, mapper, scans, timing);
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-slam: " << e.what() << "\n" << desc << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-slam: " << e.what() << std::endl;
    return 1;
  }
}
