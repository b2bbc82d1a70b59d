// RegionMcl: Monte Carlo localization in an RG map (thesis 5.3). Each particle lives in a region
// and is weighed on that region's likelihood field (LocalizationMap.h); a particle that moves
// past a gateway is handed over into the region on the other side (its pose re-expressed in that
// region's frame: between(frameB, frameA ⊕ pose)). One update, once the odometry moved
// MclConfig::updateMinTravelM or turned updateMinTurnRad since the last:
//   1. prediction: every particle moved by the odometry's rot1/trans/rot2 with four-alpha noise
//      (OdometrySampler.h), then handed over where it passed a gateway;
//   2. correction: weight *= exp(logLikelihood of the scan on the particle's region field);
//   3. resampling (when the effective sample size falls below resampleBelowEss of the count):
//      low-variance draws (LowVarianceResampler.h) in shuffled order until the count reaches the
//      KLD bound of the bins drawn so far (KldSampling.h).
// The estimate is the weighted mean of the heaviest cluster (ParticleClusters.h); the best
// particle is reported beside it (the thesis' choice). When the estimate's region changes to a
// region joined to the previous one by a gateway, and the estimate lies traversalConfirmM from
// that gateway's centre and outside the previous region's freespace ("a reasonable distance
// behind the gateway"), the traversal is reported once (takeTraversals), as evidence for the
// kernel; a change into a region mapped over the same place (no gateway between) is none.
// Kidnapping and global localization are not this class's: the caller reseeds with setParticles.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "core/common/SensorData.h"
#include "core/nav/localization/LocalizationMap.h"
#include "core/nav/localization/OdometrySampler.h"
#include "core/nav/localization/ParticleClusters.h"

namespace rgnav {

struct PoseEstimate {
  DataId scanId = 0;      // the scan of the last update
  RegionId region;        // the region of the estimate
  Pose2D mapPose;         // mean of the heaviest cluster, map frame
  Pose2D regionPose;      // the same in the region's frame
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // of that cluster, map frame
  Pose2D bestParticle;    // the heaviest particle, map frame
  double clusterWeight = 0.0;  // the heaviest cluster's share of the weight
  std::size_t particles = 0;
  // The mean log-likelihood per used beam at the estimate (before beamWeight): how well the scan
  // fits the map there; a kidnapping detector watches it.
  double fitPerBeam = 0.0;
};

// A gateway traversal the filter confirmed (the evidence the Localization module reports to the
// kernel). PassageTracker.h's GatewayTraversal is the detector's, in its odometry frame.
struct ConfirmedTraversal {
  GatewayId gateway;
  RegionId from, to;
  DataId scanId = 0;
};

class RegionMcl {
 public:
  // Throws ConfigError for a bad configuration. `map` must outlive the filter.
  RegionMcl(const MclConfig& config, const LocalizationMap& map, std::uint64_t seed);

  // Particles drawn around a map pose with a diagonal standard deviation (x, y in m, theta in
  // rad), in the region that holds it (LocalizationMap::regionAt, preferring `region`).
  // The KLD maximum of particles is drawn; the next resampling adapts the count.
  void setPose(const Pose2D& mapPose, const Eigen::Vector3d& sigma, RegionId region);
  // Replaces the particle set (weights are normalised; InvalidArgumentError if empty or a
  // particle's region is not in the map).
  void setParticles(std::vector<Particle> particles);

  // Takes the scan with its odometry pose (LaserScan::odometry). The first scan after setPose /
  // setParticles only sets the odometry reference and weighs. Returns whether the filter updated.
  // NotAvailableError if no particles were set.
  bool update(const LaserScan& scan);

  bool initialised() const { return !particles_.empty(); }
  PoseEstimate estimate() const;  // NotAvailableError before the first update
  const std::vector<Particle>& particles() const { return particles_; }
  Pose2D mapPose(const Particle& particle) const;
  // Traversals confirmed since the last call (cleared by it).
  std::vector<ConfirmedTraversal> takeTraversals();

 private:
  void predict(const OdometryMotion& motion);
  void correct(const ScanBeams& beams);
  void resample();
  void refreshEstimate(DataId scanId, const ScanBeams& beams);
  // Confirms a traversal when the estimate's region changed from lastRegion_ across a gateway.
  void checkTraversal(DataId scanId);

  MclConfig config_;
  const LocalizationMap& map_;
  std::mt19937_64 rng_;
  OdometrySampler sampler_;
  std::vector<Particle> particles_;
  std::optional<Pose2D> lastOdometry_;  // the odometry of the last update
  std::optional<PoseEstimate> estimate_;
  std::vector<ConfirmedTraversal> traversals_;
  RegionId lastRegion_;  // the region the confirmed traversals have the robot in
};

}  // namespace rgnav
