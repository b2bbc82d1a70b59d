// k-means start values from distance-sorted sliding windows (thesis 4.1.3.3; see WindowSeeds.h).
#include "core/gateways/classify/WindowSeeds.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

Eigen::MatrixXd slidingWindowMeans(const Eigen::MatrixXd& sortedPoints, Eigen::Index k, double overlap) {
  const Eigen::Index n = sortedPoints.cols();
  if (k < 1 || k > n) throw InvalidArgumentError("sliding windows need 1 <= k <= number of observations");
  if (!(overlap >= 0.0 && overlap < 1.0)) throw InvalidArgumentError("window overlap must lie in [0, 1)");
  const double width = static_cast<double>(n) / (1.0 + static_cast<double>(k - 1) * (1.0 - overlap));
  const double stride = width * (1.0 - overlap);
  Eigen::MatrixXd means(sortedPoints.rows(), k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const double start = static_cast<double>(i) * stride;
    const auto first = std::min(static_cast<Eigen::Index>(std::llround(start)), n - 1);
    const auto end = std::clamp(static_cast<Eigen::Index>(std::llround(start + width)), first + 1, n);
    means.col(i) = sortedPoints.middleCols(first, end - first).rowwise().mean();
  }
  return means;
}

}  // namespace rgnav
