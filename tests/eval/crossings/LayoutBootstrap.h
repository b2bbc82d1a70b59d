// LayoutBootstrap: how far the lowest class rate in the 2 m cluttered hallways depends on the
// clutter layouts that happened to be drawn for testing. The test sequences of one gateway (one
// clutter layout of a class, approached about a dozen times) are strongly correlated - in
// clutter a layout is mostly decided all right or all wrong - so a class's rate rests on its ~15
// test layouts, not on its ~180 sequences, and one bad layout costs it about 8 points. A cluster
// bootstrap (Davison & Hinkley 1997, sec. 3.8: resample whole clusters, here test gateways, with
// replacement within each environment and class) shows that spread: every resample recomputes
// each group's rate and takes the lowest, and the interval holds the central `level` share of
// those minima (percentile interval). The minimum of resampled rates is biased low against the
// minimum of the true rates, so the interval is a measure of spread, not an unbiased estimate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rgnav {

// The test sequences of one gateway and how many of them were decided right.
struct GatewayTally {
  std::size_t correct = 0;
  std::size_t sequences = 0;
};

struct RateInterval {
  double low = 0.0;
  double high = 0.0;
};

// `groups` holds, per environment and class, the tallies of its test gateways. Throws
// InvalidArgumentError for no group, an empty group, a gateway without sequences or with more
// correct ones than sequences, no resamples, or a level outside (0, 1). Seeded: the same input
// gives the same interval.
RateInterval bootstrapLowestRate(const std::vector<std::vector<GatewayTally>>& groups, int resamples, double level,
                                 std::uint64_t seed);

}  // namespace rgnav
