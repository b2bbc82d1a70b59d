// Open frontier share of a region's freespace; see FreespaceCompleteness.h.
#include "core/rgmap/describe/FreespaceCompleteness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

constexpr double kFarCells = 1e8;  // gateway ends beyond this (in cells) cannot belong to a region

// The gateway cells within the freespace window grown by one cell (all a neighbour test reaches).
class GatewayCells {
 public:
  GatewayCells(const RegionFreespace& freespace, std::span<const GatewaySegment> gateways)
      : area_{freespace.window().col0 - 1, freespace.window().row0 - 1, freespace.window().width + 2,
              freespace.window().height + 2},
        marked_(std::size_t(area_.width) * std::size_t(area_.height), false) {
    const double perCell = 1.0 / freespace.cellSizeM();
    const auto mark = [this](int i, int j) {
      if (area_.contains(i, j)) marked_[index(i, j)] = true;
    };
    for (const GatewaySegment& g : gateways) {
      const Eigen::Vector2d a = g.a * perCell, b = g.b * perCell;
      if (!(std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()) <= kFarCells))
        throw InvalidArgumentError("freespace completeness: gateway ends must be finite and near the region");
      // Only the part that can reach the window matters; clipping keeps far gateways cheap.
      if (std::max(a.x(), b.x()) < area_.col0 || std::min(a.x(), b.x()) > area_.col0 + area_.width ||
          std::max(a.y(), b.y()) < area_.row0 || std::min(a.y(), b.y()) > area_.row0 + area_.height)
        continue;
      const LatticeCell last = traverseCells(a.x(), a.y(), b.x(), b.y(), mark);
      mark(last.i, last.j);
    }
  }

  bool contains(int i, int j) const { return area_.contains(i, j) && marked_[index(i, j)]; }

 private:
  std::size_t index(int i, int j) const {
    return std::size_t(j - area_.row0) * std::size_t(area_.width) + std::size_t(i - area_.col0);
  }

  CellWindow area_;
  std::vector<bool> marked_;
};

}  // namespace

FreespaceCompleteness freespaceCompleteness(const RegionFreespace& freespace,
                                            std::span<const GatewaySegment> gateways) {
  const GatewayCells gatewayCells(freespace, gateways);
  const CellWindow& w = freespace.window();
  constexpr std::array<std::array<int, 2>, 4> kNeighbours{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
  FreespaceCompleteness out;
  for (int j = w.row0; j < w.row0 + w.height; ++j)
    for (int i = w.col0; i < w.col0 + w.width; ++i) {
      if (freespace.cell(i, j) != FreespaceCell::Free) continue;
      bool border = false, open = false;
      for (const auto& [di, dj] : kNeighbours) {
        const FreespaceCell n = freespace.cell(i + di, j + dj);
        border = border || n != FreespaceCell::Free;
        open = open || (n == FreespaceCell::Unknown && !gatewayCells.contains(i + di, j + dj));
      }
      if (!border) continue;
      ++out.borderCells;
      if (open && !gatewayCells.contains(i, j)) ++out.openCells;
    }
  if (out.borderCells > 0) {
    out.frontierShare = double(out.openCells) / double(out.borderCells);
    out.completeness = 1.0 - out.frontierShare;
  }
  return out;
}

}  // namespace rgnav
