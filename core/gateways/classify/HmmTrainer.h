// Training of the gateway HMMs as in thesis 4.1.3.3: (1) all observations of one class are
// sorted by distance and k-means starts from sliding-window means (WindowSeeds.h, KMeans.h);
// (2) every cluster becomes a Gaussian, spread by added noise; (3) clusters of about the same
// distance interval form one state of a left-right HMM, far states left (StateGrouping.h);
// (4) prior and transition matrix start uniform at 1/Q (the full matrix, as in the thesis, so
// that EM has to find the left-right structure by itself), the mixture weights of a state start
// uniform; (5) Baum-Welch learns prior, transitions and mixture weights with the Gaussians fixed
// (BaumWelch.h).
// Differences: the thesis adds random noise to the clustering data; here the noise's expected
// effect, noiseStdDev^2 on the covariance diagonal, is added, which is deterministic and keeps
// every covariance positive definite. Covariances are full (maximum likelihood, 1/n). Clusters
// that end up empty are dropped. With em.learnedCovarianceFloor set, step (5) learns the
// Gaussians too (BaumWelch.h); rgnav-eval-crossings sets that floor to noiseStdDev^2 and decides
// on validation data whether the Gaussians are learned.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <map>
#include <vector>

#include "core/gateways/classify/BaumWelch.h"
#include "core/gateways/classify/GatewayObservation.h"
#include "core/gateways/classify/GaussianMixtureHmm.h"
#include "core/gateways/classify/HmmClassifier.h"
#include "core/gateways/classify/StateGrouping.h"

namespace rgnav {

struct HmmTrainingConfig {
  Eigen::Index clusters = 8;   // k of k-means (table 4.1: 8)
  double windowOverlap = 0.5;  // fraction of a start window shared with the next one
  int kMeansIterations = 100;
  double noiseStdDev = 0.05;         // spread added to every cluster, in weight units
  double distanceQuantile = 0.05;    // cluster distance intervals span these quantiles
  double minIntervalOverlap = 0.75;  // clusters overlapping this much in distance share a state
  BaumWelchConfig em;
};

// One column of table 4.1: a cluster, its size, its distances and the state it went to.
struct ClusterSummary {
  std::size_t observations = 0;
  ClusterDistances distances;
  std::size_t state = 0;
};

struct TrainedHmm {
  GaussianMixtureHmm hmm;
  std::vector<ClusterSummary> clusters;  // the non-empty clusters in k-means order
  std::vector<double> logLikelihoods;    // the EM history (BaumWelchResult)
  bool converged = false;
};

// The HMM of one gateway class from its training sequences. Throws InvalidArgumentError for no
// sequences, sequences of different dimensions, fewer observations than clusters or an invalid
// configuration.
TrainedHmm trainGatewayHmm(const std::vector<GatewayObservationSequence>& sequences, const HmmTrainingConfig& config);

// One HMM per class of `training`, all with the same prior.
HmmClassifier trainHmmClassifier(const std::map<GatewayClass, std::vector<GatewayObservationSequence>>& training,
                                 const HmmTrainingConfig& config);

}  // namespace rgnav
