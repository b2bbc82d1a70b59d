// MultivariateGaussian: a multivariate normal density with a full covariance matrix, evaluated
// in log space through its Cholesky factor (Bishop 2006, eq. 2.43). The output densities of the
// gateway HMMs are mixtures of these (Rabiner 1989, eq. 49).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace rgnav {

class MultivariateGaussian {
 public:
  // Throws InvalidArgumentError unless the covariance is a symmetric positive definite matrix
  // of the mean's dimension with finite entries.
  MultivariateGaussian(Eigen::VectorXd mean, Eigen::MatrixXd covariance);

  const Eigen::VectorXd& mean() const { return mean_; }
  const Eigen::MatrixXd& covariance() const { return covariance_; }
  Eigen::Index dimension() const { return mean_.size(); }

  // log N(x; mean, covariance).
  double logDensity(const Eigen::Ref<const Eigen::VectorXd>& x) const;

 private:
  Eigen::VectorXd mean_;
  Eigen::MatrixXd covariance_;
  Eigen::LLT<Eigen::MatrixXd> cholesky_;
  double logNormaliser_;  // -(d log(2 pi) + log det covariance) / 2
};

}  // namespace rgnav
