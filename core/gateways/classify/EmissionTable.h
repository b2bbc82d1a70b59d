// Log output probabilities of a Gaussian mixture HMM for every observation of a sequence:
// log b_j(o_t) and its per-component terms log c_jm + log N(o_t; mu_jm, U_jm) (Rabiner 1989,
// eq. 49), shared by the forward-backward recursions and the Baum-Welch mixture update.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/gateways/classify/GaussianMixtureHmm.h"

namespace rgnav {

struct EmissionTable {
  Eigen::MatrixXd state;                   // T x Q: log b_j(o_t)
  std::vector<Eigen::MatrixXd> component;  // per state j, T x M_j: log c_jm + log N(o_t)
};

// `observations` holds one observation per column (dimension x T). Throws InvalidArgumentError
// if the dimension differs from the model's or the sequence is empty.
EmissionTable logEmissions(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& observations);

}  // namespace rgnav
