// registerScan: robust and accurate registration of a scan against a ReferenceMap: a correlative
// branch-and-bound search over a window (Olson 2009 / Hess et al. 2016) finds the basin, point-to-
// line Gauss-Newton (ScanRefinement) refines it, fused with an optional pose prior. Both the
// local registration and the loop-closure verification use it, with different windows and
// thresholds; without a prior (loop closing), a direction the scan does not determine (a
// corridor's axis, UndeterminedDirection.h) keeps the guess's position and no point information.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

#include "core/slam/CorrelativeSearch.h"
#include "core/slam/ScanRefinement.h"
#include "core/slam/SlamConfig.h"

namespace rgnav {

struct RegistrationCriteria {
  SearchWindow window;
  double minScore = 0.0;          // correlative score the search must reach
  double minInlierFraction = 0.0; // inliers of the refined pose
  // Without a prior: how a direction the scan does not determine is found (none: not tested).
  std::optional<UndeterminedDirectionConfig> undetermined = std::nullopt;
};

struct Registration {
  Pose2D pose;                   // sensor pose in the reference's frame
  Eigen::Matrix3d information;   // of that pose: scan points plus the prior, or without a prior the
                                 // scan points in the directions they determine plus a floor from
                                 // the search window (positive definite either way)
  double score = 0.0;            // correlative score
  double inlierFraction = 0.0;
};

// nullopt if the search finds nothing above minScore, the refinement fails, or too few inliers.
std::optional<Registration> registerScan(const ReferenceMap& reference, std::span<const Eigen::Vector2f> query,
                                         const Pose2D& guess, const RegistrationCriteria& criteria,
                                         const IcpConfig& icp, const PosePrior* prior = nullptr);

}  // namespace rgnav
