// Log-space forward and backward recursions (Rabiner 1989, eqs. 19-25; see ForwardBackward.h).
#include "core/gateways/classify/ForwardBackward.h"

#include "core/gateways/classify/EmissionTable.h"
#include "core/gateways/classify/LogSumExp.h"

namespace rgnav {

Eigen::MatrixXd logForward(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& stateLogEmissions) {
  const Eigen::MatrixXd logA = hmm.transitions.array().log();
  const Eigen::Index length = stateLogEmissions.rows();
  const Eigen::Index q = hmm.stateCount();
  Eigen::MatrixXd alpha(length, q);
  alpha.row(0) = hmm.prior.array().log().transpose() + stateLogEmissions.row(0).array();
  for (Eigen::Index t = 1; t < length; ++t) {
    for (Eigen::Index j = 0; j < q; ++j) {
      alpha(t, j) = logSumExp(alpha.row(t - 1).transpose() + logA.col(j)) + stateLogEmissions(t, j);
    }
  }
  return alpha;
}

Eigen::MatrixXd logBackward(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& stateLogEmissions) {
  const Eigen::MatrixXd logA = hmm.transitions.array().log();
  const Eigen::Index length = stateLogEmissions.rows();
  const Eigen::Index q = hmm.stateCount();
  Eigen::MatrixXd beta(length, q);
  beta.row(length - 1).setZero();
  for (Eigen::Index t = length - 2; t >= 0; --t) {
    const Eigen::VectorXd next = (stateLogEmissions.row(t + 1) + beta.row(t + 1)).transpose();
    for (Eigen::Index i = 0; i < q; ++i) beta(t, i) = logSumExp(logA.row(i).transpose() + next);
  }
  return beta;
}

double logLikelihood(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& observations) {
  const Eigen::MatrixXd alpha = logForward(hmm, logEmissions(hmm, observations).state);
  return logSumExp(alpha.row(alpha.rows() - 1));
}

}  // namespace rgnav
