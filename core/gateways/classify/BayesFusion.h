// Bayes fusion of gateway classifications (thesis 4.1.4, last paragraph: the HMM classifier
// gives probabilities for observation sequences, so the results of several sequences of the same
// gateway can be fused with a Bayes filter). With sequences O_1..O_n that are independent given
// the class c: P(c | O_1..O_n) ~ P(c) * prod_s P(O_s | c); one update folds in one sequence.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"

namespace rgnav {

struct GatewayPosterior {
  std::vector<GatewayClass> classes;
  Eigen::VectorXd probabilities;  // one per class, summing to 1

  GatewayClass best() const;  // the most probable class; ties go to the first
  // Throws InvalidArgumentError for a class that is not in `classes`.
  double probabilityOf(GatewayClass c) const;
};

// One Bayes filter step: the posterior from the prior probabilities and the log-likelihoods
// log P(O | c) of one more sequence, computed in log space. Throws InvalidArgumentError for
// mismatched sizes, a NaN, or when no class has a non-zero posterior.
Eigen::VectorXd bayesUpdate(const Eigen::VectorXd& prior, const Eigen::VectorXd& logLikelihoods);

}  // namespace rgnav
