// Scoring the classifiers on the crossing data; see Evaluation.h.
#include "tests/eval/crossings/Evaluation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/Errors.h"
#include "core/gateways/classify/WeightClassifiers.h"

namespace rgnav {
namespace {

bool is2mCluttered(const HallwayEnvironment& e) { return e.width == 2.0 && e.clutter != ClutterLevel::None; }

void addWeightClassifications(const ClassSequences& test, EnvironmentResults& results) {
  const GatewayWeightLayout layout = thesisWeightLayout();
  for (const auto& [truth, sequences] : test) {
    if (truth == GatewayClass::Hallway) continue;
    for (const GatewayObservationSequence& s : sequences) {
      results.asc.add(truth, classifyAveragedSequence(s, layout));
      results.socLast.add(truth, classifySingleObservation(s, layout, 0));
      results.socLastButOne.add(truth, classifySingleObservation(s, layout, 1));
    }
  }
}

HmmClassifier pairwiseClassifier(const HmmClassifier& all, GatewayClass a, GatewayClass b) {
  std::vector<GatewayClassModel> pair;
  for (const GatewayClass c : {a, b}) {
    const auto& models = all.models();
    const auto it =
        std::find_if(models.begin(), models.end(), [c](const GatewayClassModel& m) { return m.gatewayClass == c; });
    if (it == models.end())
      throw NotAvailableError("no HMM for " + std::string(gatewayClassName(c)) + " (no training sequences)");
    pair.push_back(*it);
  }
  return HmmClassifier(std::move(pair));
}

// The test gateways of one environment: per gateway class (the counter-class has none), the
// indices of its test sequences in each clutter layout, layouts ascending.
using TestGateways = std::map<GatewayClass, std::map<int, std::vector<std::size_t>>>;
TestGateways testGateways(const std::map<GatewayClass, std::vector<int>>& testLayouts) {
  TestGateways gateways;
  for (const auto& [truth, layoutOf] : testLayouts) {
    if (truth == GatewayClass::Hallway) continue;
    auto& perLayout = gateways[truth];
    for (std::size_t i = 0; i < layoutOf.size(); ++i) perLayout[layoutOf[i]].push_back(i);
  }
  return gateways;
}

// One fused decision per test gateway of a class of `matrix`, from all its sequences.
void addFusedClassifications(const HmmClassifier& classifier, const ClassSequences& test, const TestGateways& gateways,
                             GatewayConfusionMatrix& matrix) {
  const std::vector<GatewayClass>& classes = matrix.classes();
  for (const auto& [truth, perLayout] : gateways) {
    if (std::find(classes.begin(), classes.end(), truth) == classes.end()) continue;
    const std::vector<GatewayObservationSequence>& sequences = test.at(truth);
    for (const auto& [layout, indices] : perLayout) {
      std::vector<GatewayObservationSequence> gateway;
      for (const std::size_t i : indices) gateway.push_back(sequences.at(i));
      matrix.add(truth, classifier.classify(gateway).best());
    }
  }
}

// The decision of `classifier` for every sequence of `test` whose true class is in `classes`, per
// true class in `test` order.
using ClassDecisions = std::map<GatewayClass, std::vector<GatewayClass>>;
ClassDecisions hmmDecisions(const HmmClassifier& classifier, const ClassSequences& test,
                            const std::vector<GatewayClass>& classes) {
  ClassDecisions decisions;
  for (const auto& [truth, sequences] : test) {
    if (std::find(classes.begin(), classes.end(), truth) == classes.end()) continue;
    std::vector<GatewayClass>& decided = decisions[truth];
    for (const GatewayObservationSequence& s : sequences) decided.push_back(classifier.classify(s).best());
  }
  return decisions;
}

void addDecisions(const ClassDecisions& decisions, GatewayConfusionMatrix& matrix) {
  for (const auto& [truth, decided] : decisions)
    for (const GatewayClass d : decided) matrix.add(truth, d);
}

// The decisions on the sequences of each test gateway.
std::vector<GatewayDecisions> gatewayDecisions(const ClassDecisions& decisions, const TestGateways& gateways) {
  std::vector<GatewayDecisions> out;
  for (const auto& [truth, perLayout] : gateways) {
    const auto decided = decisions.find(truth);
    if (decided == decisions.end()) continue;
    for (const auto& [layout, indices] : perLayout) {
      GatewayDecisions& g = out.emplace_back(GatewayDecisions{truth, layout, indices.size(), {}});
      for (const std::size_t i : indices)
        if (decided->second.at(i) != truth) ++g.wrong[decided->second.at(i)];
    }
  }
  return out;
}

// Appends to `groups` one group per gateway class of `gateways`: the tallies of its test gateways.
void addBootstrapGroups(const std::vector<GatewayDecisions>& gateways, std::vector<std::vector<GatewayTally>>& groups) {
  std::map<GatewayClass, std::vector<GatewayTally>> perClass;
  for (const GatewayDecisions& g : gateways)
    perClass[g.truth].push_back({g.sequences - g.wrongCount(), g.sequences});
  for (auto& [truth, tallies] : perClass) groups.push_back(std::move(tallies));
}

// The lowest rate of a gateway class (counter-class excluded) in `m`; NaN if it has none.
double minGatewayClassRate(const GatewayConfusionMatrix& m) {
  double lowest = std::numeric_limits<double>::quiet_NaN();
  const std::vector<GatewayClass>& modelled = m.classes();
  for (const GatewayClass c : gatewayClassesOnly())
    if (std::find(modelled.begin(), modelled.end(), c) != modelled.end() && m.total(c) > 0)
      lowest = std::fmin(lowest, m.classAccuracy(c));
  return lowest;
}

}  // namespace

std::size_t GatewayDecisions::wrongCount() const {
  std::size_t n = 0;
  for (const auto& [decided, count] : wrong) n += count;
  return n;
}

void addHmmClassifications(const HmmClassifier& classifier, const ClassSequences& test,
                           GatewayConfusionMatrix& matrix) {
  addDecisions(hmmDecisions(classifier, test, matrix.classes()), matrix);
}

std::vector<GatewayClass> gatewayClassesOnly() {
  std::vector<GatewayClass> classes;
  for (const GatewayClass c : kGatewayClasses)
    if (c != GatewayClass::Hallway) classes.push_back(c);
  return classes;
}

CrossingResults evaluateCrossings(const CrossingData& data, const HmmClassifier& hmm) {
  std::vector<HmmClassifier> pairwise;
  for (const auto& [a, b] : kTable43Pairs) pairwise.push_back(pairwiseClassifier(hmm, a, b));
  const double none = std::numeric_limits<double>::quiet_NaN();
  CrossingResults results{
      {}, GatewayConfusionMatrix(hmm.classes()), GatewayConfusionMatrix(hmm.classes()), none, none, none, {}};
  std::vector<std::vector<GatewayTally>> bootstrapGroups;  // per 2 m cluttered environment and class
  const auto& environments = thesisEnvironments();
  for (std::size_t e = 0; e < environments.size(); ++e) {
    const ClassSequences& test = data.environments[e].test;
    const ClassDecisions decided = hmmDecisions(hmm, test, hmm.classes());  // once for every multi-class figure
    const TestGateways gateways = testGateways(data.environments[e].testLayouts);
    EnvironmentResults& r = results.environments.emplace_back(
        EnvironmentResults{.hmm = GatewayConfusionMatrix(hmm.classes()),
                           .pairs = {},
                           .fused = GatewayConfusionMatrix(hmm.classes()),
                           .gateways = gatewayDecisions(decided, gateways)});
    addWeightClassifications(test, r);
    addDecisions(decided, r.hmm);
    addDecisions(decided, results.hmmAll);
    for (std::size_t p = 0; p < kTable43Pairs.size(); ++p) {
      r.pairs.emplace_back(std::vector<GatewayClass>{kTable43Pairs[p].first, kTable43Pairs[p].second});
      addHmmClassifications(pairwise[p], test, r.pairs.back());
    }
    addFusedClassifications(hmm, test, gateways, r.fused);
    if (!is2mCluttered(environments[e])) continue;
    addDecisions(decided, results.hmm2mCluttered);
    addBootstrapGroups(r.gateways, bootstrapGroups);
    results.hmmMinClassRate2mCluttered = std::fmin(results.hmmMinClassRate2mCluttered, minGatewayClassRate(r.hmm));
    results.fusedMinClassRate2mCluttered =
        std::fmin(results.fusedMinClassRate2mCluttered, minGatewayClassRate(r.fused));
  }
  if (results.hmmAll.total() > 0) results.hmmMeanClassRate = results.hmmAll.meanClassAccuracy();
  if (!bootstrapGroups.empty()) {
    results.hmmMinClassInterval2mCluttered =
        bootstrapLowestRate(bootstrapGroups, kLayoutResamples, kLayoutIntervalLevel, kLayoutBootstrapSeed);
  }
  return results;
}

}  // namespace rgnav
