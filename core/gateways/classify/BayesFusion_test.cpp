// Tests Bayes fusion of gateway classifications (thesis 4.1.4): the update rule, fusion of
// several sequences by the HMM classifier, class priors, and no underflow with many sequences.
#include "core/gateways/classify/BayesFusion.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>

#include "core/common/Errors.h"
#include "core/gateways/classify/HmmClassifier.h"

using rgnav::GatewayClass;
using rgnav::GatewayObservationSequence;

namespace {

// One-state, one-dimensional HMMs: an L-Turn emits around 0, an R-Turn around 1.
rgnav::GaussianMixtureHmm oneState(double mean) {
  rgnav::GaussianMixtureHmm hmm{Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Ones(1, 1), {}};
  hmm.states.push_back(
      {{rgnav::MultivariateGaussian(Eigen::VectorXd::Constant(1, mean), Eigen::MatrixXd::Identity(1, 1))},
       Eigen::VectorXd::Ones(1)});
  return hmm;
}

rgnav::HmmClassifier turns(double lTurnPrior, double rTurnPrior) {
  return rgnav::HmmClassifier(
      {{GatewayClass::LTurn, oneState(0.0), lTurnPrior}, {GatewayClass::RTurn, oneState(1.0), rTurnPrior}});
}

GatewayObservationSequence at(std::initializer_list<double> values) {
  GatewayObservationSequence s;
  double distance = 5.0;
  for (const double x : values) s.push_back({distance -= 1.0, Eigen::VectorXd::Constant(1, x)});
  return s;
}

}  // namespace

class BayesFusionTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(BayesFusionTest);
  CPPUNIT_TEST(updateMultipliesPriorAndLikelihood);
  CPPUNIT_TEST(fusionOfSequencesEqualsProductOfLikelihoods);
  CPPUNIT_TEST(priorsShiftAmbiguousDecisions);
  CPPUNIT_TEST(manySequencesDoNotUnderflow);
  CPPUNIT_TEST(rejectsImpossibleEvidence);
  CPPUNIT_TEST_SUITE_END();

 public:
  void updateMultipliesPriorAndLikelihood() {
    const Eigen::VectorXd posterior =
        rgnav::bayesUpdate(Eigen::Vector3d(0.5, 0.25, 0.25), Eigen::Vector3d(0.1, 0.4, 0.2).array().log());
    CPPUNIT_ASSERT(posterior.isApprox(Eigen::Vector3d(0.25, 0.5, 0.25), 1e-12));
    // Fusing two sequences one after the other equals fusing them at once.
    const Eigen::Vector3d l1(-3.0, -1.0, -2.0);
    const Eigen::Vector3d l2(-0.5, -4.0, -1.0);
    const Eigen::Vector3d prior(0.2, 0.3, 0.5);
    CPPUNIT_ASSERT(
        rgnav::bayesUpdate(rgnav::bayesUpdate(prior, l1), l2).isApprox(rgnav::bayesUpdate(prior, l1 + l2), 1e-12));
  }

  void fusionOfSequencesEqualsProductOfLikelihoods() {
    const rgnav::HmmClassifier classifier = turns(1.0, 1.0);
    const GatewayObservationSequence first = at({0.6, 0.4});
    const GatewayObservationSequence second = at({0.7});
    const rgnav::GatewayPosterior fused = classifier.classify(std::vector<GatewayObservationSequence>{first, second});
    const Eigen::VectorXd l = classifier.logLikelihoods(first) + classifier.logLikelihoods(second);
    const double expectedLTurn = 1.0 / (1.0 + std::exp(l[1] - l[0]));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(expectedLTurn, fused.probabilityOf(GatewayClass::LTurn), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, fused.probabilities.sum(), 1e-12);
    CPPUNIT_ASSERT(GatewayClass::RTurn == fused.best());
    // With one-state models the fused posterior is that of the concatenated sequence.
    CPPUNIT_ASSERT(fused.probabilities.isApprox(classifier.classify(at({0.6, 0.4, 0.7})).probabilities, 1e-12));
    // No sequences: the priors.
    CPPUNIT_ASSERT(classifier.classify(std::vector<GatewayObservationSequence>{})
                       .probabilities.isApprox(Eigen::Vector2d(0.5, 0.5)));
    CPPUNIT_ASSERT_THROW(fused.probabilityOf(GatewayClass::XCrossing), rgnav::InvalidArgumentError);
  }

  void priorsShiftAmbiguousDecisions() {
    const GatewayObservationSequence ambiguous = at({0.55});
    CPPUNIT_ASSERT(GatewayClass::RTurn == turns(1.0, 1.0).classify(ambiguous).best());
    const rgnav::GatewayPosterior biased = turns(3.0, 1.0).classify(ambiguous);
    CPPUNIT_ASSERT(GatewayClass::LTurn == biased.best());
    CPPUNIT_ASSERT(turns(3.0, 1.0).priors().isApprox(Eigen::Vector2d(0.75, 0.25)));
  }

  void manySequencesDoNotUnderflow() {
    const rgnav::HmmClassifier classifier = turns(1.0, 1.0);
    std::vector<GatewayObservationSequence> sequences(400, at({40.0, 41.0}));
    sequences.push_back(at({-40.0}));
    const rgnav::GatewayPosterior fused = classifier.classify(sequences);
    CPPUNIT_ASSERT(fused.probabilities.allFinite());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, fused.probabilityOf(GatewayClass::RTurn), 1e-12);
  }

  void rejectsImpossibleEvidence() {
    const double inf = std::numeric_limits<double>::infinity();
    CPPUNIT_ASSERT_THROW(rgnav::bayesUpdate(Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(-inf, -inf)),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::bayesUpdate(Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(-inf, 0.0)),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::bayesUpdate(Eigen::Vector2d(0.5, 0.5), Eigen::Vector3d(0.0, 0.0, 0.0)),
                         rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(BayesFusionTest);
