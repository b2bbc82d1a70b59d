// Holes in regions filled; see RegionHoles.h.
#include "tests/eval/rooms/RegionHoles.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

struct Box {
  int col0, row0, col1, row1;  // inclusive
};

// The bounding box of the claimed cells; none claimed: col0 > col1.
Box claimedBox(const std::vector<std::uint8_t>& claimed, int width, int height) {
  Box box{width, height, -1, -1};
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col)
      if (claimed[std::size_t(row) * std::size_t(width) + std::size_t(col)] != 0) {
        box.col0 = std::min(box.col0, col);
        box.col1 = std::max(box.col1, col);
        box.row0 = std::min(box.row0, row);
        box.row1 = std::max(box.row1, row);
      }
  return box;
}

}  // namespace

void fillEnclosedHoles(std::span<RegionRaster> regions, int width, int height, std::size_t maxHoleCells) {
  if (width < 0 || height < 0) throw InvalidArgumentError("fillEnclosedHoles: negative map size");
  const std::size_t cells = std::size_t(width) * std::size_t(height);
  std::vector<std::uint16_t> claims(cells, 0);
  for (const RegionRaster& region : regions) {
    if (region.claimed.size() != cells)
      throw InvalidArgumentError("fillEnclosedHoles: region " + std::to_string(region.regionId) +
                                 " has a raster of the wrong size");
    for (std::size_t i = 0; i < cells; ++i) claims[i] += region.claimed[i] != 0 ? 1 : 0;
  }
  std::vector<std::vector<std::size_t>> holes(regions.size());
  std::vector<std::uint8_t> seen(cells, 0);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const std::vector<std::uint8_t>& claimed = regions[k].claimed;
    const Box box = claimedBox(claimed, width, height);
    std::vector<std::size_t> component, stack;
    for (int row = box.row0; row <= box.row1; ++row)
      for (int col = box.col0; col <= box.col1; ++col) {
        const std::size_t start = std::size_t(row) * std::size_t(width) + std::size_t(col);
        if (claimed[start] != 0 || seen[start] != 0) continue;
        component.clear();
        stack.assign(1, start);
        seen[start] = 1;
        bool enclosed = true;
        while (!stack.empty()) {
          const std::size_t cell = stack.back();
          stack.pop_back();
          component.push_back(cell);
          enclosed = enclosed && claims[cell] == 0;
          const int c = int(cell % std::size_t(width)), r = int(cell / std::size_t(width));
          if (c == box.col0 || c == box.col1 || r == box.row0 || r == box.row1) enclosed = false;
          for (const auto& [dc, dr] : std::array<std::pair<int, int>, 4>{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}}) {
            const int nc = c + dc, nr = r + dr;
            if (nc < box.col0 || nr < box.row0 || nc > box.col1 || nr > box.row1) continue;
            const std::size_t next = std::size_t(nr) * std::size_t(width) + std::size_t(nc);
            if (claimed[next] != 0 || seen[next] != 0) continue;
            seen[next] = 1;
            stack.push_back(next);
          }
        }
        if (enclosed && component.size() <= maxHoleCells)
          holes[k].insert(holes[k].end(), component.begin(), component.end());
      }
    for (int row = box.row0; row <= box.row1; ++row)
      for (int col = box.col0; col <= box.col1; ++col)
        seen[std::size_t(row) * std::size_t(width) + std::size_t(col)] = 0;
  }
  for (std::size_t k = 0; k < regions.size(); ++k)
    for (const std::size_t cell : holes[k]) regions[k].claimed[cell] = 1;
}

}  // namespace rgnav
