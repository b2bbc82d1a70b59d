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

void addFusedClassifications(const HmmClassifier& classifier, const GatewaySequences& gateways,
                             GatewayConfusionMatrix& matrix) {
  const std::vector<GatewayClass>& classes = matrix.classes();
  for (const auto& [truth, perGateway] : gateways) {
    if (std::find(classes.begin(), classes.end(), truth) == classes.end()) continue;
    for (const std::vector<GatewayObservationSequence>& sequences : perGateway)
      matrix.add(truth, classifier.classify(sequences).best());
  }
}

std::vector<LayoutErrors> layoutErrors(const HmmClassifier& classifier, const EnvironmentData& data) {
  std::vector<LayoutErrors> errors;
  for (const auto& [truth, perGateway] : data.testGateways) {
    const std::vector<int>& layouts = data.testGatewayLayouts.at(truth);
    for (std::size_t g = 0; g < perGateway.size(); ++g) {
      LayoutErrors e{truth, layouts.at(g), perGateway[g].size(), {}};
      for (const GatewayObservationSequence& s : perGateway[g]) {
        const GatewayClass decided = classifier.classify(s).best();
        if (decided != truth) ++e.decided[decided];
      }
      if (!e.decided.empty()) errors.push_back(std::move(e));
    }
  }
  return errors;
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

void addHmmClassifications(const HmmClassifier& classifier, const ClassSequences& test,
                           GatewayConfusionMatrix& matrix) {
  const std::vector<GatewayClass>& classes = matrix.classes();
  for (const auto& [truth, sequences] : test) {
    if (std::find(classes.begin(), classes.end(), truth) == classes.end()) continue;
    for (const GatewayObservationSequence& s : sequences) matrix.add(truth, classifier.classify(s).best());
  }
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
      {}, GatewayConfusionMatrix(hmm.classes()), GatewayConfusionMatrix(hmm.classes()), none, none, none};
  const auto& environments = thesisEnvironments();
  for (std::size_t e = 0; e < environments.size(); ++e) {
    const ClassSequences& test = data.environments[e].test;
    EnvironmentResults& r = results.environments.emplace_back(
        EnvironmentResults{.hmm = GatewayConfusionMatrix(hmm.classes()),
                           .pairs = {},
                           .fused = GatewayConfusionMatrix(hmm.classes()),
                           .layoutErrors = layoutErrors(hmm, data.environments[e])});
    addWeightClassifications(test, r);
    addHmmClassifications(hmm, test, r.hmm);
    addHmmClassifications(hmm, test, results.hmmAll);
    for (std::size_t p = 0; p < kTable43Pairs.size(); ++p) {
      r.pairs.emplace_back(std::vector<GatewayClass>{kTable43Pairs[p].first, kTable43Pairs[p].second});
      addHmmClassifications(pairwise[p], test, r.pairs.back());
    }
    addFusedClassifications(hmm, data.environments[e].testGateways, r.fused);
    if (!is2mCluttered(environments[e])) continue;
    addHmmClassifications(hmm, test, results.hmm2mCluttered);
    results.hmmMinClassRate2mCluttered = std::fmin(results.hmmMinClassRate2mCluttered, minGatewayClassRate(r.hmm));
    results.fusedMinClassRate2mCluttered =
        std::fmin(results.fusedMinClassRate2mCluttered, minGatewayClassRate(r.fused));
  }
  if (results.hmmAll.total() > 0) results.hmmMeanClassRate = results.hmmAll.meanClassAccuracy();
  return results;
}

}  // namespace rgnav
