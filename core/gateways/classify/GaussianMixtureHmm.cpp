// Consistency checks of a Gaussian mixture HMM (see GaussianMixtureHmm.h).
#include "core/gateways/classify/GaussianMixtureHmm.h"

#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

void checkProbabilities(const Eigen::VectorXd& p, Eigen::Index size, const std::string& what) {
  if (p.size() != size) {
    throw InvalidArgumentError(what + " has " + std::to_string(p.size()) + " entries, expected " +
                               std::to_string(size));
  }
  if (!p.allFinite() || (p.array() < 0.0).any() || std::abs(p.sum() - 1.0) > 1e-6) {
    throw InvalidArgumentError(what + " is not a probability vector");
  }
}

}  // namespace

Eigen::Index GaussianMixtureHmm::dimension() const {
  if (states.empty() || states.front().components.empty()) return 0;
  return states.front().components.front().dimension();
}

void validateHmm(const GaussianMixtureHmm& hmm) {
  const Eigen::Index q = hmm.stateCount();
  if (q == 0) throw InvalidArgumentError("HMM has no states");
  checkProbabilities(hmm.prior, q, "HMM prior");
  if (hmm.transitions.rows() != q || hmm.transitions.cols() != q) {
    throw InvalidArgumentError("HMM transition matrix is not " + std::to_string(q) + "x" + std::to_string(q));
  }
  for (Eigen::Index i = 0; i < q; ++i) {
    checkProbabilities(hmm.transitions.row(i).transpose(), q, "HMM transition row " + std::to_string(i));
  }
  const Eigen::Index d = hmm.dimension();
  for (Eigen::Index j = 0; j < q; ++j) {
    const HmmState& state = hmm.states[static_cast<std::size_t>(j)];
    const std::string name = "HMM state " + std::to_string(j);
    if (state.components.empty()) throw InvalidArgumentError(name + " has no mixture components");
    checkProbabilities(state.mixtureWeights, static_cast<Eigen::Index>(state.components.size()),
                       name + " mixture weights");
    for (const MultivariateGaussian& g : state.components) {
      if (g.dimension() != d) throw InvalidArgumentError(name + " has a component of another dimension");
    }
  }
}

}  // namespace rgnav
