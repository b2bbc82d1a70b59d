// rgnav-eval-localization: the localization evaluation of issue 28 ("rgctl eval localization"):
// how well the region Monte Carlo localization (thesis 5.3, core/nav/localization RegionMcl)
// follows a real run in an RG map made of the same run.
//   1. The log's scans are read with their raw odometry; their corrected poses come from the log
//      itself (CARMEN corrected logs) or from another file of the same run (--corrected: the
//      Intel JSON companion, a CARMEN corrected log), matched by stamp within 1 ms
//      (StampedPoses.h); the program says how many matched and refuses to score too few. A log
//      without raw odometry (CARMEN corrected logs) gets odometry made from its corrected poses
//      with seeded four-alpha noise (--odometry-noise, core/sim/motion/OdometryNoiseModel).
//   2. The RG map is built in process from the corrected poses (tests/eval/rooms MappingPipeline
//      addScanAt: gateway detection on odometry -> RG Mapping Kernel with the given poses), and
//      its final regions and gateways (RgMapViews.h) become the localization map.
//   3. The filter starts at the first localized scan's corrected pose and follows the raw
//      odometry (LocalizationRun.h); each scan's estimate is compared with its corrected pose.
//      The same run on the global-map baseline (one likelihood field over the whole floor,
//      LocalizationMap::wholeFloor) is printed first, the region map's last:
//   localization <name> [global map]: scans=… trans_err_m=… … field_mib=…
//   localization <name>: scans=… trans_err_m=… p95_trans_err_m=… rot_err_deg=… lost=…
//                         updates_per_s=… particles_mean=… field_mib=… best_particle_…
//                         region_agreement=… region_changes=… followed=…
// lost = scans with a translation error over 1 m; updates_per_s = filter updates per second of
// the filter's own CPU time (one thread). best_particle_* score the heaviest particle (the
// thesis' estimate) beside the cluster mean (the issue's). region_agreement: how often the
// particles' heaviest region is the kernel's region of the scan; followed: of the kernel's
// changes of region, those the particles made within 10 scans (the hand-over at gateways).
// --part first|second localizes along one half of the scans only (the map is always built from
// all of them): the first half is the tuning half of the MclConfig defaults, the second the check.
#include <algorithm>
#include <cstdio>
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
#include "core/sim/motion/OdometryNoiseModel.h"
#include "tests/eval/localization/LocalizationRun.h"
#include "tests/eval/localization/RunMap.h"
#include "tests/eval/localization/StampedPoses.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;

namespace {

constexpr double kLostM = 1.0;  // the "lost": an error over 1 m

struct Options {
  std::string log;
  std::string corrected;
  std::string models = rgnav::shippedConfigFile("gateways/gateway-hmms.txt");
  std::string trace;
  std::string part = "all";
  std::optional<std::uint64_t> noiseSeed;
  std::size_t maxScans = 0;
  double stampOffset = 0.0;
  double stampTolerance = 0.001;
  double minMatchedShare = 0.9;
  double initialSigmaM = 0.05;
  double initialSigmaDeg = 2.0;
  bool global = true;
  rgnav::LocalizationSetup setup;
};

std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Sets each scan's sensorPose to its corrected pose from --corrected and drops the scans without one.
void takeCorrectedPoses(const Options& options, std::vector<rgnav::LaserScan>& scans) {
  if (options.corrected.empty()) {
    std::cout << "corrected poses: the log's own (" << scans.size() << " scans)\n";
    return;
  }
  const auto poses = rgnav::readScanPoses(options.corrected);
  const rgnav::PoseMatch match = rgnav::matchByStamp(scans, poses, options.stampOffset, options.stampTolerance);
  std::cout << "corrected poses: " << std::filesystem::path(options.corrected).filename().string() << " ("
            << poses.size() << " poses): matched=" << match.matched << " of " << scans.size() << " scans within "
            << options.stampTolerance * 1000.0 << " ms\n";
  if (static_cast<double>(match.matched) < options.minMatchedShare * static_cast<double>(scans.size()) ||
      match.matched < 2)
    throw rgnav::InvalidArgumentError("too few scans matched a corrected pose (--stamp-offset, --min-matched-share)");
  std::vector<rgnav::LaserScan> kept;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    if (!match.poses[i]) continue;
    scans[i].sensorPose = *match.poses[i];
    kept.push_back(std::move(scans[i]));
  }
  scans = std::move(kept);
}

void addOdometryNoise(std::vector<rgnav::LaserScan>& scans, std::uint64_t seed) {
  std::vector<rgnav::Pose2D> truth;
  for (const auto& scan : scans) truth.push_back(scan.sensorPose);
  const rgnav::OdometryNoiseConfig noise;
  rgnav::OdometryNoiseModel model(noise, seed);
  const auto odometry = model.odometryPoses(truth, truth.front());
  for (std::size_t i = 0; i < scans.size(); ++i) scans[i].odometry = odometry[i];
  std::cout << "odometry: the corrected poses plus four-alpha noise, seed " << seed << ", alphas " << noise.alpha1
            << " " << noise.alpha2 << " " << noise.alpha3 << " " << noise.alpha4 << "\n";
}

bool odometryIsCorrected(const std::vector<rgnav::LaserScan>& scans) {
  return std::all_of(scans.begin(), scans.end(), [](const rgnav::LaserScan& s) { return s.odometry == s.sensorPose; });
}

rgnav::RunMap buildMap(const Options& options, const std::vector<rgnav::LaserScan>& scans) {
  rgnav::RunMap run = rgnav::mapOfRun(scans, options.models);
  std::cout << "map: regions=" << run.map.regions.size() << " gateways=" << run.map.gateways.size()
            << " neutralised=" << run.map.summary.neutralised << " gateway_events=" << run.gatewayEvents
            << " seconds=" << shown(run.seconds) << "\n";
  return run;
}

// The scans of --part.
std::vector<rgnav::LaserScan> partOf(const Options& options, const std::vector<rgnav::LaserScan>& scans) {
  const auto half = static_cast<std::ptrdiff_t>(scans.size() / 2);
  if (options.part == "all") return scans;
  if (options.part == "first") return {scans.begin(), scans.begin() + half};
  if (options.part == "second") return {scans.begin() + half, scans.end()};
  throw rgnav::InvalidArgumentError("--part must be all, first or second, not " + options.part);
}

std::string figures(const rgnav::LocalizationRun& run) {
  std::vector<rgnav::PoseError> errors, bestErrors;
  for (const auto& s : run.scans) {
    errors.push_back(s.error);
    bestErrors.push_back(s.bestParticleError);
  }
  const rgnav::ErrorSummary e = rgnav::summarize(errors, kLostM);
  const rgnav::ErrorSummary b = rgnav::summarize(bestErrors, kLostM);
  const double perSecond = run.filterSeconds > 0.0 ? static_cast<double>(run.updates) / run.filterSeconds : 0.0;
  char text[512];
  std::snprintf(text, sizeof text,
                "scans=%zu trans_err_m=%.4f p95_trans_err_m=%.4f rot_err_deg=%.3f lost=%zu updates_per_s=%.0f "
                "particles_mean=%.0f field_mib=%.2f best_particle_trans_err_m=%.4f best_particle_p95_trans_err_m=%.4f "
                "best_particle_rot_err_deg=%.3f best_particle_lost=%zu updates=%zu traversals=%zu field_build_s=%.2f",
                e.scans, e.translationMeanM, e.translationP95M, e.rotationMeanDeg, e.lost, perSecond, run.particlesMean,
                static_cast<double>(run.fieldBytes) / (1024.0 * 1024.0), b.translationMeanM, b.translationP95M,
                b.rotationMeanDeg, b.lost, run.updates, run.traversals, run.fieldSeconds);
  return text;
}

constexpr std::size_t kFollowScans = 10;  // a change of region is followed if the particles get there this soon

// How often the particles' heaviest region is the region the kernel mapped the scan into, and of
// the kernel's changes of region between consecutive scans, how many the particles followed
// within kFollowScans scans (the hand-over at gateways working).
std::string regionAgreement(const rgnav::LocalizationRun& run, const std::map<rgnav::DataId, rgnav::RegionId>& scanRegions) {
  std::vector<rgnav::RegionId> mapped;
  for (const auto& s : run.scans) {
    const auto it = scanRegions.find(s.scanId);
    mapped.push_back(it == scanRegions.end() ? rgnav::RegionId() : it->second);
  }
  std::size_t same = 0, changes = 0, followed = 0;
  for (std::size_t i = 0; i < run.scans.size(); ++i) {
    same += mapped[i] == run.scans[i].particleRegion;
    if (i == 0 || mapped[i] == mapped[i - 1] || mapped[i].isNone() || mapped[i - 1].isNone()) continue;
    ++changes;
    for (std::size_t j = i; j < std::min(run.scans.size(), i + kFollowScans); ++j)
      if (run.scans[j].particleRegion == mapped[i]) {
        ++followed;
        break;
      }
  }
  char text[128];
  std::snprintf(text, sizeof text, " region_agreement=%.3f region_changes=%zu followed=%zu",
                static_cast<double>(same) / static_cast<double>(run.scans.size()), changes, followed);
  return text;
}

void writeTrace(std::ostream& out, const char* filter, const rgnav::LocalizationRun& run,
                const std::map<rgnav::DataId, rgnav::RegionId>& scanRegions) {
  for (const auto& s : run.scans) {
    const auto mapped = scanRegions.find(s.scanId);
    out << filter << ' ' << s.scanId << ' ' << s.updated << ' ' << s.truth.x << ' ' << s.truth.y << ' '
        << s.truth.theta << ' ' << s.estimate.x << ' ' << s.estimate.y << ' ' << s.estimate.theta << ' '
        << s.error.translationM << ' ' << s.error.rotationRad * 180.0 / M_PI << ' ' << s.bestParticleError.translationM
        << ' ' << s.bestParticleError.rotationRad * 180.0 / M_PI << ' ' << s.region.value() << ' '
        << s.particleRegion.value() << ' ' << s.particles
        << ' ' << s.clusterWeight << ' ' << s.fitPerBeam << ' '
        << (mapped == scanRegions.end() ? rgnav::RegionId() : mapped->second).value() << '\n';
  }
}

void evaluate(const Options& options) {
  std::vector<rgnav::LaserScan> scans = rgnav::readLaserScans(options.log, {}, options.maxScans);
  takeCorrectedPoses(options, scans);
  if (options.noiseSeed) addOdometryNoise(scans, *options.noiseSeed);
  else if (odometryIsCorrected(scans))
    std::cout << "warning: the odometry is the corrected pose (a corrected log?): use --odometry-noise\n";
  const rgnav::RunMap run = buildMap(options, scans);
  const rgnav::FinalMap& map = run.map;
  const std::vector<rgnav::LaserScan> localized = partOf(options, scans);
  const std::string name = std::filesystem::path(options.log).filename().string() +
                           (options.part == "all" ? std::string() : " (" + options.part + " half)");
  rgnav::validate(options.setup.config);
  std::optional<std::ofstream> trace;
  if (!options.trace.empty()) {
    trace.emplace(options.trace);
    *trace << "# filter scan_id updated true_x true_y true_theta est_x est_y est_theta err_m err_deg best_err_m "
              "best_err_deg region particle_region particles cluster_weight fit_per_beam "
              "mapped_region\n";
  }
  if (options.global) {
    const auto floor = rgnav::LocalizationMap::wholeFloor(map.regions, options.setup.config.beam);
    const rgnav::LocalizationRun global = rgnav::localizeAlong(floor, localized, floor.regionIds().front(), options.setup);
    std::cout << "localization " << name << " [global map]: " << figures(global) << std::endl;
    if (trace) writeTrace(*trace, "global", global, run.scanRegions);
  }
  const auto regions = rgnav::LocalizationMap::fromViews(map.regions, map.gateways, options.setup.config.beam);
  std::cout << "localization map: regions=" << regions.regionIds().size()
            << " handover_gateways=" << regions.gateways().size() << " (both sides known, not neutralised)\n";
  const auto start = run.scanRegions.find(localized.front().id);
  const rgnav::LocalizationRun regional = rgnav::localizeAlong(
      regions, localized, start == run.scanRegions.end() ? rgnav::RegionId() : start->second, options.setup);
  if (trace) {
    writeTrace(*trace, "region", regional, run.scanRegions);
    if (!trace->flush()) throw rgnav::FileError("cannot write " + options.trace);
  }
  std::cout << "localization " << name << ": " << figures(regional) << regionAgreement(regional, run.scanRegions)
            << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  rgnav::MclConfig& mcl = options.setup.config;
  po::options_description desc(
      "rgnav-eval-localization <log> [--corrected file] [--odometry-noise seed] [--max-scans N] [--part first|second]");
  desc.add_options()
      ("help", "this text")
      ("log", po::value(&options.log)->required(), "CARMEN or Intel JSON log (raw odometry)")
      ("corrected", po::value(&options.corrected),
       "the run's corrected poses from another file (Intel JSON companion, CARMEN corrected log), matched by stamp")
      ("stamp-offset", po::value(&options.stampOffset)->default_value(0.0),
       "s added to the corrected file's stamps to give the log's (976052857.3373: corrected/intel-corrected.log.gz "
       "against the Intel JSON)")
      ("stamp-tolerance", po::value(&options.stampTolerance)->default_value(options.stampTolerance, "0.001"),
       "s between a scan's stamp and its corrected pose's")
      ("min-matched-share", po::value(&options.minMatchedShare)->default_value(options.minMatchedShare, "0.9"),
       "refuse to score if fewer of the scans matched a corrected pose")
      ("odometry-noise", po::value<std::uint64_t>()->notifier([&](std::uint64_t s) { options.noiseSeed = s; }),
       "replace the odometry by the corrected poses plus four-alpha noise drawn with this seed")
      ("max-scans", po::value(&options.maxScans), "read only the first N scans (0: all)")
      ("part", po::value(&options.part)->default_value(options.part),
       "localize along all scans, the first half (tuning) or the second (check); the map is made of all")
      ("models", po::value(&options.models)->default_value(options.models), "gateway HMMs for mapping")
      ("global", po::value(&options.global)->default_value(true), "also run the global-map baseline")
      ("trace", po::value(&options.trace), "write every scan's estimate and errors to this file")
      ("seed", po::value(&options.setup.seed)->default_value(options.setup.seed), "the filter's random seed")
      ("initial-sigma-m", po::value(&options.initialSigmaM)->default_value(options.initialSigmaM, "0.05"),
       "spread of the initial particles around the first true pose (x, y)")
      ("initial-sigma-deg", po::value(&options.initialSigmaDeg)->default_value(options.initialSigmaDeg, "2"),
       "spread of the initial particles' heading")
      ("particles-min", po::value(&mcl.kld.minParticles)->default_value(mcl.kld.minParticles), "KLD minimum")
      ("particles-max", po::value(&mcl.kld.maxParticles)->default_value(mcl.kld.maxParticles), "KLD maximum")
      ("kld-epsilon", po::value(&mcl.kld.epsilon)->default_value(mcl.kld.epsilon, shown(mcl.kld.epsilon)), "KLD bound")
      ("sigma-hit", po::value(&mcl.beam.sigmaHitM)->default_value(mcl.beam.sigmaHitM, shown(mcl.beam.sigmaHitM)),
       "m, beam model")
      ("z-hit", po::value(&mcl.beam.zHit)->default_value(mcl.beam.zHit, shown(mcl.beam.zHit)), "beam model")
      ("z-rand", po::value(&mcl.beam.zRand)->default_value(mcl.beam.zRand, shown(mcl.beam.zRand)), "beam model")
      ("beams", po::value(&mcl.beam.beams)->default_value(mcl.beam.beams), "beams per update")
      ("beam-weight", po::value(&mcl.beam.beamWeight)->default_value(mcl.beam.beamWeight, shown(mcl.beam.beamWeight)),
       "factor on the scan's log-likelihood")
      ("alpha1", po::value(&mcl.motion.alpha1)->default_value(mcl.motion.alpha1, shown(mcl.motion.alpha1)), "motion model")
      ("alpha2", po::value(&mcl.motion.alpha2)->default_value(mcl.motion.alpha2, shown(mcl.motion.alpha2)), "motion model")
      ("alpha3", po::value(&mcl.motion.alpha3)->default_value(mcl.motion.alpha3, shown(mcl.motion.alpha3)), "motion model")
      ("alpha4", po::value(&mcl.motion.alpha4)->default_value(mcl.motion.alpha4, shown(mcl.motion.alpha4)), "motion model")
      ("resample-below-ess",
       po::value(&mcl.resampleBelowEss)->default_value(mcl.resampleBelowEss, shown(mcl.resampleBelowEss)),
       "resample when the effective sample size falls below this share")
      ("handover-radius",
       po::value(&mcl.handoverRadiusM)->default_value(mcl.handoverRadiusM, shown(mcl.handoverRadiusM)),
       "m, gateway hand-over");
  po::positional_options_description positional;
  positional.add("log", 1);
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc, positional)) return 0;
    options.setup.initialSigma = {options.initialSigmaM, options.initialSigmaM, options.initialSigmaDeg * M_PI / 180.0};
    evaluate(options);
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-localization: " << e.what() << "\n" << desc << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-localization: " << e.what() << std::endl;
    return 1;
  }
}
