// GlobalLocalizer: localization without a known start, and recovery from kidnapping (issue 28,
// "global localization by region recognition"; thesis 5.3 leaves it as future work). It wraps a
// RegionMcl and decides where its particles go:
//   searching:  no particles. Scans gather in RecentScans (LocalObservation.h); once the robot
//               has moved firstRecognitionTravelM (or turned firstRecognitionTurnRad) by
//               odometry, RegionRecognizer ranks pose candidates over all regions and the filter
//               is seeded (setParticles) only around the best of them: at most seedCandidates
//               poses whose score lies within seedScoreMargin of the best, seedParticles split
//               evenly among them, drawn with seedSigma, weighted exp(seedFitGain * (score - best))
//               so that the filter starts from the recognizer's ranking without trusting it fully.
//   converging: the filter runs. Each time the robot has travelled reseedTravelM more, the
//               recognizer runs again on the grown observation and the action history prunes
//               its candidates: a new candidate survives only if some candidate of the previous
//               recognition, moved by the odometry travelled since, lands within
//               historyToleranceM + historyTolerancePerM * travel and historyToleranceRad of it,
//               in the same region or one that shares a gateway with the previous candidate's
//               (the RG graph's adjacency). If nothing survives, the new candidates are taken
//               unpruned (the earlier recognition had it wrong). The filter's own estimate
//               competes as one more candidate, scored the same way. The filter is reseeded with
//               the survivors. The filter's confirmed traversals (RegionMcl::takeTraversals) also
//               prune: after one, candidates must lie in the region it led into or next to it.
//               Localized once the travel since the first seed is at least confirmTravelM (two
//               recognitions agreed), the heaviest cluster holds localizedClusterWeight of the
//               weight, its position spread is below localizedSpreadM, and the fit per beam is
//               at least localizedFitPerBeam.
//   localized:  the filter tracks. Kidnapping is suspected when the estimate's fit per beam
//               (PoseEstimate::fitPerBeam: the odometry-predicted, corrected pose no longer
//               explains the scan) stays below kidnapFitPerBeam for kidnapUpdates updates in a
//               row, and confirmed when the recognizer, run on the newest scans only (the last
//               kidnapCheckTravelM of travel: those after the jump), finds a pose more than
//               kidnapDistanceM away that scores kidnapScoreMargin per point better than the
//               estimate does on the same scans (a low fit alone is often a view into space the
//               map does not hold). Then the older scans are dropped (they show the place before
//               the jump) and the filter is reseeded around the estimate and the recognizer's
//               candidates alike (at most seedCandidates, within seedScoreMargin of the best):
//               converging again, the filter decides between staying and the jump, and the usual
//               recognitions every reseedTravelM go on from there. If the better pose lies within
//               kidnapDistanceM, the filter has drifted (typically into a region whose line map
//               lacks walls the scan sees): it is reseeded around that pose and stays localized
//               (corrections()).
// Thresholds and weights, as chosen on Freiburg52 (a tuning map of the IPA split, rgctl eval
// globalloc --list prints the fit figures): a beam on a line scores log(zHit N(0) + zRand /
// maxRange) = 1.5 with the shipped beam model, one far from every line log(zRand / maxRange) =
// -5.7. Correctly localized in the SLAM-built map (with the region MCL as first merged; the
// later one-byte fields moved these by about 0.1 to 0.6), the fit per beam had median 0.9, 5th
// percentile -1.0, 1st -2.0 (views into unmapped space, furniture, the map's own distortion);
// estimates over 1 m off had median -0.5 but a 95th percentile of 0.9: a wrong place in a
// building of alike rooms fits as well as the right one, so the fit alone can neither confirm a
// pose nor prove a kidnapping. Hence localizedFitPerBeam = kidnapFitPerBeam = -0.5 only as a
// gate, kidnapUpdates = 20 (1 m of travel at one update per 5 cm, where more than 5 % of the
// correct scans fall below the gate) to ride out unmapped views,
// and the confirmation by recognition on the last 0.8 m (long enough to tell rooms apart, short
// enough to hold only scans after a jump that the 1 m of low fit followed), with a margin of 1.5
// per point (a wrong region typically scores 1 to 3 lower). confirmTravelM = 3 m means two
// recognitions 1.5 m apart agreed through the action history. The seed spread (0.15 m, 5 degrees)
// is about the recognizer's refinement error; a score margin of 1.0 per point keeps the
// candidates still plausible after the correlation; seedFitGain 3 weighs a candidate 1 per point
// worse by e^-3 at the start, so the filter starts from the ranking without trusting it fully.
// Deliberate difference from a plain MCL with uniform seeding: particles never go where the
// recognizer saw no fit, so a floor of thousands of square metres needs a few thousand particles,
// not hundreds of thousands.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "core/nav/localization/RegionMcl.h"
#include "core/nav/localization/RegionRecognition.h"

namespace rgnav {

struct GlobalLocalizerConfig {
  LocalObservationConfig observation;
  RecognitionConfig recognition;
  double firstRecognitionTravelM = 1.0;
  double firstRecognitionTurnRad = M_PI;
  std::size_t seedCandidates = 12;
  double seedScoreMargin = 1.0;
  std::size_t seedParticles = 3000;
  double seedSigmaXyM = 0.15;
  double seedSigmaThetaRad = 5.0 * M_PI / 180.0;
  double seedFitGain = 3.0;
  double reseedTravelM = 1.5;
  double historyToleranceM = 0.5;
  double historyTolerancePerM = 0.1;
  double historyToleranceRad = 15.0 * M_PI / 180.0;
  double confirmTravelM = 3.0;
  double localizedClusterWeight = 0.8;
  double localizedSpreadM = 0.2;
  double localizedFitPerBeam = -0.5;
  double kidnapFitPerBeam = -0.5;
  std::size_t kidnapUpdates = 20;
  double kidnapCheckTravelM = 0.8;
  double kidnapScoreMargin = 1.5;
  double kidnapDistanceM = 1.0;
};

enum class LocalizerState { kSearching, kConverging, kLocalized };

class GlobalLocalizer {
 public:
  // `map` must outlive the localizer; `regions` and `gateways` are the views it was made from.
  // Throws ConfigError for a bad configuration.
  GlobalLocalizer(const GlobalLocalizerConfig& config, const MclConfig& mcl, const LocalizationMap& map,
                  const std::vector<RegionView>& regions, const std::vector<GatewayView>& gateways, std::uint64_t seed);

  // The next scan with its odometry pose.
  void update(const LaserScan& scan);
  // Forget the pose and search again (e.g. the robot was carried away and the caller knows it).
  void relocalize();
  // An initial guess the caller trusts (RegionMcl::setPose): localized from the next scan on, the
  // kidnap watch guarding it. NotAvailableError if no region holds the pose.
  void setPose(const Pose2D& mapPose, const Eigen::Vector3d& sigma);

  LocalizerState state() const { return state_; }
  bool localized() const { return state_ == LocalizerState::kLocalized; }
  // The filter's estimate while it runs (converging or localized).
  std::optional<PoseEstimate> estimate() const;
  const RegionMcl& filter() const { return mcl_; }
  // The candidates of the latest recognition after pruning (best first).
  const std::vector<PoseCandidate>& candidates() const { return candidates_; }
  std::size_t recognitions() const { return recognitions_; }
  std::size_t kidnapsDetected() const { return kidnaps_; }
  std::size_t corrections() const { return corrections_; }
  // Traversals the filter confirmed while localized, since the last call (for the kernel).
  std::vector<ConfirmedTraversal> takeTraversals();

 private:
  void recognizeAndSeed(const LaserScan& scan);
  std::vector<PoseCandidate> pruneByHistory(std::vector<PoseCandidate> fresh, const Pose2D& odometry) const;
  bool adjacent(RegionId a, RegionId b) const;
  void seed(const std::vector<PoseCandidate>& candidates);
  // Seeds the filter with `hypotheses` and runs it on `scan`; converging from here.
  void startConverging(const std::vector<PoseCandidate>& hypotheses, const LaserScan& scan);
  void checkConvergence(const LaserScan& scan);
  void watchForKidnap();

  GlobalLocalizerConfig config_;
  const LocalizationMap& map_;
  RegionRecognizer recognizer_;
  RegionMcl mcl_;
  std::mt19937_64 rng_;
  std::map<RegionId, std::set<RegionId>> neighbours_;
  RecentScans recent_;
  LocalizerState state_ = LocalizerState::kSearching;
  std::optional<Pose2D> searchStart_;       // odometry when the search began
  double searchTurnRad_ = 0.0;              // odometry turn since then
  std::optional<Pose2D> lastOdometry_;
  std::vector<PoseCandidate> candidates_;   // of the last recognition
  std::optional<Pose2D> candidatesOdometry_;  // odometry at the last recognition
  double travelSinceSeedM_ = 0.0, travelSinceRecognitionM_ = 0.0;
  std::optional<RegionId> traversedInto_;   // the region the filter's last traversal led into
  std::vector<ConfirmedTraversal> traversals_;
  std::size_t lowFitUpdates_ = 0;
  std::size_t recognitions_ = 0, kidnaps_ = 0, corrections_ = 0;
};

}  // namespace rgnav
