// Parallel generation and train/test split of the crossing sequences; see CrossingData.h.
#include "tests/eval/crossings/CrossingData.h"

#include "core/common/Errors.h"
#include "core/gateways/vlm/TrackedObservations.h"
#include "tests/eval/crossings/ParallelFor.h"

namespace rgnav {

ClassSequences merged(ClassSequences a, const ClassSequences& b) {
  for (const auto& [c, sequences] : b) a[c].insert(a[c].end(), sequences.begin(), sequences.end());
  return a;
}

CrossingData generateCrossingData(std::uint64_t seed, int layoutsPerClass, const CrossingsSetup& setup, int threads) {
  const std::vector<ScenarioSpec> specs = scenarioSet(seed, layoutsPerClass);
  std::vector<ScenarioSequences> perScenario(specs.size());
  parallelFor(specs.size(), threads, [&](std::size_t i) { perScenario[i] = scenarioSequences(specs[i], setup); });

  CrossingData data;
  const auto& environments = thesisEnvironments();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    // scenarioSet lists environments outermost and the layouts of one class innermost.
    const auto layout = static_cast<int>(i % static_cast<std::size_t>(layoutsPerClass));
    const std::size_t env = i / (kGatewayClasses.size() * static_cast<std::size_t>(layoutsPerClass));
    if (environments[env].name != specs[i].environment.name)
      throw InvalidArgumentError("crossing data: unexpected scenario order");
    EnvironmentData& target = data.environments[env];
    ClassSequences& split = layout % 2 == 1 ? target.test : layout % 4 == 0 ? target.fit : target.validation;
    if (layout % 2 == 1) target.testApproaches[specs[i].gatewayClass] += perScenario[i].approaches;
    for (const LabelledTrack& t : perScenario[i].tracks) {
      split[t.truth].push_back(toObservationSequence(t.sequence));
      if (layout % 2 == 1) target.testLayouts[t.truth].push_back(layout);
      ++data.sequences;
      data.observations += t.sequence.observations.size();
    }
  }
  return data;
}

}  // namespace rgnav
