// Euclidean clustering of 2D points (single linkage): points closer than maxGapM end up in the
// same cluster. A hash grid of cell size maxGapM keeps it linear in the number of points. Used
// to cut a region's scan points into object candidates for circle detection (Table 2.1).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace rgnav {

// Clusters as lists of indices into `points`, each in increasing order; clusters ordered by
// their first index. Throws InvalidArgumentError unless maxGapM > 0.
std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Eigen::Vector2d>& points, double maxGapM);

}  // namespace rgnav
