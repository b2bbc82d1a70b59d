// Tests the log-space forward and backward recursions against brute-force enumeration of all
// state paths of a tiny mixture HMM, and log-sum-exp at its edges.
#include "core/gateways/classify/ForwardBackward.h"

#include <cppunit/extensions/HelperMacros.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/Errors.h"
#include "core/gateways/classify/EmissionTable.h"
#include "core/gateways/classify/LogSumExp.h"

using rgnav::GaussianMixtureHmm;
using rgnav::MultivariateGaussian;

namespace {

Eigen::MatrixXd covariance(double a, double b, double c) { return (Eigen::MatrixXd(2, 2) << a, b, b, c).finished(); }

// Two states; state 0 a two-component mixture, state 1 one Gaussian; no way back from state 1.
GaussianMixtureHmm tinyHmm() {
  GaussianMixtureHmm hmm;
  hmm.prior = Eigen::Vector2d(0.6, 0.4);
  hmm.transitions = (Eigen::MatrixXd(2, 2) << 0.7, 0.3, 0.0, 1.0).finished();
  hmm.states.push_back({{MultivariateGaussian(Eigen::Vector2d(0.0, 0.0), covariance(1.0, 0.3, 0.5)),
                         MultivariateGaussian(Eigen::Vector2d(1.0, -1.0), covariance(0.4, -0.1, 0.8))},
                        Eigen::Vector2d(0.25, 0.75)});
  hmm.states.push_back(
      {{MultivariateGaussian(Eigen::Vector2d(2.0, 1.0), covariance(0.6, 0.2, 0.9))}, Eigen::VectorXd::Ones(1)});
  return hmm;
}

Eigen::MatrixXd observations() {
  return (Eigen::MatrixXd(2, 4) << 0.1, 0.9, 1.8, 2.2, -0.2, -0.7, 0.6, 1.3).finished();
}

// The density by its textbook formula, independent of the Cholesky evaluation.
double density(const MultivariateGaussian& g, const Eigen::VectorXd& x) {
  const Eigen::VectorXd d = x - g.mean();
  const double norm = std::sqrt(std::pow(2.0 * std::numbers::pi, 2.0) * g.covariance().determinant());
  return std::exp(-0.5 * d.dot(g.covariance().inverse() * d)) / norm;
}

double emission(const GaussianMixtureHmm& hmm, std::size_t state, const Eigen::VectorXd& x) {
  double sum = 0.0;
  for (std::size_t m = 0; m < hmm.states[state].components.size(); ++m) {
    sum += hmm.states[state].mixtureWeights[static_cast<Eigen::Index>(m)] * density(hmm.states[state].components[m], x);
  }
  return sum;
}

// P(O | lambda) as the sum over all Q^T state paths.
double bruteForceLikelihood(const GaussianMixtureHmm& hmm, const Eigen::MatrixXd& o) {
  const Eigen::Index q = hmm.stateCount();
  const Eigen::Index length = o.cols();
  double total = 0.0;
  const auto paths = static_cast<Eigen::Index>(std::pow(q, length));
  for (Eigen::Index code = 0; code < paths; ++code) {
    Eigen::Index rest = code;
    double p = 1.0;
    Eigen::Index previous = -1;
    for (Eigen::Index t = 0; t < length; ++t) {
      const Eigen::Index state = rest % q;
      rest /= q;
      p *= (t == 0 ? hmm.prior[state] : hmm.transitions(previous, state)) *
           emission(hmm, static_cast<std::size_t>(state), o.col(t));
      previous = state;
    }
    total += p;
  }
  return total;
}

}  // namespace

class ForwardBackwardTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ForwardBackwardTest);
  CPPUNIT_TEST(forwardMatchesBruteForceEnumeration);
  CPPUNIT_TEST(backwardAgreesWithForwardAtEveryStep);
  CPPUNIT_TEST(logSumExpHandlesInfinitiesAndLargeValues);
  CPPUNIT_TEST(rejectsObservationsOfAnotherDimension);
  CPPUNIT_TEST_SUITE_END();

 public:
  void forwardMatchesBruteForceEnumeration() {
    const GaussianMixtureHmm hmm = tinyHmm();
    const Eigen::MatrixXd o = observations();
    for (Eigen::Index length = 1; length <= o.cols(); ++length) {
      const double expected = bruteForceLikelihood(hmm, o.leftCols(length));
      const double logL = rgnav::logLikelihood(hmm, o.leftCols(length));
      CPPUNIT_ASSERT_DOUBLES_EQUAL(std::log(expected), logL, 1e-10);
    }
  }

  void backwardAgreesWithForwardAtEveryStep() {
    const GaussianMixtureHmm hmm = tinyHmm();
    const Eigen::MatrixXd table = rgnav::logEmissions(hmm, observations()).state;
    const Eigen::MatrixXd alpha = rgnav::logForward(hmm, table);
    const Eigen::MatrixXd beta = rgnav::logBackward(hmm, table);
    const double logL = rgnav::logLikelihood(hmm, observations());
    for (Eigen::Index t = 0; t < alpha.rows(); ++t) {
      CPPUNIT_ASSERT_DOUBLES_EQUAL(logL, rgnav::logSumExp(alpha.row(t) + beta.row(t)), 1e-10);
    }
  }

  void logSumExpHandlesInfinitiesAndLargeValues() {
    const double inf = std::numeric_limits<double>::infinity();
    CPPUNIT_ASSERT_EQUAL(-inf, rgnav::logSumExp(Eigen::Vector2d(-inf, -inf)));
    CPPUNIT_ASSERT_EQUAL(-inf, rgnav::logSumExp(Eigen::VectorXd()));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, rgnav::logSumExp(Eigen::Vector2d(-inf, 3.0)), 1e-15);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1000.0 + std::log(2.0), rgnav::logSumExp(Eigen::Vector2d(1000.0, 1000.0)), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-1000.0 + std::log(2.0), rgnav::logSumExp(Eigen::Vector2d(-1000.0, -1000.0)), 1e-12);
  }

  void rejectsObservationsOfAnotherDimension() {
    CPPUNIT_ASSERT_THROW(rgnav::logLikelihood(tinyHmm(), Eigen::MatrixXd::Zero(3, 2)), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::logLikelihood(tinyHmm(), Eigen::MatrixXd::Zero(2, 0)), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ForwardBackwardTest);
