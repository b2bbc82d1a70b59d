// Ceres problem of the 2D pose graph: one (x, y, theta) block per pose, one auto-differentiated
// relative-pose residual per constraint, whitened by the upper Cholesky factor of its information.
#include "core/slam/PoseGraph.h"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

// A loop whose whitened residual norm exceeds this many Cauchy scales (weight below 0.1) makes
// the optimisation start with a Cauchy loss this many times wider.
constexpr double kGraduation = 3.0;

template <typename T>
T wrapAngle(const T& a) {
  const T twoPi(2.0 * M_PI);
  return a - twoPi * ceres::floor((a + T(M_PI)) / twoPi);
}

// The residual of `to` relative to `from` against the measured relative pose, in `from`'s frame.
class RelativePoseError {
 public:
  RelativePoseError(const Pose2D& measurement, const Eigen::Matrix3d& sqrtInformation)
      : measurement_(measurement), sqrtInformation_(sqrtInformation) {}

  template <typename T>
  bool operator()(const T* from, const T* to, T* residual) const {
    const T c = ceres::cos(from[2]), s = ceres::sin(from[2]);
    const T dx = to[0] - from[0], dy = to[1] - from[1];
    Eigen::Matrix<T, 3, 1> e;
    e(0) = c * dx + s * dy - T(measurement_.x);
    e(1) = -s * dx + c * dy - T(measurement_.y);
    e(2) = wrapAngle(to[2] - from[2] - T(measurement_.theta));
    Eigen::Map<Eigen::Matrix<T, 3, 1>> out(residual);
    out = sqrtInformation_.cast<T>() * e;
    return true;
  }

 private:
  Pose2D measurement_;
  Eigen::Matrix3d sqrtInformation_;
};

void checkConstraint(const Constraint& constraint, std::size_t poses, const Eigen::LLT<Eigen::Matrix3d>& llt) {
  const std::string name = "slam: constraint " + std::to_string(constraint.from) + " -> " + std::to_string(constraint.to);
  if (constraint.from >= poses || constraint.to >= poses || constraint.from == constraint.to)
    throw InvalidArgumentError(name + " names no pair of poses");
  if (llt.info() != Eigen::Success) throw InvalidArgumentError(name + " has no positive definite information");
}

}  // namespace

OptimizationSummary optimizePoseGraph(std::vector<Pose2D>& poses, std::span<const Constraint> constraints,
                                      const PoseGraphConfig& config) {
  OptimizationSummary summary;
  if (poses.size() < 2 || constraints.empty()) {
    summary.usable = true;
    return summary;
  }
  std::vector<std::array<double, 3>> blocks(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) blocks[i] = {poses[i].x, poses[i].y, poses[i].theta};

  ceres::Problem::Options problemOptions;
  problemOptions.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problemOptions);
  ceres::LossFunctionWrapper loopLoss(nullptr, ceres::DO_NOT_TAKE_OWNERSHIP);
  std::vector<ceres::ResidualBlockId> loops;
  for (const Constraint& constraint : constraints) {
    const Eigen::LLT<Eigen::Matrix3d> llt(constraint.information);
    checkConstraint(constraint, poses.size(), llt);
    const Eigen::Matrix3d upper = llt.matrixU();
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseError, 3, 3, 3>(
        new RelativePoseError(constraint.measurement, upper));
    const bool loop = constraint.kind == Constraint::Kind::Loop;
    const auto id = problem.AddResidualBlock(cost, loop ? &loopLoss : nullptr, blocks[constraint.from].data(),
                                             blocks[constraint.to].data());
    if (loop) loops.push_back(id);
  }
  if (problem.HasParameterBlock(blocks[0].data())) problem.SetParameterBlockConstant(blocks[0].data());

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = static_cast<int>(config.maxIterations);
  options.function_tolerance = config.functionTolerance;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;

  const double gate = kGraduation * config.loopLossScale;
  const bool graduated = std::any_of(loops.begin(), loops.end(), [&](ceres::ResidualBlockId id) {
    double cost = 0.0;
    problem.EvaluateResidualBlock(id, false, &cost, nullptr, nullptr);
    return 2.0 * cost > gate * gate;
  });
  ceres::Solver::Summary step;
  if (graduated) {
    ceres::CauchyLoss wide(gate * kGraduation);
    loopLoss.Reset(&wide, ceres::DO_NOT_TAKE_OWNERSHIP);
    ceres::Solve(options, &problem, &step);
    summary.initialCost = step.initial_cost;
    summary.iterations = step.iterations.size();
  }
  ceres::CauchyLoss cauchy(config.loopLossScale);
  loopLoss.Reset(&cauchy, ceres::DO_NOT_TAKE_OWNERSHIP);
  ceres::Solve(options, &problem, &step);
  if (!graduated) summary.initialCost = step.initial_cost;
  summary.iterations += step.iterations.size();
  summary.finalCost = step.final_cost;
  summary.usable = step.IsSolutionUsable();
  if (!summary.usable) return summary;
  for (std::size_t i = 0; i < poses.size(); ++i) poses[i] = {blocks[i][0], blocks[i][1], normalizeAngle(blocks[i][2])};
  return summary;
}

}  // namespace rgnav
