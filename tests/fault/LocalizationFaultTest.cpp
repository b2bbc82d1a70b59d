// rgnav-faulttest-localization: fault injection on the Localization module (issue 28, `rgctl
// faulttest localization`). A real server set (LocalizationSet.h: own omniNames on free loopback
// ports, a temporary directory, the watchdog supervising) replays a log's scans with their RAW
// odometry through the log playback (the Laser), paced by the module in lock-step, while the RG
// Mapping Kernel holds the RG map made in process from the run's corrected poses (AnchoredRun.h)
// and the Localization module localizes the whole run from the first scan's corrected pose. The
// program fetches the module's estimate of every scan by ID and scores it against the corrected
// poses (mean and 95th percentile of the translation error, mean rotation error, lost = scans
// over 1 m; tests/eval/localization LocalizationErrors.h), once undisturbed and once while the
// module is SIGKILLed `--kills` times spread over the run (the watchdog restarts it, it resumes
// from its particle checkpoint; EstimateCollection.h says how a scan without an estimate of its
// own is scored). A line per run, and last:
//   faulttest localization: kills=20 restarts=… resumed=… propagated=… undisturbed_trans_err_m=…
//   trans_err_m=… ratio=… … lost=… result=PASS|FAIL
// PASS: every kill dealt, answered by exactly one restart that resumed from a checkpoint; the mean
// and p95 translation error and the mean rotation error at most 10 % (--tolerance) above the
// undisturbed run's; no scan lost. Exit code 0 only on PASS.
#include <cstdio>
#include <iostream>

#include "core/config/ShippedConfig.h"
#include "tests/eval/localization/LocalizationErrors.h"
#include "tests/fault/EstimateCollection.h"
#include "tests/fault/LocalizationSet.h"
#include "tests/support/cluster/Interruption.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;

namespace {

constexpr double kLostM = 1.0;

struct Options {
  std::string log, corrected, models;
  int kills = 20;
  std::size_t maxScans = 0;
  double tolerance = 0.10;
  double stallSeconds = 120.0;
};

struct RunFigures {
  CollectedRun collected;
  ErrorSummary errors;
  std::uint32_t restarts = 0;
};

RunFigures runOnce(const Options& options, const AnchoredRun& run, int kills, const char* name) {
  const std::unique_ptr<TestCluster> cluster = localizationSet(options.log, run);
  cluster->start();
  RunFigures figures;
  figures.collected = collectEstimates(*cluster, run, kills, options.stallSeconds);
  figures.restarts = cluster->describe("Localization").restarts;
  std::vector<PoseError> errors;
  for (std::size_t i = 0; i < run.scans.size(); ++i)
    errors.push_back(poseError(figures.collected.estimates[i], run.scans[i].truth));
  figures.errors = summarize(errors, kLostM);
  const CollectedRun& c = figures.collected;
  for (std::size_t k = 0; k < c.killedAfter.size(); ++k)
    std::printf("kill %zu: after scan %llu, resumed at scan %llu\n", k + 1,
                static_cast<unsigned long long>(c.killedAfter[k]), static_cast<unsigned long long>(c.resumedAfter[k]));
  const ErrorSummary& e = figures.errors;
  std::printf("localization_faults %s: scans=%zu served=%zu propagated=%zu kills=%d restarts=%u resumed=%d "
              "trans_err_m=%.4f p95_trans_err_m=%.4f rot_err_deg=%.3f lost=%zu seconds=%.1f\n",
              name, e.scans, c.served.size(), c.propagated, c.kills, figures.restarts, c.resumed, e.translationMeanM,
              e.translationP95M, e.rotationMeanDeg, e.lost, c.seconds);
  std::fflush(stdout);
  return figures;
}

double ratio(double disturbed, double undisturbed) { return undisturbed > 0.0 ? disturbed / undisturbed : 0.0; }

}  // namespace

int main(int argc, char** argv) {
  Options options;
  options.log = TestCluster::shared("data/laser/derived/xiaofeng-intel_gfs.json.xz");
  options.corrected = TestCluster::shared("data/laser/derived/xiaofeng-intel_corrected_log.json.xz");
  options.models = shippedConfigFile("gateways/gateway-hmms.txt");
  po::options_description desc("rgnav-faulttest-localization [options]");
  desc.add_options()
      ("help", "this text")
      ("log", po::value(&options.log)->default_value(options.log), "Intel JSON log to replay (raw odometry)")
      ("corrected", po::value(&options.corrected)->default_value(options.corrected),
       "the run's corrected poses (the Intel JSON companion), matched to the scans by stamp within 1 ms")
      ("models", po::value(&options.models)->default_value(options.models), "gateway HMMs for making the map")
      ("kills", po::value(&options.kills)->default_value(options.kills), "SIGKILLs of the Localization module")
      ("max-scans", po::value(&options.maxScans)->default_value(options.maxScans),
       "localize and score the first N scans only (0: all; the map is made of all)")
      ("tolerance", po::value(&options.tolerance)->default_value(options.tolerance, "0.1"),
       "largest allowed increase of each error figure over the undisturbed run's (0.1: 10 %)")
      ("stall-s", po::value(&options.stallSeconds)->default_value(options.stallSeconds, "120"),
       "give up when the module takes no scan for this long");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    if (options.kills < 0) throw po::error("--kills must not be negative");
    catchInterruptions();  // a stopped run still shuts its server set down and removes its directory
    const AnchoredRun run = anchoredRun(options.log, options.corrected, options.models, options.maxScans);
    std::cout << "run: scans=" << run.scans.size() << " regions=" << run.regions
              << " (map made in process from the corrected poses, in the frame where the first scan's corrected "
                 "pose is its odometry pose)"
              << std::endl;
    const RunFigures reference = runOnce(options, run, 0, "undisturbed");
    const RunFigures faulty = runOnce(options, run, options.kills, "under_kills");
    const ErrorSummary &u = reference.errors, &f = faulty.errors;
    const CollectedRun& c = faulty.collected;
    const double meanRatio = ratio(f.translationMeanM, u.translationMeanM);
    const double p95Ratio = ratio(f.translationP95M, u.translationP95M);
    const double rotRatio = ratio(f.rotationMeanDeg, u.rotationMeanDeg);
    const double ceiling = 1.0 + options.tolerance;
    const bool ok = c.kills == options.kills && faulty.restarts == static_cast<std::uint32_t>(c.kills) &&
                    c.resumed == c.kills && reference.restarts == 0 && meanRatio <= ceiling && p95Ratio <= ceiling &&
                    rotRatio <= ceiling && f.lost == 0;
    std::printf("faulttest localization: kills=%d restarts=%u resumed=%d propagated=%zu undisturbed_trans_err_m=%.4f "
                "trans_err_m=%.4f ratio=%.3f undisturbed_p95_trans_err_m=%.4f p95_trans_err_m=%.4f p95_ratio=%.3f "
                "undisturbed_rot_err_deg=%.3f rot_err_deg=%.3f rot_ratio=%.3f undisturbed_lost=%zu lost=%zu result=%s\n",
                c.kills, faulty.restarts, c.resumed, c.propagated, u.translationMeanM, f.translationMeanM, meanRatio,
                u.translationP95M, f.translationP95M, p95Ratio, u.rotationMeanDeg, f.rotationMeanDeg, rotRatio, u.lost,
                f.lost, ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-faulttest-localization: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-faulttest-localization: " << e.what() << std::endl;
  }
  return 2;
}
