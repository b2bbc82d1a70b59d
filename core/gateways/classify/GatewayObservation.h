// GatewayObservation and GatewayObservationSequence: the input of every gateway classifier of
// thesis 4.1.3, independent of how the observation vectors are computed (4.1.2.3). An observation
// is one observation vector - the gateway weights W(GW, VLM), one entry per gateway class
// measure, possibly followed by further entries (the VLM's measures, core/gateways/vlm
// ObservationVector.h) - together with the distance from the robot to the gateway; a sequence
// holds the observations of one tracked VLM hypothesis in the order they were made, i.e. by
// decreasing distance.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace rgnav {

struct GatewayObservation {
  double distance = 0.0;    // metres from the robot to the gateway (0 = gateway centre)
  Eigen::VectorXd weights;  // the observation vector: one weight per gateway class measure first
};

// Observations of one VLM hypothesis, the farthest first and the closest last. The order is
// the order of observation and is not checked: measured distances jitter.
using GatewayObservationSequence = std::vector<GatewayObservation>;

// A sequence from parallel plain vectors, observation t being (distances[t], weights[t]) - the
// form in which the VLM hypothesis tracker hands out its sequences. Throws InvalidArgumentError
// if the sizes differ.
GatewayObservationSequence makeObservationSequence(const std::vector<double>& distances,
                                                   const std::vector<std::vector<double>>& weights);

// Throws InvalidArgumentError unless the sequence is non-empty and every observation has
// `dimension` finite weights and a finite, non-negative distance.
void checkSequence(const GatewayObservationSequence& sequence, Eigen::Index dimension);

// The weight vectors as the columns of a dimension x length matrix (after checkSequence).
Eigen::MatrixXd weightMatrix(const GatewayObservationSequence& sequence, Eigen::Index dimension);

}  // namespace rgnav
