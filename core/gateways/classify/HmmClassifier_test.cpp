// Tests the HMM gateway classifier end to end (thesis 4.1.3.3): HMMs trained by clustering and
// EM on sequences drawn from three known left-right HMMs - alike far from the gateway, different
// close to it - classify held-out sequences of the three classes; training recovers left-right
// models; the classifier checks its models.
#include <cppunit/extensions/HelperMacros.h>

#include <map>
#include <random>

#include "core/common/Errors.h"
#include "core/gateways/classify/GatewayConfusionMatrix.h"
#include "core/gateways/classify/HmmTrainer.h"
#include "core/gateways/classify/testing/SyntheticHmm.h"

using rgnav::GatewayClass;
using rgnav::GatewayObservationSequence;

namespace {

Eigen::VectorXd v(double a, double b, double c, double d) { return Eigen::Vector4d(a, b, c, d); }

// Weights for (T-Junction, L-Turn, R-Turn, Hallway): every class starts from the same far view.
std::map<GatewayClass, rgnav::GaussianMixtureHmm> truths() {
  const Eigen::VectorXd far = v(0.4, 0.4, 0.4, 0.6);
  return {{GatewayClass::TJunction,
           rgnav::testing::leftRightHmm({far, v(0.6, 0.45, 0.45, 0.4), v(0.8, 0.5, 0.5, 0.2)}, 0.12, 0.6)},
          {GatewayClass::LTurn,
           rgnav::testing::leftRightHmm({far, v(0.5, 0.6, 0.3, 0.4), v(0.5, 0.8, 0.2, 0.2)}, 0.12, 0.6)},
          {GatewayClass::RTurn,
           rgnav::testing::leftRightHmm({far, v(0.5, 0.3, 0.6, 0.4), v(0.5, 0.2, 0.8, 0.2)}, 0.12, 0.6)}};
}

std::map<GatewayClass, std::vector<GatewayObservationSequence>> draw(std::uint64_t seed, int perClass) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> length(10, 16);
  std::map<GatewayClass, std::vector<GatewayObservationSequence>> data;
  for (const auto& [c, hmm] : truths()) {
    for (int i = 0; i < perClass; ++i)
      data[c].push_back(rgnav::testing::sampleSequence(hmm, length(rng), 1.0, 0.4, rng));
  }
  return data;
}

rgnav::HmmTrainingConfig config() {
  rgnav::HmmTrainingConfig c;
  c.clusters = 6;
  return c;
}

}  // namespace

class HmmClassifierTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HmmClassifierTest);
  CPPUNIT_TEST(classifiesHeldOutSequencesOfThreeClasses);
  CPPUNIT_TEST(trainingFindsLeftRightModels);
  CPPUNIT_TEST(rejectsInconsistentModels);
  CPPUNIT_TEST_SUITE_END();

 public:
  void classifiesHeldOutSequencesOfThreeClasses() {
    const rgnav::HmmClassifier learned = rgnav::trainHmmClassifier(draw(1, 150), config());
    std::vector<rgnav::GatewayClassModel> trueModels;
    for (const auto& [c, hmm] : truths()) trueModels.push_back({c, hmm, 1.0});
    const rgnav::HmmClassifier ideal(trueModels);
    rgnav::GatewayConfusionMatrix confusion(learned.classes());
    rgnav::GatewayConfusionMatrix idealConfusion(learned.classes());
    for (const auto& [truth, sequences] : draw(2, 150)) {
      for (const GatewayObservationSequence& s : sequences) {
        confusion.add(truth, learned.classify(s).best());
        idealConfusion.add(truth, ideal.classify(s).best());
      }
    }
    CPPUNIT_ASSERT(confusion.minClassAccuracy() >= 0.95);
    // Close to the models that generated the data.
    CPPUNIT_ASSERT(confusion.accuracy() >= idealConfusion.accuracy() - 0.03);
    // Pairwise classification (thesis table 4.3) keeps the chosen models.
    const rgnav::HmmClassifier pair = learned.subset({GatewayClass::RTurn, GatewayClass::LTurn});
    CPPUNIT_ASSERT(pair.classes() == std::vector<GatewayClass>({GatewayClass::RTurn, GatewayClass::LTurn}));
    const GatewayObservationSequence s = draw(4, 1).at(GatewayClass::LTurn).front();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(learned.logLikelihoods(s)[1], pair.logLikelihoods(s)[1], 1e-12);
    CPPUNIT_ASSERT_THROW(pair.subset({GatewayClass::XCrossing}), rgnav::InvalidArgumentError);
  }

  void trainingFindsLeftRightModels() {
    const auto data = draw(3, 150);
    const rgnav::TrainedHmm trained = rgnav::trainGatewayHmm(data.at(GatewayClass::LTurn), config());
    const rgnav::GaussianMixtureHmm& hmm = trained.hmm;
    CPPUNIT_ASSERT(hmm.stateCount() >= 2);
    CPPUNIT_ASSERT(trained.logLikelihoods.back() > trained.logLikelihoods.front());
    // States run from far to near; the model starts far and rarely steps back.
    std::vector<double> sum(static_cast<std::size_t>(hmm.stateCount()), 0.0);
    std::vector<double> count(sum.size(), 0.0);
    for (const rgnav::ClusterSummary& c : trained.clusters) {
      sum[c.state] += c.distances.mean;
      count[c.state] += 1.0;
    }
    for (std::size_t s = 1; s < sum.size(); ++s) CPPUNIT_ASSERT(sum[s] / count[s] < sum[s - 1] / count[s - 1]);
    CPPUNIT_ASSERT(hmm.prior[0] > 0.5);
    const Eigen::MatrixXd backwards = hmm.transitions.triangularView<Eigen::StrictlyLower>();
    CPPUNIT_ASSERT(backwards.rowwise().sum().maxCoeff() < 0.1);
    std::size_t clustered = 0;
    for (const rgnav::ClusterSummary& c : trained.clusters) clustered += c.observations;
    std::size_t observations = 0;
    for (const GatewayObservationSequence& s : data.at(GatewayClass::LTurn)) observations += s.size();
    CPPUNIT_ASSERT_EQUAL(observations, clustered);
  }

  void rejectsInconsistentModels() {
    const auto hmms = truths();
    const rgnav::GaussianMixtureHmm& t = hmms.at(GatewayClass::TJunction);
    CPPUNIT_ASSERT_THROW(rgnav::HmmClassifier({}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::HmmClassifier({{GatewayClass::TJunction, t, 1.0}, {GatewayClass::TJunction, t, 1.0}}),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::HmmClassifier({{GatewayClass::TJunction, t, 0.0}}), rgnav::InvalidArgumentError);
    const rgnav::GaussianMixtureHmm other = rgnav::testing::leftRightHmm({Eigen::Vector2d(0.0, 0.0)}, 0.1, 1.0);
    CPPUNIT_ASSERT_THROW(rgnav::HmmClassifier({{GatewayClass::TJunction, t, 1.0}, {GatewayClass::LTurn, other, 1.0}}),
                         rgnav::InvalidArgumentError);
    const rgnav::HmmClassifier classifier({{GatewayClass::TJunction, t, 1.0}});
    CPPUNIT_ASSERT_THROW(classifier.classify(GatewayObservationSequence{{1.0, Eigen::Vector2d(0.0, 0.0)}}),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::trainGatewayHmm({}, config()), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(HmmClassifierTest);
