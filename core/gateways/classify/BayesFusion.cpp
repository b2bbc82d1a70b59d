// Bayes filter over gateway classes (thesis 4.1.4; see BayesFusion.h).
#include "core/gateways/classify/BayesFusion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/Errors.h"
#include "core/gateways/classify/LogSumExp.h"

namespace rgnav {

GatewayClass GatewayPosterior::best() const {
  if (probabilities.size() == 0) throw InvalidArgumentError("empty class posterior");
  Eigen::Index index = 0;
  probabilities.maxCoeff(&index);
  return classes[static_cast<std::size_t>(index)];
}

double GatewayPosterior::probabilityOf(GatewayClass c) const {
  const auto it = std::find(classes.begin(), classes.end(), c);
  if (it == classes.end()) {
    throw InvalidArgumentError("class " + std::string(gatewayClassName(c)) + " is not in the posterior");
  }
  return probabilities[it - classes.begin()];
}

Eigen::VectorXd bayesUpdate(const Eigen::VectorXd& prior, const Eigen::VectorXd& logLikelihoods) {
  if (prior.size() != logLikelihoods.size()) throw InvalidArgumentError("prior and likelihoods differ in size");
  if (prior.hasNaN() || logLikelihoods.hasNaN()) throw InvalidArgumentError("NaN in a Bayes update");
  const Eigen::VectorXd logPosterior = prior.array().log().matrix() + logLikelihoods;
  const double normaliser = logSumExp(logPosterior);
  if (!std::isfinite(normaliser)) throw InvalidArgumentError("no class explains the observations");
  return (logPosterior.array() - normaliser).exp();
}

}  // namespace rgnav
