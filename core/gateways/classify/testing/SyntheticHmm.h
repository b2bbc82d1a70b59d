// Test helpers: known left-right HMMs (thesis figure 4.6) and observation sequences drawn from
// them with a seeded generator, so that learned models can be checked against the truth.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <random>
#include <vector>

#include "core/gateways/classify/GatewayObservation.h"
#include "core/gateways/classify/GaussianMixtureHmm.h"

namespace rgnav::testing {

// One isotropic Gaussian (standard deviation `stdDev`) per state mean; the model starts in state 0,
// stays with probability `stay` and otherwise moves to the next state; the last state is absorbing.
GaussianMixtureHmm leftRightHmm(const std::vector<Eigen::VectorXd>& stateMeans, double stdDev, double stay);

// `length` observations drawn from `hmm` (state path from prior and transitions, each observation
// from its state's mixture), made `step` metres apart while approaching down to `nearDistance`.
GatewayObservationSequence sampleSequence(const GaussianMixtureHmm& hmm, std::size_t length, double nearDistance,
                                          double step, std::mt19937_64& rng);

}  // namespace rgnav::testing
