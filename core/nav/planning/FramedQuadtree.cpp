// FramedQuadtree: the decomposition (see the header), with a summed-area table of free cells so
// that every square's content is known in constant time.
#include "core/nav/planning/FramedQuadtree.h"

#include <algorithm>

namespace rgnav {

namespace {

// Free cells per rectangle [0, col) x [0, row), (width + 1) x (height + 1) entries, row-major.
class FreeCellSums {
 public:
  explicit FreeCellSums(const OccupancyGrid& grid) : width_(grid.width()), height_(grid.height()) {
    sums_.assign(static_cast<std::size_t>(width_ + 1) * static_cast<std::size_t>(height_ + 1), 0);
    for (int r = 0; r < height_; ++r)
      for (int c = 0; c < width_; ++c)
        at(c + 1, r + 1) = at(c, r + 1) + at(c + 1, r) - at(c, r) + (grid.blocked({c, r}) ? 0 : 1);
  }
  // Free cells of the square of `size` at (col, row); the part outside the grid holds none.
  std::int64_t square(int col, int row, int size) const {
    const int c0 = std::min(col, width_), r0 = std::min(row, height_);
    const int c1 = std::min(col + size, width_), r1 = std::min(row + size, height_);
    return at(c1, r1) - at(c0, r1) - at(c1, r0) + at(c0, r0);
  }
  std::int64_t total() const { return at(width_, height_); }

 private:
  std::int64_t& at(int c, int r) { return sums_[static_cast<std::size_t>(r) * (width_ + 1) + c]; }
  std::int64_t at(int c, int r) const { return sums_[static_cast<std::size_t>(r) * (width_ + 1) + c]; }

  int width_;
  int height_;
  std::vector<std::int64_t> sums_;
};

struct Square {
  int col;
  int row;
  int size;
};

}  // namespace

FramedQuadtree::FramedQuadtree(const OccupancyGrid& grid) : width_(grid.width()), height_(grid.height()) {
  const std::size_t cells = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  quadOfCell_.assign(cells, kNone);
  nodeOfCell_.assign(cells, kNone);
  const FreeCellSums sums(grid);
  freeCells_ = static_cast<std::size_t>(sums.total());
  int padded = 1;
  while (padded < std::max(width_, height_)) padded *= 2;
  std::vector<Square> pending{{0, 0, padded}};
  while (!pending.empty()) {
    const Square s = pending.back();
    pending.pop_back();
    const std::int64_t free = sums.square(s.col, s.row, s.size);
    if (free == 0) continue;
    if (free == static_cast<std::int64_t>(s.size) * s.size) {
      addQuad(s.col, s.row, s.size);
      continue;
    }
    const int half = s.size / 2;
    // Pushed in reverse so that quads come out row-major by their lower-left quarter first.
    pending.push_back({s.col + half, s.row + half, half});
    pending.push_back({s.col, s.row + half, half});
    pending.push_back({s.col + half, s.row, half});
    pending.push_back({s.col, s.row, half});
  }
  linkCellNeighbours(grid);
  labelComponents();
}

// Components over quads: a quad's frame is joined within itself, so quads joined by a cell
// neighbour link share a component.
void FramedQuadtree::labelComponents() {
  componentOfQuad_.assign(quads_.size(), kNone);
  std::int32_t next = 0;
  std::vector<std::int32_t> pending;
  for (std::size_t seed = 0; seed < quads_.size(); ++seed) {
    if (componentOfQuad_[seed] != kNone) continue;
    componentOfQuad_[seed] = next;
    pending.assign(1, static_cast<std::int32_t>(seed));
    while (!pending.empty()) {
      const Quad& q = quads_[static_cast<std::size_t>(pending.back())];
      pending.pop_back();
      for (std::int32_t node = q.firstNode; node < q.firstNode + q.nodeCount; ++node)
        forEachCellNeighbour(node, [&](std::int32_t n) {
          const std::int32_t quad = nodeQuad(n);
          if (componentOfQuad_[static_cast<std::size_t>(quad)] != kNone) return;
          componentOfQuad_[static_cast<std::size_t>(quad)] = next;
          pending.push_back(quad);
        });
    }
    ++next;
  }
}

void FramedQuadtree::linkCellNeighbours(const OccupancyGrid& grid) {
  cellNeighbourStart_.assign(1, 0);
  cellNeighbourStart_.reserve(nodeCells_.size() + 1);
  for (std::size_t node = 0; node < nodeCells_.size(); ++node) {
    const CellIndex c = nodeCells_[node];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::int32_t n = nodeOf({c.col + dx, c.row + dy});
        if (n == kNone || nodeQuads_[static_cast<std::size_t>(n)] == nodeQuads_[node]) continue;
        if (dx != 0 && dy != 0 && grid.blocked({c.col + dx, c.row}) && grid.blocked({c.col, c.row + dy})) continue;
        cellNeighbours_.push_back(n);
      }
    cellNeighbourStart_.push_back(static_cast<std::uint32_t>(cellNeighbours_.size()));
  }
}

void FramedQuadtree::addQuad(int col, int row, int size) {
  const auto quad = static_cast<std::int32_t>(quads_.size());
  Quad q{col, row, size, static_cast<std::int32_t>(nodeCells_.size()), 0};
  for (int r = row; r < row + size; ++r)
    for (int c = col; c < col + size; ++c) {
      const std::size_t i = index({c, r});
      quadOfCell_[i] = quad;
      if (c == col || c == col + size - 1 || r == row || r == row + size - 1) {
        nodeOfCell_[i] = static_cast<std::int32_t>(nodeCells_.size());
        nodeCells_.push_back({c, r});
        nodeQuads_.push_back(quad);
        ++q.nodeCount;
      }
    }
  quads_.push_back(q);
}

}  // namespace rgnav
