// SlamConfig: every parameter of the scan mapper (thesis 5.2 ScanMapper module), SI units,
// with defaults tuned on the Intel and Freiburg 079 logs of data/laser/. validate() rejects
// values that can never work with a ConfigError naming the key. describe() lists each struct's
// keys for config/modules/scanmapper.yaml (core/config/DescribedConfig.h).
#pragma once

#include <cstddef>

namespace rgnav {

// Thesis 5.2: scans are taken into the map only at certain distance or angle intervals.
struct KeyframeFilterConfig {
  double minTranslation = 0.2;  // m travelled (odometry) since the last keyframe
  double minRotation = 0.15;    // rad turned (odometry) since the last keyframe
};

template <class V>
void describe(V& v, KeyframeFilterConfig& c) {
  v.field("min_translation_m", c.minTranslation);
  v.field("min_rotation_rad", c.minRotation);
}

// Which beams become points, and how their surface normals are estimated.
struct ScanPointsConfig {
  double minRange = 0.1;        // m; shorter returns hit the robot itself
  double maxRange = 30.0;       // m; longer returns are too noisy in angle to help
  std::size_t normalHalfWindow = 3;  // beams on either side used for a normal
  double normalRadius = 0.3;    // m; neighbours farther than this from the point are ignored
  double maxPlanarity = 0.1;    // smallest / largest eigenvalue above this: no normal
  std::size_t minPoints = 20;   // fewer points: the scan is not registered (odometry only)
};

template <class V>
void describe(V& v, ScanPointsConfig& c) {
  v.field("min_range_m", c.minRange);
  v.field("max_range_m", c.maxRange);
  v.field("normal_half_window_beams", c.normalHalfWindow);
  v.field("normal_radius_m", c.normalRadius);
  v.field("max_planarity", c.maxPlanarity);
  v.field("min_points", c.minPoints);
}

// Rasterisation of a reference point set for the correlative search and the nearest-point look-up.
struct GridConfig {
  double resolution = 0.05;     // m per cell
  double sigma = 0.05;          // m; likelihood exp(-d^2 / 2 sigma^2) of distance d to the nearest point
  double nearestRadius = 0.2;   // m; cells farther from every point have no nearest point
};

template <class V>
void describe(V& v, GridConfig& c) {
  v.field("resolution_m", c.resolution);
  v.field("sigma_m", c.sigma);
  v.field("nearest_radius_m", c.nearestRadius);
}

// Gauss-Newton point-to-line refinement.
struct IcpConfig {
  std::size_t maxIterations = 20;
  double maxCorrespondence = 0.2;  // m; farther pairs are not used
  double huberDelta = 0.02;        // m; residuals beyond this are down-weighted
  double inlierResidual = 0.05;    // m; points closer than this to their line count as inliers
  double convergedStep = 1e-5;     // m or rad; a smaller update ends the iteration
  double pointSigma = 0.03;        // m; standard deviation of one point-to-line residual
  double effectivePoints = 30.0;   // the information of a match is that of this many independent points
};

template <class V>
void describe(V& v, IcpConfig& c) {
  v.field("max_iterations", c.maxIterations);
  v.field("max_correspondence_m", c.maxCorrespondence);
  v.field("huber_delta_m", c.huberDelta);
  v.field("inlier_residual_m", c.inlierResidual);
  v.field("converged_step_m_or_rad", c.convergedStep);
  v.field("point_sigma_m", c.pointSigma);
  v.field("effective_points", c.effectivePoints);
}

// Odometry error model (standard deviations grow with the motion), for the registration prior
// and for edges where no registration was possible.
struct OdometryModelConfig {
  double translationPerMetre = 0.1;   // m per m travelled
  double rotationPerRadian = 0.1;     // rad per rad turned
  double rotationPerMetre = 0.05;     // rad per m travelled
  double minTranslation = 0.02;       // m
  double minRotation = 0.01;          // rad
};

template <class V>
void describe(V& v, OdometryModelConfig& c) {
  v.field("translation_m_per_m", c.translationPerMetre);
  v.field("rotation_rad_per_rad", c.rotationPerRadian);
  v.field("rotation_rad_per_m", c.rotationPerMetre);
  v.field("min_translation_m", c.minTranslation);
  v.field("min_rotation_rad", c.minRotation);
}

// Registration of each keyframe against the recent keyframes (local registration).
struct LocalRegistrationConfig {
  std::size_t windowKeyframes = 8;    // recent keyframes forming the local reference
  double searchTranslation = 0.4;     // m, half width of the correlative search window
  double searchRotation = 0.3;        // rad, half width
  double minScore = 0.3;              // correlative score [0, 1] below which registration fails
  double minInlierFraction = 0.2;     // of the scan's points after refinement
  GridConfig grid;
  OdometryModelConfig odometry;
};

template <class V>
void describe(V& v, LocalRegistrationConfig& c) {
  v.field("window_keyframes", c.windowKeyframes);
  v.field("search_translation_m", c.searchTranslation);
  v.field("search_rotation_rad", c.searchRotation);
  v.field("min_score", c.minScore);
  v.field("min_inlier_fraction", c.minInlierFraction);
  v.section("grid", c.grid);
  v.section("odometry", c.odometry);
}

// The test of a revisit's least-constrained direction (UndeterminedDirection.h): the position
// along it is undetermined if the point information along it is weak AND shifting the pose
// along it hardly lowers the correlative score.
struct UndeterminedDirectionConfig {
  double maxInformationRatio = 0.05;  // weakest / strongest translational point information below this
  double shift = 0.2;                 // m, both ways along the weakest direction
  double minScoreDrop = 0.03;         // relative drop of the score that the shift must reach to determine it
};

template <class V>
void describe(V& v, UndeterminedDirectionConfig& c) {
  v.field("max_information_ratio", c.maxInformationRatio);
  v.field("shift_m", c.shift);
  v.field("min_score_drop", c.minScoreDrop);
}

// Detection and verification of revisits against submaps of older keyframes.
struct LoopClosureConfig {
  std::size_t submapKeyframes = 10;       // consecutive keyframes per submap
  std::size_t excludeRecentKeyframes = 25;  // submaps reaching this close to the current keyframe are not searched
  double candidateRadius = 5.0;           // m, base distance from the current estimate to a submap's anchor
  double windowTranslation = 0.5;         // m, correlative search half width right after a loop closure
  double windowTranslationPerMetre = 0.03;  // m per m travelled since the last loop closure
  double maxWindowTranslation = 3.0;      // m
  double windowRotation = 0.1;            // rad
  double windowRotationPerMetre = 0.005;  // rad per m travelled since the last loop closure
  double maxWindowRotation = 0.5;         // rad
  std::size_t maxCandidates = 3;          // nearest submaps searched per keyframe
  double minScore = 0.6;                  // correlative score a revisit must reach
  double minInlierFraction = 0.6;         // of the scan's points after refinement
  UndeterminedDirectionConfig undetermined;  // a revisit constrains only the directions its scan determines
  std::size_t cachedSubmaps = 24;         // rasterised submaps kept in memory
  GridConfig grid;
};

template <class V>
void describe(V& v, LoopClosureConfig& c) {
  v.field("submap_keyframes", c.submapKeyframes);
  v.field("exclude_recent_keyframes", c.excludeRecentKeyframes);
  v.field("candidate_radius_m", c.candidateRadius);
  v.field("window_translation_m", c.windowTranslation);
  v.field("window_translation_m_per_m", c.windowTranslationPerMetre);
  v.field("max_window_translation_m", c.maxWindowTranslation);
  v.field("window_rotation_rad", c.windowRotation);
  v.field("window_rotation_rad_per_m", c.windowRotationPerMetre);
  v.field("max_window_rotation_rad", c.maxWindowRotation);
  v.field("max_candidates", c.maxCandidates);
  v.field("min_score", c.minScore);
  v.field("min_inlier_fraction", c.minInlierFraction);
  v.section("undetermined", c.undetermined);
  v.field("cached_submaps", c.cachedSubmaps);
  v.section("grid", c.grid);
}

// Pose graph optimisation (Ceres), incremental: run when loop constraints were added.
struct PoseGraphConfig {
  double loopLossScale = 3;                  // Cauchy scale on whitened loop residuals
  std::size_t maxIterations = 50;
  double functionTolerance = 1e-4;             // relative cost change that ends an optimisation
  std::size_t keyframesBetweenOptimizations = 20;  // pending loops wait at most this many keyframes
  double immediateCorrection = 0.1;            // m; a loop moving the current pose more optimises at once
  // Revisions (optimisations) whose keyframe poses are kept, the newest, so that a consumer that
  // follows the map can apply each one at the scan it belongs to (SlamState::revisions); each
  // holds every keyframe pose of its time (24 bytes a keyframe).
  std::size_t keptRevisions = 256;
};

template <class V>
void describe(V& v, PoseGraphConfig& c) {
  v.field("loop_loss_scale", c.loopLossScale);
  v.field("max_iterations", c.maxIterations);
  v.field("function_tolerance", c.functionTolerance);
  v.field("keyframes_between_optimizations", c.keyframesBetweenOptimizations);
  v.field("immediate_correction_m", c.immediateCorrection);
  v.field("kept_revisions", c.keptRevisions);
}

struct SlamConfig {
  KeyframeFilterConfig filter;
  ScanPointsConfig points;
  IcpConfig icp;
  LocalRegistrationConfig local;
  LoopClosureConfig loop;
  PoseGraphConfig graph;
};

template <class V>
void describe(V& v, SlamConfig& c) {
  v.section("filter", c.filter);
  v.section("points", c.points);
  v.section("icp", c.icp);
  v.section("local", c.local);
  v.section("loop", c.loop);
  v.section("graph", c.graph);
}

// Throws ConfigError naming the first invalid key.
void validate(const SlamConfig& config);

}  // namespace rgnav
