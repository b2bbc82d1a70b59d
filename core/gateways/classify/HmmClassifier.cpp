// Maximum a posteriori gateway classification with one HMM per class (thesis 4.1.3.3, 4.1.4;
// see HmmClassifier.h).
#include "core/gateways/classify/HmmClassifier.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/common/Errors.h"
#include "core/gateways/classify/ForwardBackward.h"

namespace rgnav {

HmmClassifier::HmmClassifier(std::vector<GatewayClassModel> models) : models_(std::move(models)) {
  if (models_.empty()) throw InvalidArgumentError("HMM classifier without models");
  for (std::size_t i = 0; i < models_.size(); ++i) {
    const GatewayClassModel& model = models_[i];
    const std::string name(gatewayClassName(model.gatewayClass));
    try {
      validateHmm(model.hmm);
    } catch (const InvalidArgumentError& e) {
      throw InvalidArgumentError(name + " model: " + e.what());
    }
    if (model.hmm.dimension() != dimension()) throw InvalidArgumentError(name + " model has another dimension");
    if (!(model.prior > 0.0) || !std::isfinite(model.prior))
      throw InvalidArgumentError(name + " prior is not positive");
    const auto sameClass = [&model](const GatewayClassModel& m) { return m.gatewayClass == model.gatewayClass; };
    if (std::any_of(models_.begin(), models_.begin() + static_cast<std::ptrdiff_t>(i), sameClass)) {
      throw InvalidArgumentError(name + " has two models");
    }
  }
}

std::vector<GatewayClass> HmmClassifier::classes() const {
  std::vector<GatewayClass> classes;
  for (const GatewayClassModel& m : models_) classes.push_back(m.gatewayClass);
  return classes;
}

Eigen::VectorXd HmmClassifier::priors() const {
  Eigen::VectorXd priors(static_cast<Eigen::Index>(models_.size()));
  for (std::size_t i = 0; i < models_.size(); ++i) priors[static_cast<Eigen::Index>(i)] = models_[i].prior;
  return priors / priors.sum();
}

HmmClassifier HmmClassifier::subset(const std::vector<GatewayClass>& classes) const {
  std::vector<GatewayClassModel> chosen;
  for (const GatewayClass c : classes) {
    const auto it =
        std::find_if(models_.begin(), models_.end(), [c](const GatewayClassModel& m) { return m.gatewayClass == c; });
    if (it == models_.end()) throw InvalidArgumentError("no model for " + std::string(gatewayClassName(c)));
    chosen.push_back(*it);
  }
  return HmmClassifier(std::move(chosen));
}

Eigen::VectorXd HmmClassifier::logLikelihoods(const GatewayObservationSequence& sequence) const {
  const Eigen::MatrixXd observations = weightMatrix(sequence, dimension());
  Eigen::VectorXd result(static_cast<Eigen::Index>(models_.size()));
  for (std::size_t i = 0; i < models_.size(); ++i) {
    result[static_cast<Eigen::Index>(i)] = logLikelihood(models_[i].hmm, observations);
  }
  return result;
}

GatewayPosterior HmmClassifier::classify(const GatewayObservationSequence& sequence) const {
  return classify(std::vector<GatewayObservationSequence>{sequence});
}

GatewayPosterior HmmClassifier::classify(const std::vector<GatewayObservationSequence>& sequences) const {
  // The sequences' log-likelihoods add up before the single update: no product underflows.
  Eigen::VectorXd total = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(models_.size()));
  for (const GatewayObservationSequence& sequence : sequences) total += logLikelihoods(sequence);
  return {classes(), bayesUpdate(priors(), total)};
}

}  // namespace rgnav
