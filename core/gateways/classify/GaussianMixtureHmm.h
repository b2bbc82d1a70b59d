// GaussianMixtureHmm: a hidden Markov model with continuous outputs, lambda = (pi, A, c, mu, U)
// in the notation of Rabiner 1989 (eqs. 11-13, 49): state prior pi, transition matrix A, and per
// state a mixture of full-covariance Gaussians with mixture weights c (the rows of the thesis'
// mixture matrix M_mix, 4.1.3.3). States may hold different numbers of components instead of
// padding M_mix to the largest; in the gateway HMMs state 0 is the farthest ("left").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/gateways/classify/MultivariateGaussian.h"

namespace rgnav {

struct HmmState {
  std::vector<MultivariateGaussian> components;
  Eigen::VectorXd mixtureWeights;  // one per component, summing to 1
};

struct GaussianMixtureHmm {
  Eigen::VectorXd prior;        // pi_i = P(q_1 = S_i)
  Eigen::MatrixXd transitions;  // A(i, j) = P(q_t+1 = S_j | q_t = S_i)
  std::vector<HmmState> states;

  Eigen::Index stateCount() const { return static_cast<Eigen::Index>(states.size()); }
  Eigen::Index dimension() const;  // of the observations; 0 without states
};

// Throws InvalidArgumentError unless the model has states, all components share one dimension,
// and prior, every row of A and every mixture weight vector are probability vectors (tolerance
// 1e-6) of the right size.
void validateHmm(const GaussianMixtureHmm& hmm);

}  // namespace rgnav
