// One localization run along a log; see LocalizationRun.h.
#include "tests/eval/localization/LocalizationRun.h"

#include <algorithm>
#include <ctime>
#include <map>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The region holding the most weight of the particle set.
RegionId heaviestRegion(const std::vector<Particle>& particles) {
  std::map<RegionId, double> weights;
  for (const Particle& p : particles) weights[p.region] += p.weight;
  const auto best = std::max_element(weights.begin(), weights.end(),
                                     [](const auto& a, const auto& b) { return a.second < b.second; });
  return best == weights.end() ? RegionId() : best->first;
}

}  // namespace

LocalizationRun localizeAlong(const LocalizationMap& map, std::span<const LaserScan> scans, RegionId startRegion,
                              const LocalizationSetup& setup) {
  if (scans.empty()) throw InvalidArgumentError("localization run: no scans");
  LocalizationRun run;
  const double fieldStart = threadCpuSeconds();
  for (RegionId id : map.regionIds()) map.field(id);
  run.fieldSeconds = threadCpuSeconds() - fieldStart;
  run.fieldBytes = map.fieldBytes();

  RegionMcl mcl(setup.config, map, setup.seed);
  mcl.setPose(scans.front().sensorPose, setup.initialSigma, startRegion);
  Pose2D odometryAtEstimate = scans.front().odometry;
  double particleSum = 0.0;
  for (const LaserScan& scan : scans) {
    const double start = threadCpuSeconds();
    const bool updated = mcl.update(scan);
    run.filterSeconds += threadCpuSeconds() - start;
    run.traversals += mcl.takeTraversals().size();
    const PoseEstimate estimate = mcl.estimate();
    if (updated) {
      ++run.updates;
      particleSum += static_cast<double>(estimate.particles);
      odometryAtEstimate = scan.odometry;
    }
    const Pose2D moved = between(odometryAtEstimate, scan.odometry);
    LocalizedScan outcome;
    outcome.scanId = scan.id;
    outcome.updated = updated;
    outcome.truth = scan.sensorPose;
    outcome.estimate = compose(estimate.mapPose, moved);
    outcome.bestParticle = compose(estimate.bestParticle, moved);
    outcome.region = estimate.region;
    outcome.particleRegion = heaviestRegion(mcl.particles());
    outcome.particles = estimate.particles;
    outcome.clusterWeight = estimate.clusterWeight;
    outcome.fitPerBeam = estimate.fitPerBeam;
    outcome.error = poseError(outcome.estimate, outcome.truth);
    outcome.bestParticleError = poseError(outcome.bestParticle, outcome.truth);
    run.scans.push_back(outcome);
  }
  run.fieldBytes = map.fieldBytes();
  if (run.updates > 0) run.particlesMean = particleSum / static_cast<double>(run.updates);
  return run;
}

}  // namespace rgnav
