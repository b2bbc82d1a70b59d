// Log output probabilities per observation, state and mixture component (Rabiner 1989, eq. 49).
#include "core/gateways/classify/EmissionTable.h"

#include <cmath>
#include <string>
#include <utility>

#include "core/common/Errors.h"
#include "core/gateways/classify/LogSumExp.h"

namespace rgnav {

EmissionTable logEmissions(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& observations) {
  if (observations.cols() == 0) throw InvalidArgumentError("HMM input sequence is empty");
  if (observations.rows() != hmm.dimension()) {
    throw InvalidArgumentError("HMM input has dimension " + std::to_string(observations.rows()) + ", model " +
                               std::to_string(hmm.dimension()));
  }
  const Eigen::Index length = observations.cols();
  EmissionTable table;
  table.state.resize(length, hmm.stateCount());
  for (Eigen::Index j = 0; j < hmm.stateCount(); ++j) {
    const HmmState& state = hmm.states[static_cast<std::size_t>(j)];
    const Eigen::Index m = static_cast<Eigen::Index>(state.components.size());
    Eigen::MatrixXd terms(length, m);
    for (Eigen::Index k = 0; k < m; ++k) {
      const double logWeight = std::log(state.mixtureWeights[k]);
      const MultivariateGaussian& g = state.components[static_cast<std::size_t>(k)];
      for (Eigen::Index t = 0; t < length; ++t) terms(t, k) = logWeight + g.logDensity(observations.col(t));
    }
    for (Eigen::Index t = 0; t < length; ++t) table.state(t, j) = logSumExp(terms.row(t));
    table.component.push_back(std::move(terms));
  }
  return table;
}

}  // namespace rgnav
