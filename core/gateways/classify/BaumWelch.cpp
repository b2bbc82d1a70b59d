// EM for prior, transitions and mixture weights, optionally the Gaussians too (Rabiner 1989,
// eqs. 40, 52-54, 109-110; see BaumWelch.h).
#include "core/gateways/classify/BaumWelch.h"

#include <cmath>
#include <utility>

#include "core/common/Errors.h"
#include "core/gateways/classify/EmissionTable.h"
#include "core/gateways/classify/ForwardBackward.h"
#include "core/gateways/classify/LogSumExp.h"

namespace rgnav {

namespace {

// Expected counts of one E-step over all sequences, and their total log-likelihood.
struct Expectations {
  double logLikelihood = 0.0;
  Eigen::VectorXd starts;                // sum of gamma_1(i)
  Eigen::MatrixXd transitions;           // sum of xi_t(i, j)
  std::vector<Eigen::VectorXd> mixture;  // per state: sum of gamma_t(j, m)
  // Only when the Gaussians are learned, per state and component: sum of gamma_t(j, m) o_t and
  // of gamma_t(j, m) o_t o_t'.
  std::vector<std::vector<Eigen::VectorXd>> sums;
  std::vector<std::vector<Eigen::MatrixXd>> squares;
};

Expectations expectations(const GaussianMixtureHmm& hmm, const std::vector<Eigen::MatrixXd>& sequences,
                          bool withMoments) {
  const Eigen::Index q = hmm.stateCount();
  const Eigen::MatrixXd logA = hmm.transitions.array().log();
  Expectations e;
  e.starts = Eigen::VectorXd::Zero(q);
  e.transitions = Eigen::MatrixXd::Zero(q, q);
  for (const HmmState& s : hmm.states) e.mixture.push_back(Eigen::VectorXd::Zero(s.mixtureWeights.size()));
  if (withMoments) {
    const Eigen::Index d = hmm.dimension();
    for (const HmmState& s : hmm.states) {
      e.sums.emplace_back(s.components.size(), Eigen::VectorXd::Zero(d));
      e.squares.emplace_back(s.components.size(), Eigen::MatrixXd::Zero(d, d));
    }
  }

  for (const Eigen::MatrixXd& observations : sequences) {
    const EmissionTable table = logEmissions(hmm, observations);
    const Eigen::MatrixXd alpha = logForward(hmm, table.state);
    const Eigen::MatrixXd beta = logBackward(hmm, table.state);
    const Eigen::Index length = alpha.rows();
    const double logP = logSumExp(alpha.row(length - 1));
    e.logLikelihood += logP;
    const Eigen::MatrixXd gamma = (alpha + beta).array() - logP;  // log gamma_t(i)
    e.starts += gamma.row(0).transpose().array().exp().matrix();
    for (Eigen::Index t = 0; t + 1 < length; ++t) {
      const Eigen::RowVectorXd next = table.state.row(t + 1) + beta.row(t + 1);
      for (Eigen::Index i = 0; i < q; ++i) {
        e.transitions.row(i) += (alpha(t, i) - logP + logA.row(i).array() + next.array()).exp().matrix();
      }
    }
    for (Eigen::Index j = 0; j < q; ++j) {
      // gamma_t(j, m) = gamma_t(j) * c_jm N(o_t) / b_j(o_t)
      const Eigen::MatrixXd& terms = table.component[static_cast<std::size_t>(j)];
      const Eigen::ArrayXXd logShare = terms.array().colwise() - table.state.col(j).array();
      const Eigen::MatrixXd share = (logShare.colwise() + gamma.col(j).array()).exp().matrix();  // T x M_j
      const auto state = static_cast<std::size_t>(j);
      e.mixture[state] += share.colwise().sum().transpose();
      if (!withMoments) continue;
      for (Eigen::Index m = 0; m < share.cols(); ++m) {
        const auto component = static_cast<std::size_t>(m);
        e.sums[state][component] += observations * share.col(m);
        e.squares[state][component] += observations * share.col(m).asDiagonal() * observations.transpose();
      }
    }
  }
  return e;
}

// Normalises `counts` into `target` unless there is nothing to normalise.
template <typename Target, typename Counts>
void normaliseInto(Target&& target, const Counts& counts) {
  const double total = counts.sum();
  if (total > 0.0) target = counts / total;
}

// Rabiner eqs. 53-54 for every component that explains at least one observation.
void learnGaussians(GaussianMixtureHmm& hmm, const Expectations& e, double floor) {
  for (std::size_t j = 0; j < hmm.states.size(); ++j) {
    for (std::size_t m = 0; m < hmm.states[j].components.size(); ++m) {
      const double n = e.mixture[j][static_cast<Eigen::Index>(m)];
      if (n < 1.0) continue;
      const Eigen::VectorXd mean = e.sums[j][m] / n;
      Eigen::MatrixXd covariance = e.squares[j][m] / n - mean * mean.transpose();
      covariance = 0.5 * (covariance + covariance.transpose()).eval();
      covariance.diagonal().array() += floor;
      hmm.states[j].components[m] = MultivariateGaussian(mean, covariance);
    }
  }
}

GaussianMixtureHmm maximisation(GaussianMixtureHmm hmm, const Expectations& e, const BaumWelchConfig& config) {
  normaliseInto(hmm.prior, e.starts);
  for (Eigen::Index i = 0; i < hmm.stateCount(); ++i) normaliseInto(hmm.transitions.row(i), e.transitions.row(i));
  for (std::size_t j = 0; j < hmm.states.size(); ++j) normaliseInto(hmm.states[j].mixtureWeights, e.mixture[j]);
  if (config.learnedCovarianceFloor) learnGaussians(hmm, e, *config.learnedCovarianceFloor);
  return hmm;
}

}  // namespace

BaumWelchResult trainBaumWelch(GaussianMixtureHmm initial, const std::vector<Eigen::MatrixXd>& sequences,
                               const BaumWelchConfig& config) {
  validateHmm(initial);
  if (sequences.empty()) throw InvalidArgumentError("Baum-Welch needs at least one sequence");
  if (config.maxIterations < 0 || !(config.relativeTolerance >= 0.0)) {
    throw InvalidArgumentError("Baum-Welch needs a non-negative iteration count and tolerance");
  }
  const std::optional<double>& floor = config.learnedCovarianceFloor;
  if (floor && !(*floor > 0.0 && std::isfinite(*floor)))
    throw InvalidArgumentError("Baum-Welch needs a positive, finite covariance floor");
  const bool withMoments = floor.has_value();
  BaumWelchResult result{std::move(initial), {}, false};
  Expectations current = expectations(result.hmm, sequences, withMoments);
  result.logLikelihoods.push_back(current.logLikelihood);
  for (int iteration = 0; iteration < config.maxIterations && !result.converged; ++iteration) {
    result.hmm = maximisation(std::move(result.hmm), current, config);
    const double previous = current.logLikelihood;
    current = expectations(result.hmm, sequences, withMoments);
    result.logLikelihoods.push_back(current.logLikelihood);
    result.converged = current.logLikelihood - previous <= config.relativeTolerance * std::abs(previous);
  }
  return result;
}

}  // namespace rgnav
