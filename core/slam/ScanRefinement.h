// refinePointToLine: Gauss-Newton point-to-line ICP (Censi 2008, PLICP) of a scan against a
// ReferenceMap, optionally fused with a Gaussian prior on the pose (the odometry prediction).
// Differences from PLICP: correspondences come from the reference grid's nearest point and the
// line is that point's PCA normal; residuals are Huber-weighted; the prior enters the normal
// equations, so the result is the maximum a posteriori pose given scan and odometry.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <span>

#include "core/common/Pose2D.h"
#include "core/slam/ReferenceMap.h"
#include "core/slam/SlamConfig.h"

namespace rgnav {

struct PosePrior {
  Pose2D pose;
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();  // x, y, theta
};

struct Refinement {
  Pose2D pose;
  // The information the scan points alone carry about the pose (scaled to icp.effectivePoints).
  Eigen::Matrix3d pointInformation = Eigen::Matrix3d::Zero();
  std::size_t inliers = 0;     // points within icp.inlierResidual of their line
  double inlierFraction = 0.0; // inliers / query points
};

// `query`: points in the sensor frame. Returns nullopt if the reference is empty or the problem is
// degenerate (too few correspondences and no prior).
std::optional<Refinement> refinePointToLine(const ReferenceMap& reference, std::span<const Eigen::Vector2f> query,
                                            const Pose2D& initial, const IcpConfig& config,
                                            const PosePrior* prior = nullptr);

}  // namespace rgnav
