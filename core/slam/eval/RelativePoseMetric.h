// The relative-pose error of Kümmerle et al. 2009 ("On measuring the accuracy of SLAM
// algorithms"): for each relation (i, j) with reference displacement d*_ij, the error
// e_ij = d*_ij^-1 ⊕ (x_i^-1 ⊕ x_j); reported as mean ± standard deviation of |translation(e)| and
// |rotation(e)| over all relations (their tables' "absolute" errors; not the squared form).
#pragma once

#include <cstddef>
#include <functional>
#include <span>

#include "core/slam/eval/Relations.h"

namespace rgnav {

struct RelativePoseError {
  std::size_t relations = 0;
  double translationMean = 0.0;  // m
  double translationStd = 0.0;   // m, population standard deviation
  double rotationMean = 0.0;     // rad
  double rotationStd = 0.0;      // rad
};

// `pose(id)` gives the estimated pose of a scan. All zero for no relations.
RelativePoseError relativePoseError(std::span<const ScanRelation> relations, const std::function<Pose2D(DataId)>& pose);

}  // namespace rgnav
