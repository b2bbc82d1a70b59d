// Tests SOC, "last but one" and ASC (thesis 4.1.3.1-4.1.3.2) on a constructed T-Junction
// approach whose last view cuts the corner and looks like an L-Turn (thesis figure 4.5); entries
// after the weights (the measures of the observation vector) are not read.
#include "core/gateways/classify/WeightClassifiers.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"

using rgnav::GatewayClass;
using rgnav::GatewayObservation;
using rgnav::GatewayObservationSequence;

namespace {

// An 8-entry weight vector (kGatewayClasses order) with the given weights and 0.1 elsewhere.
Eigen::VectorXd weights(std::initializer_list<std::pair<GatewayClass, double>> entries) {
  Eigen::VectorXd w = Eigen::VectorXd::Constant(8, 0.1);
  for (const auto& [c, value] : entries) w[static_cast<Eigen::Index>(c)] = value;
  return w;
}

GatewayObservationSequence cutCornerApproach() {
  return {{5.0, weights({{GatewayClass::TJunction, 0.7}})},
          {3.0, weights({{GatewayClass::TJunction, 0.8}})},
          {1.5, weights({{GatewayClass::TJunction, 0.9}, {GatewayClass::LTurn, 0.3}})},
          {1.0, weights({{GatewayClass::TJunction, 0.5}, {GatewayClass::LTurn, 0.6}, {GatewayClass::Hallway, 0.95}})}};
}

}  // namespace

class WeightClassifiersTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(WeightClassifiersTest);
  CPPUNIT_TEST(socUsesTheLastObservationAndIgnoresHallway);
  CPPUNIT_TEST(lastButOneUsesTheObservationBefore);
  CPPUNIT_TEST(ascWeighsByInverseDistance);
  CPPUNIT_TEST(ignoresEntriesAfterTheWeights);
  CPPUNIT_TEST(rejectsBadInput);
  CPPUNIT_TEST_SUITE_END();

 public:
  void socUsesTheLastObservationAndIgnoresHallway() {
    const rgnav::GatewayWeightLayout layout = rgnav::thesisWeightLayout();
    CPPUNIT_ASSERT(GatewayClass::LTurn == rgnav::classifySingleObservation(cutCornerApproach(), layout));
    rgnav::GatewayWeightLayout withHallway = layout;
    withHallway.ignored.clear();
    CPPUNIT_ASSERT(GatewayClass::Hallway == rgnav::classifySingleObservation(cutCornerApproach(), withHallway));
  }

  void lastButOneUsesTheObservationBefore() {
    const rgnav::GatewayWeightLayout layout = rgnav::thesisWeightLayout();
    CPPUNIT_ASSERT(GatewayClass::TJunction == rgnav::classifySingleObservation(cutCornerApproach(), layout, 1));
    // Beyond the start of the sequence: the first observation.
    const GatewayObservationSequence single = {{2.0, weights({{GatewayClass::RTurn, 0.8}})}};
    CPPUNIT_ASSERT(GatewayClass::RTurn == rgnav::classifySingleObservation(single, layout, 1));
  }

  void ascWeighsByInverseDistance() {
    const rgnav::GatewayWeightLayout layout = rgnav::thesisWeightLayout();
    // 1/d: T-Junction 1.507/2.2 against L-Turn 0.8/2.2.
    CPPUNIT_ASSERT(GatewayClass::TJunction == rgnav::classifyAveragedSequence(cutCornerApproach(), layout));
    // Relying almost only on the closest view turns it into the SOC.
    CPPUNIT_ASSERT(GatewayClass::LTurn == rgnav::classifyAveragedSequence(cutCornerApproach(), layout, {10.0, 0.1}));
    // A zero distance stays finite.
    GatewayObservationSequence atCentre = cutCornerApproach();
    atCentre.back().distance = 0.0;
    CPPUNIT_ASSERT(GatewayClass::LTurn == rgnav::classifyAveragedSequence(atCentre, layout, {1.0, 0.01}));
  }

  void ignoresEntriesAfterTheWeights() {
    const rgnav::GatewayWeightLayout layout = rgnav::thesisWeightLayout();
    GatewayObservationSequence extended = cutCornerApproach();
    for (GatewayObservation& o : extended) {
      o.weights.conservativeResize(16);
      o.weights.tail(8).setConstant(5.0);
    }
    CPPUNIT_ASSERT(GatewayClass::LTurn == rgnav::classifySingleObservation(extended, layout));
    CPPUNIT_ASSERT(GatewayClass::TJunction == rgnav::classifySingleObservation(extended, layout, 1));
    CPPUNIT_ASSERT(GatewayClass::TJunction == rgnav::classifyAveragedSequence(extended, layout));
  }

  void rejectsBadInput() {
    const rgnav::GatewayWeightLayout layout = rgnav::thesisWeightLayout();
    CPPUNIT_ASSERT_THROW(rgnav::classifySingleObservation({}, layout), rgnav::InvalidArgumentError);
    const GatewayObservationSequence shortVector = {{1.0, Eigen::VectorXd::Zero(7)}};
    CPPUNIT_ASSERT_THROW(rgnav::classifyAveragedSequence(shortVector, layout), rgnav::InvalidArgumentError);
    GatewayObservationSequence negative = cutCornerApproach();
    negative.front().distance = -1.0;
    CPPUNIT_ASSERT_THROW(rgnav::classifySingleObservation(negative, layout), rgnav::InvalidArgumentError);
    const rgnav::GatewayWeightLayout nothing{{GatewayClass::Hallway}, {GatewayClass::Hallway}};
    const GatewayObservationSequence one = {{1.0, Eigen::VectorXd::Ones(1)}};
    CPPUNIT_ASSERT_THROW(rgnav::classifySingleObservation(one, nothing), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::classifyAveragedSequence(cutCornerApproach(), layout, {1.0, 0.0}),
                         rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(WeightClassifiersTest);
