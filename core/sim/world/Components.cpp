// connectedComponents: flood fill with an explicit stack, then renumbering of the kept sets.
#include "core/sim/world/Components.h"

#include <array>
#include <cstddef>

#include "core/common/Errors.h"

namespace rgnav {

Components connectedComponents(const std::vector<std::uint8_t>& mask, int width, int height, int minSize) {
  if (width <= 0 || height <= 0 || mask.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw InvalidArgumentError("connectedComponents: mask size does not match width x height");
  }
  static constexpr std::array<std::array<int, 2>, 8> kNeighbours{
      {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
  std::vector<int> raw(mask.size(), -1);
  std::vector<int> rawSizes;
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < mask.size(); ++seed) {
    if (!mask[seed] || raw[seed] >= 0) continue;
    const int label = static_cast<int>(rawSizes.size());
    int size = 0;
    raw[seed] = label;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::size_t cell = stack.back();
      stack.pop_back();
      ++size;
      const int col = static_cast<int>(cell % static_cast<std::size_t>(width));
      const int row = static_cast<int>(cell / static_cast<std::size_t>(width));
      for (const auto& [dc, dr] : kNeighbours) {
        const int c = col + dc;
        const int r = row + dr;
        if (c < 0 || r < 0 || c >= width || r >= height) continue;
        const std::size_t next = static_cast<std::size_t>(r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c);
        if (mask[next] && raw[next] < 0) {
          raw[next] = label;
          stack.push_back(next);
        }
      }
    }
    rawSizes.push_back(size);
  }
  Components out;
  std::vector<int> renumber(rawSizes.size(), -1);
  for (std::size_t i = 0; i < rawSizes.size(); ++i) {
    if (rawSizes[i] >= minSize) {
      renumber[i] = out.count();
      out.sizes.push_back(rawSizes[i]);
    }
  }
  out.labels.resize(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) out.labels[i] = raw[i] < 0 ? -1 : renumber[static_cast<std::size_t>(raw[i])];
  return out;
}

}  // namespace rgnav
