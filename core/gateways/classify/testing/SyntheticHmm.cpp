// Known left-right HMMs and seeded sampling from them (see SyntheticHmm.h).
#include "core/gateways/classify/testing/SyntheticHmm.h"

#include <Eigen/Cholesky>

namespace rgnav::testing {

namespace {

// Index drawn with the given probabilities.
Eigen::Index draw(const Eigen::VectorXd& probabilities, std::mt19937_64& rng) {
  std::discrete_distribution<Eigen::Index> distribution(probabilities.data(),
                                                        probabilities.data() + probabilities.size());
  return distribution(rng);
}

Eigen::VectorXd drawGaussian(const MultivariateGaussian& g, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd z(g.dimension());
  for (Eigen::Index i = 0; i < z.size(); ++i) z[i] = normal(rng);
  return g.mean() + g.covariance().llt().matrixL() * z;
}

}  // namespace

GaussianMixtureHmm leftRightHmm(const std::vector<Eigen::VectorXd>& stateMeans, double stdDev, double stay) {
  const auto q = static_cast<Eigen::Index>(stateMeans.size());
  GaussianMixtureHmm hmm{Eigen::VectorXd::Unit(q, 0), Eigen::MatrixXd::Zero(q, q), {}};
  for (Eigen::Index i = 0; i + 1 < q; ++i) {
    hmm.transitions(i, i) = stay;
    hmm.transitions(i, i + 1) = 1.0 - stay;
  }
  hmm.transitions(q - 1, q - 1) = 1.0;
  for (const Eigen::VectorXd& mean : stateMeans) {
    const Eigen::MatrixXd covariance = stdDev * stdDev * Eigen::MatrixXd::Identity(mean.size(), mean.size());
    hmm.states.push_back({{MultivariateGaussian(mean, covariance)}, Eigen::VectorXd::Ones(1)});
  }
  return hmm;
}

GatewayObservationSequence sampleSequence(const GaussianMixtureHmm& hmm, std::size_t length, double nearDistance,
                                          double step, std::mt19937_64& rng) {
  GatewayObservationSequence sequence;
  Eigen::Index state = draw(hmm.prior, rng);
  for (std::size_t t = 0; t < length; ++t) {
    if (t > 0) state = draw(hmm.transitions.row(state).transpose(), rng);
    const HmmState& s = hmm.states[static_cast<std::size_t>(state)];
    const MultivariateGaussian& component = s.components[static_cast<std::size_t>(draw(s.mixtureWeights, rng))];
    sequence.push_back({nearDistance + static_cast<double>(length - 1 - t) * step, drawGaussian(component, rng)});
  }
  return sequence;
}

}  // namespace rgnav::testing
