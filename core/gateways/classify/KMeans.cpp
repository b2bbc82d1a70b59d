// Lloyd's k-means with squared Euclidean distance (Bishop 2006, eqs. 9.2-9.4; see KMeans.h).
#include "core/gateways/classify/KMeans.h"

#include <utility>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

Eigen::Index nearestCentre(const Eigen::MatrixXd& centres, const Eigen::Ref<const Eigen::VectorXd>& x) {
  Eigen::Index best = 0;
  (centres.colwise() - x).colwise().squaredNorm().minCoeff(&best);
  return best;
}

}  // namespace

KMeansResult kMeans(const Eigen::MatrixXd& points, Eigen::MatrixXd initialCentres, int maxIterations) {
  if (points.cols() == 0 || initialCentres.cols() == 0) throw InvalidArgumentError("k-means needs points and centres");
  if (points.rows() != initialCentres.rows()) throw InvalidArgumentError("k-means centres have another dimension");
  if (maxIterations < 0) throw InvalidArgumentError("k-means iteration limit is negative");
  const Eigen::Index k = initialCentres.cols();
  KMeansResult result{std::move(initialCentres), std::vector<Eigen::Index>(static_cast<std::size_t>(points.cols())), 0,
                      false};
  // Assigns every point to its nearest centre; true if any assignment changed.
  const auto assign = [&points, &result] {
    bool changed = false;
    for (Eigen::Index p = 0; p < points.cols(); ++p) {
      const Eigen::Index c = nearestCentre(result.centres, points.col(p));
      changed = changed || c != result.assignment[static_cast<std::size_t>(p)];
      result.assignment[static_cast<std::size_t>(p)] = c;
    }
    return changed;
  };
  assign();
  while (result.iterations < maxIterations && !result.converged) {
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(points.rows(), k);
    Eigen::VectorXd counts = Eigen::VectorXd::Zero(k);
    for (Eigen::Index p = 0; p < points.cols(); ++p) {
      sums.col(result.assignment[static_cast<std::size_t>(p)]) += points.col(p);
      counts[result.assignment[static_cast<std::size_t>(p)]] += 1.0;
    }
    for (Eigen::Index c = 0; c < k; ++c) {
      if (counts[c] > 0.0) result.centres.col(c) = sums.col(c) / counts[c];
    }
    ++result.iterations;
    result.converged = !assign();
  }
  return result;
}

}  // namespace rgnav
