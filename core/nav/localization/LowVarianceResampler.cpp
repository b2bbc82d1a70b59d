// Low-variance (systematic) resampling (LowVarianceResampler.h).
#include "core/nav/localization/LowVarianceResampler.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

std::vector<std::size_t> lowVarianceDraw(std::span<const double> weights, std::size_t count, std::mt19937_64& rng) {
  double total = 0.0;
  for (const double w : weights) {
    if (!(w >= 0.0) || !std::isfinite(w)) throw InvalidArgumentError("lowVarianceDraw: weights must be finite and non-negative");
    total += w;
  }
  if (!(total > 0.0)) throw InvalidArgumentError("lowVarianceDraw: the weights sum to zero");
  std::vector<std::size_t> drawn;
  drawn.reserve(count);
  if (count == 0) return drawn;
  const double step = total / static_cast<double>(count);
  double pointer = std::uniform_real_distribution<double>(0.0, step)(rng);
  double cumulative = weights[0];
  std::size_t i = 0;
  for (std::size_t m = 0; m < count; ++m) {
    while (pointer > cumulative && i + 1 < weights.size()) cumulative += weights[++i];
    drawn.push_back(i);
    pointer += step;
  }
  return drawn;
}

}  // namespace rgnav
