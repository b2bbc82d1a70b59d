// SequenceLabelling: the labels of the tracked sequences of one approach (thesis 4.1.4: "we
// annotated the maps, in order to automatically label the recorded observation sequences").
// The true gateway is the square gateway area of the scenario (side = hallway width, centre at
// the origin of the gateway frame). Of the sequences whose last gateway points all lie within
// matchFraction * width of its corners (a VLM built on the face of a box instead of the wall
// behind it lies farther off), the longest carries the scenario's class (at most one sequence
// per approach, as in the thesis); sequences whose gateway centre lies farther than
// counterFraction * width from the true centre are hypotheses of no gateway and carry the
// counter-class Hallway (4.1.3); the rest (shifted duplicates of the true gateway) and sequences
// shorter than minObservations are dropped. A Hallway scenario has no gateway at the labelled
// place, so all its sequences are counter-class.
#pragma once

#include <cstddef>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/gateways/vlm/HypothesisTracker.h"

namespace rgnav {

struct LabelParams {
  double matchFraction = 0.1;
  double counterFraction = 1.0;
  std::size_t minObservations = 3;
};

struct LabelledTrack {
  GatewayClass truth = GatewayClass::Hallway;
  TrackedSequence sequence;
};

std::vector<LabelledTrack> labelApproach(const std::vector<TrackedSequence>& sequences, GatewayClass scenarioClass,
                                         double width, const LabelParams& params = {});

}  // namespace rgnav
