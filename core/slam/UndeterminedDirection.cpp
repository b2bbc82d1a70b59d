// The weakest eigenvector of the translational information, two score probes along it, and the
// projection that removes it.
#include "core/slam/UndeterminedDirection.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace rgnav {

namespace {

// Mean likelihood [0, 1] of the points placed at `pose` (the correlative score off the lattice).
double meanLikelihood(const PointGrid& grid, std::span<const Eigen::Vector2f> query, const Pose2D& pose) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double sum = 0.0;
  for (const Eigen::Vector2f& q : query) {
    const Eigen::Vector2i cell = grid.cellOf({pose.x + c * q.x() - s * q.y(), pose.y + s * q.x() + c * q.y()});
    sum += grid.likelihood(cell.x(), cell.y());
  }
  return sum / (255.0 * static_cast<double>(query.size()));
}

}  // namespace

std::optional<Eigen::Vector2d> undeterminedDirection(const PointGrid& grid, std::span<const Eigen::Vector2f> query,
                                                     const Pose2D& pose, const Eigen::Matrix3d& pointInformation,
                                                     const UndeterminedDirectionConfig& config) {
  if (query.empty()) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(pointInformation.topLeftCorner<2, 2>());
  const Eigen::Vector2d& eigenvalues = solver.eigenvalues();  // ascending
  if (eigenvalues(0) >= config.maxInformationRatio * eigenvalues(1)) return std::nullopt;
  const Eigen::Vector2d direction = solver.eigenvectors().col(0);
  double shifted = 0.0;
  for (const double sign : {-1.0, 1.0}) {
    const Eigen::Vector2d offset = sign * config.shift * direction;
    shifted = std::max(shifted, meanLikelihood(grid, query, {pose.x + offset.x(), pose.y + offset.y(), pose.theta}));
  }
  if (shifted < (1.0 - config.minScoreDrop) * meanLikelihood(grid, query, pose)) return std::nullopt;
  return direction;
}

void dropDirection(Pose2D& pose, Eigen::Matrix3d& information, const Pose2D& guess, const Eigen::Vector2d& direction) {
  const double along = direction.dot(Eigen::Vector2d(guess.x - pose.x, guess.y - pose.y));
  pose.x += along * direction.x();
  pose.y += along * direction.y();
  Eigen::Matrix3d projection = Eigen::Matrix3d::Identity();
  projection.topLeftCorner<2, 2>() -= direction * direction.transpose();
  information = projection * information * projection;
}

}  // namespace rgnav
