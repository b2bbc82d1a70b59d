// ScenarioSequences: the labelled observation sequences of one hallway scenario (thesis 4.1.4):
// the simulated laser (LaserModel, Raycaster) at every labelled pose of every approach, the VLM
// observer (d_hw = the environment's hallway width, as the thesis measured it by hand) and the
// hypothesis tracker per approach, then the labels (SequenceLabelling). Laser noise is drawn
// from a generator seeded by the scenario's seed, so a scenario gives the same sequences
// whichever thread computes it.
#pragma once

#include <cstddef>
#include <vector>

#include "core/gateways/vlm/HypothesisTracker.h"
#include "core/gateways/vlm/VlmObserver.h"
#include "core/sim/scenarios/HallwayScenarios.h"
#include "core/sim/world/LaserModel.h"
#include "tests/eval/crossings/SequenceLabelling.h"

namespace rgnav {

struct CrossingsSetup {
  HallwayScenarioConfig scenarios;
  LaserConfig laser;
  VlmObserverParams observer;  // hypotheses.hallwayWidthM is set per environment
  TrackerParams tracker;
  LabelParams labels;
};

struct ScenarioSequences {
  std::vector<LabelledTrack> tracks;
  std::size_t approaches = 0;
};

ScenarioSequences scenarioSequences(const ScenarioSpec& spec, const CrossingsSetup& setup);

}  // namespace rgnav
