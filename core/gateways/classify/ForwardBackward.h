// The forward and backward recursions of Rabiner 1989 (eqs. 19-21 and 23-25) in log space with
// log-sum-exp, and the sequence log-likelihood log P(O | lambda) (eq. 21) that the HMM gateway
// classifier compares (thesis 4.1.3.3). Differs from Rabiner only in working with logarithms
// instead of scale factors (section V.A); zero probabilities are -inf and stay exact.
#pragma once

#include <Eigen/Core>

#include "core/gateways/classify/GaussianMixtureHmm.h"

namespace rgnav {

// log alpha_t(i), T x Q, from the T x Q table of log b_j(o_t).
Eigen::MatrixXd logForward(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& stateLogEmissions);

// log beta_t(i), T x Q, from the same table.
Eigen::MatrixXd logBackward(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& stateLogEmissions);

// log P(O | lambda) for the observations in the columns of `observations` (dimension x T).
double logLikelihood(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& observations);

}  // namespace rgnav
