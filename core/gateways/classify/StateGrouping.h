// The structure of a gateway HMM from its clusters (thesis 4.1.3.3, "Initializing the Hidden
// Markov Model", table 4.1): clusters that cover approximately the same distance interval become
// the mixture components of one state, and every new distance interval adds a state; states are
// ordered left (far) to right (near).
// The thesis groups by inspection; here the rule is explicit: clusters are taken by decreasing
// mean distance, and a cluster joins the current state when its interval overlaps the interval of
// every cluster already in the state by at least `minOverlap` of the shorter of the two (so that
// a chain of slightly shifted clusters cannot grow into one state). Intervals are distance
// quantiles, so a few stray observations do not widen them.
#pragma once

#include <cstddef>
#include <vector>

namespace rgnav {

// The distances of a cluster's observations: their mean and the interval [low, high] they cover.
struct ClusterDistances {
  double mean = 0.0;
  double low = 0.0;
  double high = 0.0;
};

// Distances of a cluster's observations summarised by their mean and the interval between the
// `quantile` and 1 - `quantile` quantiles (0: minimum and maximum, as in table 4.1). Throws
// InvalidArgumentError for no distances or a quantile outside [0, 0.5].
ClusterDistances summariseDistances(std::vector<double> distances, double quantile);

// The part of the shorter of the two intervals covered by both; an interval of length 0 counts as
// covered (1) if it lies inside the other and as not covered (0) otherwise.
double overlapFraction(const ClusterDistances& a, const ClusterDistances& b);

// The indices of the clusters of each state, the farthest state first.
std::vector<std::vector<std::size_t>> groupByDistanceInterval(const std::vector<ClusterDistances>& clusters,
                                                              double minOverlap);

}  // namespace rgnav
