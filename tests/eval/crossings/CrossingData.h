// CrossingData: the labelled observation sequences of all scenarios of a seeded scenario set
// (core/sim HallwayScenarios), computed on several threads, converted to the classifiers'
// GatewayObservationSequence (core/gateways/vlm TrackedObservations.h) and split per
// environment by clutter layout, so that no test sequence was recorded in a world the HMMs were
// trained in: of the layouts of one environment and class, odd ones are test data, even ones
// training data, and of those every other one (layout % 4 == 2) is held out to choose the HMM
// configuration (validation). The clutter layout of every test sequence is kept beside it: the
// test sequences of one gateway (Evaluation.h) are those of its class and layout.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/gateways/classify/GatewayObservation.h"
#include "tests/eval/crossings/ScenarioSequences.h"

namespace rgnav {

using ClassSequences = std::map<GatewayClass, std::vector<GatewayObservationSequence>>;

struct EnvironmentData {
  ClassSequences fit;         // layout % 4 == 0
  ClassSequences validation;  // layout % 4 == 2
  ClassSequences test;        // odd layouts
  std::map<GatewayClass, std::vector<int>> testLayouts;  // the clutter layout of each sequence of `test`
  std::map<GatewayClass, std::size_t> testApproaches;  // approaches driven in the test layouts
};

struct CrossingData {
  std::array<EnvironmentData, 8> environments;  // in thesisEnvironments() order
  std::size_t sequences = 0;
  std::size_t observations = 0;
};

// `a` with the sequences of `b` appended.
ClassSequences merged(ClassSequences a, const ClassSequences& b);

// Throws InvalidArgumentError for layoutsPerClass < 1 or threads < 1.
CrossingData generateCrossingData(std::uint64_t seed, int layoutsPerClass, const CrossingsSetup& setup, int threads);

}  // namespace rgnav
