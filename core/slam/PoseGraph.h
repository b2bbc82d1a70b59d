// optimizePoseGraph: least-squares optimisation of 2D keyframe poses under relative-pose
// constraints (graph-based SLAM as in Lu & Milios 1997, Konolige et al. 2010 and Grisetti et al.
// 2010, tutorial on graph-based SLAM), solved with Ceres (sparse Cholesky, Levenberg-Marquardt).
// Loop constraints get a Cauchy loss so that a wrong revisit is down-weighted instead of bending
// the map (Cartographer puts a Huber loss on its loop constraints, Hess et al. 2016); unlike a
// single robust solve, when a loop's residual is far out in the loss's tail we first solve with a
// much wider Cauchy loss (two-step graduated non-convexity), so a correct loop that corrects a
// large drift is not rejected. The first pose is held fixed.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/slam/SlamConfig.h"
#include "core/slam/SlamState.h"

namespace rgnav {

struct OptimizationSummary {
  std::size_t iterations = 0;
  double initialCost = 0.0;  // before the first step, with that step's loss
  double finalCost = 0.0;    // with the robust loss
  bool usable = false;  // Ceres reached a solution it considers usable
};

// Optimises `poses` in place (indices as in the constraints). Throws InvalidArgumentError if a
// constraint names a pose that does not exist or has an information matrix that is not positive
// definite. Deterministic: single-threaded.
OptimizationSummary optimizePoseGraph(std::vector<Pose2D>& poses, std::span<const Constraint> constraints,
                                      const PoseGraphConfig& config);

}  // namespace rgnav
