// Baum-Welch (EM) re-estimation of a Gaussian mixture HMM from several observation sequences
// (Rabiner 1989, eqs. 40a-c with the multi-sequence sums of eqs. 109-110, and eqs. 52 for the
// mixture weights), as the thesis uses it in 4.1.3.3: the prior, the transition matrix and the
// mixture weights are learned, the observation model (the Gaussians from clustering) stays
// fixed. EM therefore never decreases the training log-likelihood.
// Differences: a state that the data never visits (or never leaves) keeps its old row of A
// (or its old mixture weights) instead of a 0/0. Optionally (learnedCovarianceFloor set) the
// means and covariances are re-estimated as well (Rabiner eqs. 53-54), each covariance with the
// floor added to its diagonal - the spread the thesis gets by adding noise to the data - and a
// component that explains less than one observation keeps its Gaussian; the floor can cost a
// little likelihood, which then ends the iteration.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/gateways/classify/GaussianMixtureHmm.h"

namespace rgnav {

struct BaumWelchConfig {
  int maxIterations = 100;
  // Stop when one iteration gains less than tolerance * |log-likelihood|.
  double relativeTolerance = 1e-6;
  // Unset: the Gaussians stay fixed. Set: they are learned too, every covariance with this
  // variance added to its diagonal.
  std::optional<double> learnedCovarianceFloor;
};

struct BaumWelchResult {
  GaussianMixtureHmm hmm;
  // Total log-likelihood of the training sequences under the initial model and after every
  // iteration; the last entry belongs to `hmm`.
  std::vector<double> logLikelihoods;
  bool converged = false;
};

// `sequences` hold one observation per column. Throws InvalidArgumentError for an invalid
// model, no sequences, a sequence of another dimension or of length 0, or a floor that is not
// positive and finite.
BaumWelchResult trainBaumWelch(GaussianMixtureHmm initial, const std::vector<Eigen::MatrixXd>& sequences,
                               const BaumWelchConfig& config = {});

}  // namespace rgnav
