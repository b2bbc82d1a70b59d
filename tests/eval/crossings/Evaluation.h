// Evaluation: the classifiers of thesis 4.1.3 (rgnav_gateway_classify) scored on the test
// sequences of the crossing data, per environment. The weight classifiers (SOC on the last and
// the last but one observation, ASC) ignore the Hallway counter-class as in the thesis and are
// scored on the seven gateway classes; the multi-class HMM classifier has one model per class
// with training data (counter-class included) and is scored on every class; a pairwise
// classifier (table 4.3) holds the HMMs of two classes only and sees test data of those two.
// Separately, the Bayes fusion of thesis 4.1.4 (last paragraph: "it is possible to globally fuse
// the results of different observation sequences formally, using Bayes filter"): every test
// gateway (one layout of a gateway class) is classified once from the sequences of all its
// approaches together (HmmClassifier::classify of several sequences), as a robot that passes a
// gateway several times would; its rates count gateways, not sequences, and are reported beside
// the per-sequence rates, never instead of them. The HMM errors are also listed per test gateway:
// in clutter they come in groups, most of them from one or two layouts of a class; so the lowest
// class rate in the 2 m cluttered hallways comes with its spread over the test layouts.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/gateways/classify/GatewayConfusionMatrix.h"
#include "core/gateways/classify/HmmClassifier.h"
#include "tests/eval/crossings/CrossingData.h"
#include "tests/eval/crossings/LayoutBootstrap.h"

namespace rgnav {

// kGatewayClasses without the counter-class Hallway.
std::vector<GatewayClass> gatewayClassesOnly();

// Adds the HMM decisions for the test sequences of the classes `matrix` holds.
void addHmmClassifications(const HmmClassifier& classifier, const ClassSequences& test,
                           GatewayConfusionMatrix& matrix);

// The pairs of table 4.3 (its "tcrossing" is the T-Junction).
inline constexpr std::array<std::pair<GatewayClass, GatewayClass>, 4> kTable43Pairs{{
    {GatewayClass::LTurn, GatewayClass::RTurn},
    {GatewayClass::LTurn, GatewayClass::TJunction},
    {GatewayClass::RTurn, GatewayClass::TJunction},
    {GatewayClass::LTurn, GatewayClass::XCrossing},
}};

// The HMM decisions on the test sequences of one gateway (one clutter layout of a class).
struct GatewayDecisions {
  GatewayClass truth = GatewayClass::Hallway;
  int layout = 0;
  std::size_t sequences = 0;
  std::map<GatewayClass, std::size_t> wrong;  // the wrong decisions, per decided class

  std::size_t wrongCount() const;
};

struct EnvironmentResults {
  GatewayConfusionMatrix asc{gatewayClassesOnly()};
  GatewayConfusionMatrix socLast{gatewayClassesOnly()};
  GatewayConfusionMatrix socLastButOne{gatewayClassesOnly()};
  GatewayConfusionMatrix hmm;
  std::vector<GatewayConfusionMatrix> pairs;  // one per kTable43Pairs entry
  GatewayConfusionMatrix fused;               // one decision per test gateway (Bayes fusion)
  std::vector<GatewayDecisions> gateways;     // every test gateway of a gateway class
};

struct CrossingResults {
  std::vector<EnvironmentResults> environments;  // in thesisEnvironments() order
  GatewayConfusionMatrix hmmAll;                 // every test sequence
  GatewayConfusionMatrix hmm2mCluttered;         // the 2 m slightly and strongly cluttered ones
  // The lowest HMM rate of a gateway class (counter-class excluded) in a 2 m cluttered
  // environment, and the mean per-class HMM rate over all test sequences (counter-class
  // included); NaN without test sequences.
  double hmmMinClassRate2mCluttered = 0.0;
  double hmmMeanClassRate = 0.0;
  // The same minimum for the fused decisions (gateways recognised / gateways); NaN without any.
  double fusedMinClassRate2mCluttered = 0.0;
  // The spread of hmmMinClassRate2mCluttered over the test layouts (LayoutBootstrap.h); unset
  // without test gateways.
  std::optional<RateInterval> hmmMinClassInterval2mCluttered;
};

// The bootstrap behind hmmMinClassInterval2mCluttered: resamples, interval level and seed.
inline constexpr int kLayoutResamples = 2000;
inline constexpr double kLayoutIntervalLevel = 0.9;
inline constexpr std::uint64_t kLayoutBootstrapSeed = 1;

// Throws NotAvailableError if a class of kTable43Pairs has no HMM (no training sequences).
CrossingResults evaluateCrossings(const CrossingData& data, const HmmClassifier& hmm);

}  // namespace rgnav
