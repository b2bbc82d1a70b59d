// Gauss-Newton iterations with re-association at every step.
#include "core/slam/ScanRefinement.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace rgnav {

namespace {

struct NormalEquations {
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
  std::size_t correspondences = 0;
  std::size_t inliers = 0;
};

NormalEquations linearize(const ReferenceMap& reference, std::span<const Eigen::Vector2f> query, const Pose2D& pose,
                          const IcpConfig& config) {
  NormalEquations eq;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double maxDistance2 = config.maxCorrespondence * config.maxCorrespondence;
  const PointGrid& grid = reference.grid();
  for (const Eigen::Vector2f& qf : query) {
    const Eigen::Vector2d rotated(c * qf.x() - s * qf.y(), s * qf.x() + c * qf.y());
    const Eigen::Vector2d p(rotated.x() + pose.x, rotated.y() + pose.y);
    const Eigen::Vector2i cell = grid.cellOf(p);
    const int j = grid.nearest(cell.x(), cell.y());
    if (j < 0) continue;
    const Eigen::Vector2d& normal = reference.normals()[static_cast<std::size_t>(j)];
    if (normal.isZero()) continue;
    const Eigen::Vector2d d = p - reference.points()[static_cast<std::size_t>(j)];
    if (d.squaredNorm() > maxDistance2) continue;
    const double r = normal.dot(d);
    const Eigen::Vector3d jacobian(normal.x(), normal.y(), normal.x() * -rotated.y() + normal.y() * rotated.x());
    const double weight = std::abs(r) <= config.huberDelta ? 1.0 : config.huberDelta / std::abs(r);
    eq.hessian += weight * jacobian * jacobian.transpose();
    eq.gradient += weight * r * jacobian;
    ++eq.correspondences;
    if (std::abs(r) <= config.inlierResidual) ++eq.inliers;
  }
  return eq;
}

}  // namespace

std::optional<Refinement> refinePointToLine(const ReferenceMap& reference, std::span<const Eigen::Vector2f> query,
                                            const Pose2D& initial, const IcpConfig& config, const PosePrior* prior) {
  if (reference.empty() || query.empty()) return std::nullopt;
  const double pointWeight = 1.0 / (config.pointSigma * config.pointSigma);
  Pose2D pose = initial;
  NormalEquations eq;
  double scale = 0.0;
  for (std::size_t iteration = 0; iteration < config.maxIterations; ++iteration) {
    eq = linearize(reference, query, pose, config);
    if (eq.correspondences < 3 && prior == nullptr) return std::nullopt;
    scale = pointWeight * std::min(1.0, config.effectivePoints / std::max<double>(1.0, eq.correspondences));
    Eigen::Matrix3d hessian = scale * eq.hessian;
    Eigen::Vector3d gradient = scale * eq.gradient;
    if (prior != nullptr) {
      const Eigen::Vector3d e(pose.x - prior->pose.x, pose.y - prior->pose.y, normalizeAngle(pose.theta - prior->pose.theta));
      hessian += prior->information;
      gradient += prior->information * e;
    }
    const Eigen::LDLT<Eigen::Matrix3d> solver(hessian);
    if (solver.info() != Eigen::Success || !solver.isPositive()) return std::nullopt;
    const Eigen::Vector3d step = -solver.solve(gradient);
    if (!step.allFinite()) return std::nullopt;
    pose = {pose.x + step.x(), pose.y + step.y(), normalizeAngle(pose.theta + step.z())};
    if (step.cwiseAbs().maxCoeff() < config.convergedStep) break;
  }
  eq = linearize(reference, query, pose, config);
  Refinement result;
  result.pose = pose;
  scale = pointWeight * std::min(1.0, config.effectivePoints / std::max<double>(1.0, eq.correspondences));
  result.pointInformation = scale * eq.hessian;
  result.inliers = eq.inliers;
  result.inlierFraction = static_cast<double>(eq.inliers) / static_cast<double>(query.size());
  return result;
}

}  // namespace rgnav
