// HmmClassifier: the HMM gateway classifier of thesis 4.1.3.3 - one Gaussian mixture HMM per
// gateway class (Deadend and the Hallway counter-class included when trained), and a class
// prior each. A sequence goes to the class of the largest posterior, i.e. of the largest
// log P(O | lambda_c) + log P(c); with equal priors that is the maximum likelihood decision.
// Several sequences of the same gateway are fused with Bayes' rule (4.1.4, BayesFusion.h).
// Only the observation vectors (all their entries) enter the HMMs; the distances shape the
// models in training alone (HmmTrainer.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/gateways/classify/BayesFusion.h"
#include "core/gateways/classify/GatewayObservation.h"
#include "core/gateways/classify/GaussianMixtureHmm.h"

namespace rgnav {

struct GatewayClassModel {
  GatewayClass gatewayClass = GatewayClass::Hallway;
  GaussianMixtureHmm hmm;
  double prior = 1.0;  // relative; the classifier normalises the priors of all models
};

class HmmClassifier {
 public:
  // Throws InvalidArgumentError for no models, an invalid HMM, a class given twice, models of
  // different dimensions, or a prior that is not positive and finite.
  explicit HmmClassifier(std::vector<GatewayClassModel> models);

  const std::vector<GatewayClassModel>& models() const { return models_; }
  std::vector<GatewayClass> classes() const;
  Eigen::VectorXd priors() const;  // normalised, in model order
  Eigen::Index dimension() const { return models_.front().hmm.dimension(); }

  // A classifier with the models of `classes` only, in that order, e.g. for the pairwise
  // classification of thesis table 4.3. Throws InvalidArgumentError for a class without a model.
  HmmClassifier subset(const std::vector<GatewayClass>& classes) const;

  // log P(O | lambda_c) for every model, in model order (forward algorithm).
  Eigen::VectorXd logLikelihoods(const GatewayObservationSequence& sequence) const;

  // The posterior over the classes given one sequence.
  GatewayPosterior classify(const GatewayObservationSequence& sequence) const;
  // The posterior given several sequences of the same gateway (Bayes fusion); with no
  // sequences, the priors.
  GatewayPosterior classify(const std::vector<GatewayObservationSequence>& sequences) const;

 private:
  std::vector<GatewayClassModel> models_;
};

}  // namespace rgnav
