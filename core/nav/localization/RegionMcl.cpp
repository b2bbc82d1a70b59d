// RegionMcl (RegionMcl.h): prediction with hand-over, correction on the regions' fields,
// KLD-adaptive low-variance resampling, and the estimate from the heaviest cluster.
#include "core/nav/localization/RegionMcl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"
#include "core/nav/localization/KldSampling.h"
#include "core/nav/localization/LowVarianceResampler.h"

namespace rgnav {
namespace {

Eigen::Vector2d position(const Pose2D& p) { return {p.x, p.y}; }

}  // namespace

RegionMcl::RegionMcl(const MclConfig& config, const LocalizationMap& map, std::uint64_t seed)
    : config_(config), map_(map), rng_(seed), sampler_(config.motion, seed ^ 0x9E3779B97F4A7C15ull) {
  validate(config);
}

void RegionMcl::setPose(const Pose2D& pose, const Eigen::Vector3d& sigma, RegionId hint) {
  for (int i = 0; i < 3; ++i)
    if (!(std::isfinite(sigma[i]) && sigma[i] >= 0.0)) throw InvalidArgumentError("setPose: sigma must be finite and non-negative");
  requireFiniteArgument(pose.x, "setPose: x");
  requireFiniteArgument(pose.y, "setPose: y");
  requireFiniteArgument(pose.theta, "setPose: theta");
  RegionId region = map_.regionAt(position(pose), hint);
  if (region.isNone() && map_.hasRegion(hint)) region = hint;
  if (region.isNone()) throw NotAvailableError("setPose: no region of the map holds the pose");
  const Pose2D toRegion = inverse(map_.region(region).frame);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Particle> particles(config_.kld.maxParticles);
  for (Particle& p : particles) {
    const Pose2D drawn{pose.x + sigma[0] * normal(rng_), pose.y + sigma[1] * normal(rng_),
                       normalizeAngle(pose.theta + sigma[2] * normal(rng_))};
    p = {region, compose(toRegion, drawn), 1.0};
  }
  setParticles(std::move(particles));
}

void RegionMcl::setParticles(std::vector<Particle> particles) {
  if (particles.empty()) throw InvalidArgumentError("setParticles: no particles");
  double total = 0.0;
  for (const Particle& p : particles) {
    if (!map_.hasRegion(p.region)) throw InvalidArgumentError("setParticles: a particle's region is not in the map");
    if (!(p.weight >= 0.0) || !std::isfinite(p.weight)) throw InvalidArgumentError("setParticles: weights must be finite and non-negative");
    total += p.weight;
  }
  for (Particle& p : particles) p.weight = total > 0.0 ? p.weight / total : 1.0 / static_cast<double>(particles.size());
  particles_ = std::move(particles);
  lastOdometry_.reset();
  estimate_.reset();
  lastRegion_ = RegionId{};
}

Pose2D RegionMcl::mapPose(const Particle& particle) const {
  return compose(map_.region(particle.region).frame, particle.pose);
}

bool RegionMcl::update(const LaserScan& scan) {
  if (particles_.empty()) throw NotAvailableError("RegionMcl: no particles set (setPose first)");
  const ScanBeams beams = selectBeams(scan, config_.beam);
  if (lastOdometry_) {
    const Pose2D moved = between(*lastOdometry_, scan.odometry);
    if (std::hypot(moved.x, moved.y) < config_.updateMinTravelM && std::abs(moved.theta) < config_.updateMinTurnRad)
      return false;
    predict(decomposeMotion(*lastOdometry_, scan.odometry));
  }
  lastOdometry_ = scan.odometry;
  correct(beams);
  refreshEstimate(scan.id, beams);
  checkTraversal(scan.id);
  resample();
  return true;
}

void RegionMcl::predict(const OdometryMotion& motion) {
  for (Particle& p : particles_) {
    p.pose = sampler_.sample(p.pose, motion);
    const LocalizationRegion& region = map_.region(p.region);
    const Pose2D onMap = compose(region.frame, p.pose);
    const RegionId next = map_.handOver(p.region, position(onMap), config_.handoverRadiusM);
    if (next != p.region) {
      p.region = next;
      p.pose = between(map_.region(next).frame, onMap);
    }
  }
}

void RegionMcl::correct(const ScanBeams& beams) {
  std::vector<double> logW(particles_.size());
  double best = -std::numeric_limits<double>::infinity();
  std::map<RegionId, const LikelihoodField*> fields;  // looked up once per region and update
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Particle& p = particles_[i];
    const LikelihoodField*& field = fields[p.region];
    if (!field) field = &map_.field(p.region);
    logW[i] = std::log(std::max(p.weight, 1e-300)) + field->logLikelihood(p.pose, beams);
    best = std::max(best, logW[i]);
  }
  double total = 0.0;
  for (std::size_t i = 0; i < particles_.size(); ++i) total += particles_[i].weight = std::exp(logW[i] - best);
  for (Particle& p : particles_) p.weight /= total;
}

void RegionMcl::resample() {
  double sumSquares = 0.0;
  std::vector<double> weights(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    weights[i] = particles_[i].weight;
    sumSquares += weights[i] * weights[i];
  }
  const double ess = 1.0 / sumSquares;
  if (ess >= config_.resampleBelowEss * static_cast<double>(particles_.size())) return;
  std::vector<std::size_t> drawn = lowVarianceDraw(weights, config_.kld.maxParticles, rng_);
  std::shuffle(drawn.begin(), drawn.end(), rng_);
  KldBins bins(config_.kld);
  std::vector<Particle> next;
  next.reserve(drawn.size());
  for (const std::size_t i : drawn) {
    const Particle& p = particles_[i];
    bins.add(p.region.value(), mapPose(p));
    next.push_back({p.region, p.pose, 1.0});
    if (next.size() >= kldParticleBound(bins.occupied(), config_.kld)) break;
  }
  for (Particle& p : next) p.weight = 1.0 / static_cast<double>(next.size());
  particles_ = std::move(next);
}

void RegionMcl::refreshEstimate(DataId scanId, const ScanBeams& beams) {
  std::vector<Pose2D> poses(particles_.size());
  std::size_t best = 0;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    poses[i] = mapPose(particles_[i]);
    if (particles_[i].weight > particles_[best].weight) best = i;
  }
  const std::vector<ParticleCluster> clusters =
      clusterParticles(particles_, poses, config_.clusterRadiusM, config_.clusterAngleRad);
  const ParticleCluster& top = clusters.front();
  PoseEstimate e;
  e.scanId = scanId;
  e.region = map_.regionAt(position(top.mean), top.region);
  if (e.region.isNone()) e.region = top.region;
  e.mapPose = top.mean;
  e.regionPose = between(map_.region(e.region).frame, top.mean);
  e.covariance = top.covariance;
  e.bestParticle = poses[best];
  e.clusterWeight = top.weight;
  e.particles = particles_.size();
  e.fitPerBeam = map_.field(e.region).meanLogLikelihood(e.regionPose, beams.endpoints);
  estimate_ = e;
}

void RegionMcl::checkTraversal(DataId scanId) {
  if (!estimate_) return;
  const RegionId now = estimate_->region;
  if (lastRegion_.isNone()) lastRegion_ = now;
  if (now == lastRegion_) return;
  // The gateway between the two regions nearest to the estimate; none: the particles moved into a
  // region mapped over the same place (LocalizationMap::handOver), which is no traversal.
  const Eigen::Vector2d p = position(estimate_->mapPose);
  const LocalizationGateway* passed = nullptr;
  for (const auto& [id, g] : map_.gateways()) {
    const bool joins = (g.regions[0] == lastRegion_ && g.regions[1] == now) || (g.regions[1] == lastRegion_ && g.regions[0] == now);
    if (joins && (!passed || (p - g.centre).squaredNorm() < (p - passed->centre).squaredNorm())) passed = &g;
  }
  if (!passed) {
    lastRegion_ = now;
    return;
  }
  if ((p - passed->centre).norm() < config_.traversalConfirmM || map_.freeIn(lastRegion_, p)) return;
  traversals_.push_back({passed->id, lastRegion_, now, scanId});
  lastRegion_ = now;
}

PoseEstimate RegionMcl::estimate() const {
  if (!estimate_) throw NotAvailableError("RegionMcl: no update yet");
  return *estimate_;
}

std::vector<ConfirmedTraversal> RegionMcl::takeTraversals() {
  std::vector<ConfirmedTraversal> out;
  out.swap(traversals_);
  return out;
}

}  // namespace rgnav
