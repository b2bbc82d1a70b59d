// LowVarianceResampler: systematic resampling (Thrun, Burgard, Fox, Probabilistic Robotics 2005,
// 4.3, Table 4.4): one random offset, then evenly spaced pointers into the cumulative weights, so
// a particle of weight w is drawn floor or ceil of n w times.
#pragma once

#include <cstddef>
#include <random>
#include <span>
#include <vector>

namespace rgnav {

// The indices of `count` draws from `weights` (non-negative, not all zero: InvalidArgumentError).
std::vector<std::size_t> lowVarianceDraw(std::span<const double> weights, std::size_t count, std::mt19937_64& rng);

}  // namespace rgnav
