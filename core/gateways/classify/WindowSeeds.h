// Start values for k-means as the thesis computes them (4.1.3.3, "Clustering the Data"): the
// training observations of one class, sorted by distance, are covered by k overlapping windows of
// equal size, and the mean of each window is one start value. With N observations and overlap
// o in [0, 1) a window holds w = N / (1 + (k - 1)(1 - o)) observations and starts w(1 - o) after
// the previous one, so that the k windows end exactly at the last observation.
#pragma once

#include <Eigen/Core>

namespace rgnav {

// `sortedPoints` holds one observation per column, ordered by distance. Returns dimension x k.
// Throws InvalidArgumentError unless 1 <= k <= N and 0 <= overlap < 1.
Eigen::MatrixXd slidingWindowMeans(const Eigen::MatrixXd& sortedPoints, Eigen::Index k, double overlap);

}  // namespace rgnav
