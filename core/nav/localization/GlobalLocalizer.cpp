// Global localization and kidnap recovery around a RegionMcl (see GlobalLocalizer.h).
#include "core/nav/localization/GlobalLocalizer.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

void validate(const GlobalLocalizerConfig& c) {
  if (c.seedCandidates == 0 || c.seedParticles < c.seedCandidates || !(c.seedSigmaXyM > 0.0) ||
      !(c.seedSigmaThetaRad > 0.0) || !(c.reseedTravelM > 0.0) || c.kidnapUpdates == 0 || c.seedScoreMargin < 0.0 ||
      c.historyToleranceM < 0.0 || c.historyTolerancePerM < 0.0 || !(c.historyToleranceRad > 0.0))
    throw ConfigError("GlobalLocalizer: counts, spreads and tolerances must be positive");
}

bool near(const Pose2D& a, const Pose2D& b, double distanceM, double angleRad) {
  return std::hypot(a.x - b.x, a.y - b.y) <= distanceM && std::abs(normalizeAngle(a.theta - b.theta)) <= angleRad;
}

}  // namespace

GlobalLocalizer::GlobalLocalizer(const GlobalLocalizerConfig& config, const MclConfig& mcl, const LocalizationMap& map,
                                 const std::vector<RegionView>& regions, const std::vector<GatewayView>& gateways,
                                 std::uint64_t seed)
    : config_(config),
      map_(map),
      recognizer_(config.recognition, mcl.beam, map, regions, gateways),
      mcl_(mcl, map, seed),
      rng_(seed ^ 0x9e3779b97f4a7c15ull),
      recent_(config.observation) {
  validate(config);
  for (const GatewayView& g : gateways) {
    if (g.neutralised || g.sideA.isNone() || g.sideB.isNone() || g.sideA == g.sideB) continue;
    neighbours_[g.sideA].insert(g.sideB);
    neighbours_[g.sideB].insert(g.sideA);
  }
}

std::optional<PoseEstimate> GlobalLocalizer::estimate() const {
  if (state_ == LocalizerState::kSearching) return std::nullopt;
  return mcl_.estimate();
}

std::vector<ConfirmedTraversal> GlobalLocalizer::takeTraversals() { return std::exchange(traversals_, {}); }

void GlobalLocalizer::relocalize() {
  state_ = LocalizerState::kSearching;
  recent_.keepNewest();
  candidates_.clear();
  candidatesOdometry_.reset();
  searchStart_.reset();
  searchTurnRad_ = 0.0;
  traversedInto_.reset();
  lowFitUpdates_ = 0;
}

void GlobalLocalizer::setPose(const Pose2D& mapPose, const Eigen::Vector3d& sigma) {
  mcl_.setPose(mapPose, sigma, RegionId{});
  state_ = LocalizerState::kLocalized;
  lowFitUpdates_ = 0;
}

void GlobalLocalizer::update(const LaserScan& scan) {
  recent_.add(scan);
  double step = 0.0, turn = 0.0;
  if (lastOdometry_) {
    const Pose2D motion = between(*lastOdometry_, scan.odometry);
    step = std::hypot(motion.x, motion.y);
    turn = std::abs(motion.theta);
  }
  lastOdometry_ = scan.odometry;
  if (state_ == LocalizerState::kSearching) {
    if (!searchStart_) searchStart_ = scan.odometry;
    searchTurnRad_ += turn;
    if (recent_.travelM() >= config_.firstRecognitionTravelM || searchTurnRad_ >= config_.firstRecognitionTurnRad)
      recognizeAndSeed(scan);
    return;
  }
  const bool updated = mcl_.update(scan);
  travelSinceSeedM_ += step;
  travelSinceRecognitionM_ += step;
  for (const ConfirmedTraversal& t : mcl_.takeTraversals()) {
    traversedInto_ = t.to;
    if (state_ == LocalizerState::kLocalized) traversals_.push_back(t);
  }
  if (!updated) return;
  if (state_ == LocalizerState::kConverging)
    checkConvergence(scan);
  else
    watchForKidnap();
}

void GlobalLocalizer::checkConvergence(const LaserScan& scan) {
  const PoseEstimate e = mcl_.estimate();
  const double spread = std::sqrt(std::max(0.0, e.covariance(0, 0) + e.covariance(1, 1)));
  if (travelSinceSeedM_ >= config_.confirmTravelM && e.clusterWeight >= config_.localizedClusterWeight &&
      spread <= config_.localizedSpreadM && e.fitPerBeam >= config_.localizedFitPerBeam) {
    state_ = LocalizerState::kLocalized;
    lowFitUpdates_ = 0;
    return;
  }
  if (travelSinceRecognitionM_ >= config_.reseedTravelM) recognizeAndSeed(scan);
}

void GlobalLocalizer::watchForKidnap() {
  const PoseEstimate e = mcl_.estimate();
  lowFitUpdates_ = e.fitPerBeam < config_.kidnapFitPerBeam ? lowFitUpdates_ + 1 : 0;
  if (lowFitUpdates_ < config_.kidnapUpdates) return;
  lowFitUpdates_ = 0;
  // A low fit alone may be a view into space the map does not hold; the newest scans must fit a
  // pose elsewhere clearly better than the estimate.
  const LocalObservation newest = recent_.observation(config_.kidnapCheckTravelM);
  const std::vector<PoseCandidate> elsewhere = recognizer_.recognize(newest);
  if (elsewhere.empty()) return;
  const PoseCandidate here = recognizer_.candidateAt(e.region, e.regionPose, newest);
  const PoseCandidate& best = elsewhere.front();
  if (best.score < here.score + config_.kidnapScoreMargin) return;
  if (std::hypot(best.mapPose.x - e.mapPose.x, best.mapPose.y - e.mapPose.y) > config_.kidnapDistanceM) {
    // Kidnapped, or a view the map explains badly here and well elsewhere: the older scans show
    // the place before a jump and go; the estimate stays one of the hypotheses the filter weighs.
    ++kidnaps_;
    recent_.keepNewest();
    std::vector<PoseCandidate> hypotheses{here};
    for (const PoseCandidate& c : elsewhere)
      if (hypotheses.size() < config_.seedCandidates && c.score >= best.score - config_.seedScoreMargin)
        hypotheses.push_back(c);
    startConverging(hypotheses, recent_.newest());
    return;
  }
  ++corrections_;
  seed({best});
  mcl_.update(recent_.newest());
}

bool GlobalLocalizer::adjacent(RegionId a, RegionId b) const {
  if (a == b) return true;
  const auto it = neighbours_.find(a);
  return it != neighbours_.end() && it->second.count(b) != 0;
}

std::vector<PoseCandidate> GlobalLocalizer::pruneByHistory(std::vector<PoseCandidate> fresh, const Pose2D& odometry) const {
  if (candidates_.empty() || !candidatesOdometry_) return fresh;
  const Pose2D motion = between(*candidatesOdometry_, odometry);
  const double tolerance = config_.historyToleranceM + config_.historyTolerancePerM * travelSinceRecognitionM_;
  std::vector<PoseCandidate> kept;
  for (const PoseCandidate& c : fresh) {
    const bool fits = std::any_of(candidates_.begin(), candidates_.end(), [&](const PoseCandidate& previous) {
      return adjacent(previous.region, c.region) &&
             near(compose(previous.mapPose, motion), c.mapPose, tolerance, config_.historyToleranceRad);
    });
    if (fits) kept.push_back(c);
  }
  if (traversedInto_) {
    std::vector<PoseCandidate> throughGateway;
    std::copy_if(kept.begin(), kept.end(), std::back_inserter(throughGateway),
                 [&](const PoseCandidate& c) { return adjacent(*traversedInto_, c.region); });
    if (!throughGateway.empty()) kept = std::move(throughGateway);
  }
  return kept.empty() ? fresh : kept;
}

void GlobalLocalizer::recognizeAndSeed(const LaserScan& scan) {
  const LocalObservation observation = recent_.observation();
  std::vector<PoseCandidate> fresh = recognizer_.recognize(observation);
  ++recognitions_;
  // The filter's own hypothesis competes with the recognizer's.
  if (state_ == LocalizerState::kConverging) {
    const PoseEstimate e = mcl_.estimate();
    fresh.push_back(recognizer_.candidateAt(e.region, e.regionPose, observation));
    std::sort(fresh.begin(), fresh.end(), [](const PoseCandidate& a, const PoseCandidate& b) { return a.score > b.score; });
  }
  if (fresh.empty()) return;
  std::vector<PoseCandidate> kept = pruneByHistory(std::move(fresh), scan.odometry);
  const double best = kept.front().score;
  std::vector<PoseCandidate> selected;
  for (const PoseCandidate& c : kept)
    if (selected.size() < config_.seedCandidates && c.score >= best - config_.seedScoreMargin) selected.push_back(c);
  if (state_ == LocalizerState::kSearching) travelSinceSeedM_ = 0.0;
  startConverging(selected, scan);
}

void GlobalLocalizer::startConverging(const std::vector<PoseCandidate>& hypotheses, const LaserScan& scan) {
  if (state_ == LocalizerState::kLocalized) travelSinceSeedM_ = 0.0;
  state_ = LocalizerState::kConverging;
  candidates_ = hypotheses;
  candidatesOdometry_ = scan.odometry;
  travelSinceRecognitionM_ = 0.0;
  traversedInto_.reset();
  seed(hypotheses);
  mcl_.update(scan);
}

void GlobalLocalizer::seed(const std::vector<PoseCandidate>& candidates) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const double best = std::max_element(candidates.begin(), candidates.end(), [](const PoseCandidate& a, const PoseCandidate& b) {
                        return a.score < b.score;
                      })->score;
  const std::size_t each = config_.seedParticles / candidates.size();
  std::vector<Particle> particles;
  particles.reserve(each * candidates.size());
  for (const PoseCandidate& c : candidates) {
    const double weight = std::exp(config_.seedFitGain * (c.score - best));
    for (std::size_t i = 0; i < each; ++i)
      particles.push_back({c.region,
                           {c.regionPose.x + config_.seedSigmaXyM * normal(rng_), c.regionPose.y + config_.seedSigmaXyM * normal(rng_),
                            normalizeAngle(c.regionPose.theta + config_.seedSigmaThetaRad * normal(rng_))},
                           weight});
  }
  mcl_.setParticles(std::move(particles));
}

}  // namespace rgnav
