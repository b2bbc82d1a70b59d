// Multivariate normal log density (Bishop 2006, eq. 2.43; see MultivariateGaussian.h).
#include "core/gateways/classify/MultivariateGaussian.h"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/common/Errors.h"

namespace rgnav {

MultivariateGaussian::MultivariateGaussian(Eigen::VectorXd mean, Eigen::MatrixXd covariance)
    : mean_(std::move(mean)), covariance_(std::move(covariance)) {
  const Eigen::Index d = mean_.size();
  if (d == 0) throw InvalidArgumentError("MultivariateGaussian of dimension 0");
  if (covariance_.rows() != d || covariance_.cols() != d) {
    throw InvalidArgumentError("MultivariateGaussian covariance is not " + std::to_string(d) + "x" + std::to_string(d));
  }
  if (!mean_.allFinite() || !covariance_.allFinite())
    throw InvalidArgumentError("MultivariateGaussian has a non-finite entry");
  if (!covariance_.isApprox(covariance_.transpose(), 1e-9)) {
    throw InvalidArgumentError("MultivariateGaussian covariance is not symmetric");
  }
  cholesky_.compute(covariance_);
  if (cholesky_.info() != Eigen::Success)
    throw InvalidArgumentError("MultivariateGaussian covariance is not positive definite");
  const double logDet = 2.0 * cholesky_.matrixLLT().diagonal().array().log().sum();
  logNormaliser_ = -0.5 * (static_cast<double>(d) * std::log(2.0 * std::numbers::pi) + logDet);
}

double MultivariateGaussian::logDensity(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const Eigen::VectorXd z = cholesky_.matrixL().solve(x - mean_);
  return logNormaliser_ - 0.5 * z.squaredNorm();
}

}  // namespace rgnav
