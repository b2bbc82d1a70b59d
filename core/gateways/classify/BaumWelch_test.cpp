// Tests Baum-Welch with fixed Gaussians: the training log-likelihood never decreases, the
// Gaussians stay as they were, and a known left-right structure is recovered from a uniform start;
// with learned Gaussians, displaced means move back to the truth and every covariance keeps the
// floor.
#include "core/gateways/classify/BaumWelch.h"

#include <cppunit/extensions/HelperMacros.h>

#include <random>

#include "core/common/Errors.h"
#include "core/gateways/classify/testing/SyntheticHmm.h"

using rgnav::GaussianMixtureHmm;

namespace {

GaussianMixtureHmm truth() {
  return rgnav::testing::leftRightHmm({Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, 0.5), Eigen::Vector2d(2.0, 0.0)},
                                      0.4, 0.7);
}

std::vector<Eigen::MatrixXd> training(const GaussianMixtureHmm& hmm, int count) {
  std::mt19937_64 rng(7);
  std::vector<Eigen::MatrixXd> sequences;
  for (int i = 0; i < count; ++i) {
    const rgnav::GatewayObservationSequence s = rgnav::testing::sampleSequence(hmm, 12, 1.0, 0.4, rng);
    sequences.push_back(rgnav::weightMatrix(s, 2));
  }
  return sequences;
}

// The true Gaussians, a spurious extra component per state, and uniform prior, transitions and
// mixture weights, as the thesis initialises them.
GaussianMixtureHmm uniformStart(const GaussianMixtureHmm& hmm) {
  GaussianMixtureHmm start = hmm;
  const Eigen::Index q = start.stateCount();
  start.prior = Eigen::VectorXd::Constant(q, 1.0 / static_cast<double>(q));
  start.transitions = Eigen::MatrixXd::Constant(q, q, 1.0 / static_cast<double>(q));
  for (rgnav::HmmState& state : start.states) {
    const rgnav::MultivariateGaussian& g = state.components.front();
    state.components.emplace_back(g.mean() + Eigen::Vector2d(0.0, 1.5), g.covariance());
    state.mixtureWeights = Eigen::Vector2d(0.5, 0.5);
  }
  return start;
}

}  // namespace

class BaumWelchTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(BaumWelchTest);
  CPPUNIT_TEST(likelihoodIncreasesMonotonically);
  CPPUNIT_TEST(keepsGaussiansAndRecoversLeftRightStructure);
  CPPUNIT_TEST(learnedGaussiansMoveToTheData);
  CPPUNIT_TEST(rejectsBadInput);
  CPPUNIT_TEST_SUITE_END();

 public:
  void likelihoodIncreasesMonotonically() {
    const rgnav::BaumWelchResult result =
        rgnav::trainBaumWelch(uniformStart(truth()), training(truth(), 40), {60, 0.0, std::nullopt});
    CPPUNIT_ASSERT_EQUAL(std::size_t(61), result.logLikelihoods.size());
    for (std::size_t i = 1; i < result.logLikelihoods.size(); ++i) {
      const double previous = result.logLikelihoods[i - 1];
      CPPUNIT_ASSERT(result.logLikelihoods[i] >= previous - 1e-9 * std::abs(previous));
    }
    CPPUNIT_ASSERT(result.logLikelihoods.back() > result.logLikelihoods.front() + 10.0);
  }

  void keepsGaussiansAndRecoversLeftRightStructure() {
    const GaussianMixtureHmm start = uniformStart(truth());
    const rgnav::BaumWelchResult result = rgnav::trainBaumWelch(start, training(truth(), 80), {500, 1e-9, std::nullopt});
    CPPUNIT_ASSERT(result.converged);
    rgnav::validateHmm(result.hmm);
    const GaussianMixtureHmm& hmm = result.hmm;
    for (std::size_t j = 0; j < hmm.states.size(); ++j) {
      for (std::size_t m = 0; m < 2; ++m) {
        CPPUNIT_ASSERT(hmm.states[j].components[m].mean() == start.states[j].components[m].mean());
        CPPUNIT_ASSERT(hmm.states[j].components[m].covariance() == start.states[j].components[m].covariance());
      }
      // The spurious component explains little.
      CPPUNIT_ASSERT(hmm.states[j].mixtureWeights[1] < 0.15);
    }
    CPPUNIT_ASSERT(hmm.prior[0] > 0.9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.7, hmm.transitions(0, 0), 0.08);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.7, hmm.transitions(1, 1), 0.08);
    CPPUNIT_ASSERT(hmm.transitions(2, 2) > 0.95);
    const Eigen::MatrixXd backwards = hmm.transitions.triangularView<Eigen::StrictlyLower>();
    CPPUNIT_ASSERT(backwards.maxCoeff() < 0.05);
  }

  void learnedGaussiansMoveToTheData() {
    GaussianMixtureHmm start = uniformStart(truth());
    for (rgnav::HmmState& state : start.states) {
      const rgnav::MultivariateGaussian& g = state.components.front();
      state.components.front() = rgnav::MultivariateGaussian(g.mean() + Eigen::Vector2d(0.3, -0.2), g.covariance());
    }
    const std::vector<Eigen::MatrixXd> data = training(truth(), 80);
    const rgnav::BaumWelchResult fixed = rgnav::trainBaumWelch(start, data, {200, 1e-9, std::nullopt});
    const rgnav::BaumWelchResult learned = rgnav::trainBaumWelch(start, data, {200, 1e-9, 0.01});
    rgnav::validateHmm(learned.hmm);
    CPPUNIT_ASSERT(learned.logLikelihoods.back() > fixed.logLikelihoods.back() + 10.0);
    const GaussianMixtureHmm reference = truth();
    for (std::size_t j = 0; j < reference.states.size(); ++j) {
      const rgnav::MultivariateGaussian& g = learned.hmm.states[j].components.front();
      CPPUNIT_ASSERT((g.mean() - reference.states[j].components.front().mean()).norm() < 0.1);
      CPPUNIT_ASSERT(g.covariance().diagonal().minCoeff() > 0.01);
    }
  }

  void rejectsBadInput() {
    CPPUNIT_ASSERT_THROW(rgnav::trainBaumWelch(truth(), {}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::trainBaumWelch(truth(), {Eigen::MatrixXd::Zero(3, 4)}), rgnav::InvalidArgumentError);
    GaussianMixtureHmm broken = truth();
    broken.transitions(0, 0) = 0.9;
    CPPUNIT_ASSERT_THROW(rgnav::trainBaumWelch(broken, training(truth(), 2)), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::trainBaumWelch(truth(), training(truth(), 2), {10, 1e-6, 0.0}),
                         rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(BaumWelchTest);
