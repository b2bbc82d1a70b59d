// Clustering, left-right structure and EM for the gateway HMMs (thesis 4.1.3.3; see
// HmmTrainer.h).
#include "core/gateways/classify/HmmTrainer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/common/Errors.h"
#include "core/gateways/classify/KMeans.h"
#include "core/gateways/classify/WindowSeeds.h"

namespace rgnav {

namespace {

// All observations of all sequences, the farthest first.
struct Pool {
  Eigen::MatrixXd weights;  // dimension x N
  std::vector<double> distances;
};

Pool poolByDistance(const std::vector<GatewayObservationSequence>& sequences, Eigen::Index dimension) {
  std::vector<const GatewayObservation*> all;
  for (const GatewayObservationSequence& sequence : sequences) {
    checkSequence(sequence, dimension);
    for (const GatewayObservation& o : sequence) all.push_back(&o);
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const GatewayObservation* a, const GatewayObservation* b) { return a->distance > b->distance; });
  Pool pool{Eigen::MatrixXd(dimension, static_cast<Eigen::Index>(all.size())), {}};
  for (std::size_t i = 0; i < all.size(); ++i) {
    pool.weights.col(static_cast<Eigen::Index>(i)) = all[i]->weights;
    pool.distances.push_back(all[i]->distance);
  }
  return pool;
}

void checkConfig(const HmmTrainingConfig& config) {
  if (config.clusters < 1) throw InvalidArgumentError("HMM training needs at least one cluster");
  if (!(config.noiseStdDev >= 0.0) || !std::isfinite(config.noiseStdDev)) {
    throw InvalidArgumentError("HMM training noise must be finite and non-negative");
  }
  if (!(config.minIntervalOverlap >= 0.0 && config.minIntervalOverlap <= 1.0)) {
    throw InvalidArgumentError("HMM training interval overlap must lie in [0, 1]");
  }
}

// Maximum likelihood Gaussian of the members plus the expected spread of the added noise.
MultivariateGaussian clusterGaussian(const Eigen::MatrixXd& members, double noiseStdDev) {
  const Eigen::VectorXd mean = members.rowwise().mean();
  const Eigen::MatrixXd centred = members.colwise() - mean;
  Eigen::MatrixXd covariance = centred * centred.transpose() / static_cast<double>(members.cols());
  covariance = 0.5 * (covariance + covariance.transpose()).eval();
  covariance.diagonal().array() += noiseStdDev * noiseStdDev;
  return MultivariateGaussian(mean, covariance);
}

// A cluster of the pool: its Gaussian and its distances.
struct Cluster {
  MultivariateGaussian gaussian;
  std::size_t observations;
  ClusterDistances distances;
};

std::vector<Cluster> clusterPool(const Pool& pool, const HmmTrainingConfig& config) {
  const KMeansResult kmeans = kMeans(
      pool.weights, slidingWindowMeans(pool.weights, config.clusters, config.windowOverlap), config.kMeansIterations);
  std::vector<std::vector<Eigen::Index>> members(static_cast<std::size_t>(config.clusters));
  for (std::size_t p = 0; p < kmeans.assignment.size(); ++p) {
    members[static_cast<std::size_t>(kmeans.assignment[p])].push_back(static_cast<Eigen::Index>(p));
  }
  std::vector<Cluster> clusters;
  for (const std::vector<Eigen::Index>& indices : members) {
    if (indices.empty()) continue;
    std::vector<double> distances;
    for (const Eigen::Index p : indices) distances.push_back(pool.distances[static_cast<std::size_t>(p)]);
    clusters.push_back({clusterGaussian(pool.weights(Eigen::all, indices), config.noiseStdDev), indices.size(),
                        summariseDistances(std::move(distances), config.distanceQuantile)});
  }
  return clusters;
}

}  // namespace

TrainedHmm trainGatewayHmm(const std::vector<GatewayObservationSequence>& sequences, const HmmTrainingConfig& config) {
  checkConfig(config);
  if (sequences.empty() || sequences.front().empty()) throw InvalidArgumentError("HMM training without observations");
  const Eigen::Index dimension = sequences.front().front().weights.size();
  const Pool pool = poolByDistance(sequences, dimension);
  const std::vector<Cluster> clusters = clusterPool(pool, config);

  std::vector<ClusterDistances> distances;
  for (const Cluster& c : clusters) distances.push_back(c.distances);
  const std::vector<std::vector<std::size_t>> states = groupByDistanceInterval(distances, config.minIntervalOverlap);

  TrainedHmm trained;
  for (const Cluster& c : clusters) trained.clusters.push_back({c.observations, c.distances, 0});
  const auto q = static_cast<Eigen::Index>(states.size());
  GaussianMixtureHmm initial{Eigen::VectorXd::Constant(q, 1.0 / static_cast<double>(q)),
                             Eigen::MatrixXd::Constant(q, q, 1.0 / static_cast<double>(q)),
                             {}};
  for (std::size_t s = 0; s < states.size(); ++s) {
    HmmState state;
    for (const std::size_t c : states[s]) {
      state.components.push_back(clusters[c].gaussian);
      trained.clusters[c].state = s;
    }
    const auto m = static_cast<Eigen::Index>(state.components.size());
    state.mixtureWeights = Eigen::VectorXd::Constant(m, 1.0 / static_cast<double>(m));
    initial.states.push_back(std::move(state));
  }

  std::vector<Eigen::MatrixXd> observations;
  for (const GatewayObservationSequence& sequence : sequences)
    observations.push_back(weightMatrix(sequence, dimension));
  BaumWelchResult em = trainBaumWelch(std::move(initial), observations, config.em);
  trained.hmm = std::move(em.hmm);
  trained.logLikelihoods = std::move(em.logLikelihoods);
  trained.converged = em.converged;
  return trained;
}

HmmClassifier trainHmmClassifier(const std::map<GatewayClass, std::vector<GatewayObservationSequence>>& training,
                                 const HmmTrainingConfig& config) {
  std::vector<GatewayClassModel> models;
  for (const auto& [gatewayClass, sequences] : training) {
    try {
      models.push_back({gatewayClass, trainGatewayHmm(sequences, config).hmm, 1.0});
    } catch (const InvalidArgumentError& e) {
      throw InvalidArgumentError(std::string(gatewayClassName(gatewayClass)) + " HMM: " + e.what());
    }
  }
  return HmmClassifier(std::move(models));
}

}  // namespace rgnav
