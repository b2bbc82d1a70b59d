// FramedQuadtree: the free space of an OccupancyGrid decomposed into free square quads, each framed
// by its border cells at the finest resolution (thesis 5.4, figures 5.6 e and 5.7 right; framed
// quadtrees after Chen, Szczerba & Uhran, "A Framed-Quadtree Approach for Determining Euclidean
// Shortest Paths in a 2-D Environment", IEEE T-RA 1997). The grid is padded to a power of two
// (the padding and every non-free cell are blocked) and a square is split while it holds both free
// and blocked cells; the all-free squares are the quads. The border cells of every quad are the
// nodes of the planner's search graph (a 1x1 quad is one node, an s x s quad has 4s - 4); the node
// ids of a quad are contiguous, so a planner walks a quad's frame as one flat range.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class FramedQuadtree {
 public:
  struct Quad {
    int col = 0;  // lower-left cell
    int row = 0;
    int size = 1;  // side in cells
    std::int32_t firstNode = 0;  // its frame's nodes are [firstNode, firstNode + nodeCount)
    std::int32_t nodeCount = 1;
  };
  static constexpr std::int32_t kNone = -1;

  explicit FramedQuadtree(const OccupancyGrid& grid);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<Quad>& quads() const { return quads_; }
  // The quad holding a cell, kNone for a blocked or outside cell.
  std::int32_t quadOf(CellIndex c) const {
    return contains(c) ? quadOfCell_[index(c)] : kNone;
  }
  // The graph node of a cell, kNone for blocked, outside and quad-interior cells.
  std::int32_t nodeOf(CellIndex c) const {
    return contains(c) ? nodeOfCell_[index(c)] : kNone;
  }
  std::size_t nodeCount() const { return nodeCells_.size(); }
  CellIndex nodeCell(std::int32_t node) const { return nodeCells_[static_cast<std::size_t>(node)]; }
  std::int32_t nodeQuad(std::int32_t node) const { return nodeQuads_[static_cast<std::size_t>(node)]; }
  std::size_t freeCellCount() const { return freeCells_; }
  // The connected part of the free space holding a cell: two cells share it iff a path of the
  // graph joins them (a planner finds a path between them). kNone for a blocked or outside cell.
  std::int32_t componentOf(CellIndex c) const {
    const std::int32_t quad = quadOf(c);
    return quad == kNone ? kNone : componentOfQuad_[static_cast<std::size_t>(quad)];
  }

  // Calls visit(n) for every graph neighbour n of `node`: the rest of its quad's frame
  // (forEachFrameNeighbour) and its neighbouring cells in other quads (forEachCellNeighbour).
  template <class Visit>
  void forEachNeighbour(std::int32_t node, Visit&& visit) const {
    forEachFrameNeighbour(node, visit);
    forEachCellNeighbour(node, visit);
  }
  // The other frame nodes of the node's quad: a straight segment inside a free square.
  template <class Visit>
  void forEachFrameNeighbour(std::int32_t node, Visit&& visit) const {
    const Quad& q = quads_[static_cast<std::size_t>(nodeQuad(node))];
    for (std::int32_t n = q.firstNode; n < q.firstNode + q.nodeCount; ++n)
      if (n != node) visit(n);
  }
  // The (up to 8) neighbouring cells in other quads, a diagonal one only where the step does not
  // squeeze between two blocked cells (segmentFree's rule at a grid vertex).
  template <class Visit>
  void forEachCellNeighbour(std::int32_t node, Visit&& visit) const {
    const auto i = static_cast<std::size_t>(node);
    for (std::uint32_t k = cellNeighbourStart_[i]; k < cellNeighbourStart_[i + 1]; ++k) visit(cellNeighbours_[k]);
  }

 private:
  bool contains(CellIndex c) const { return c.col >= 0 && c.row >= 0 && c.col < width_ && c.row < height_; }
  std::size_t index(CellIndex c) const {
    return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.col);
  }
  void addQuad(int col, int row, int size);
  void linkCellNeighbours(const OccupancyGrid& grid);
  void labelComponents();

  int width_ = 0;
  int height_ = 0;
  std::size_t freeCells_ = 0;
  std::vector<Quad> quads_;
  std::vector<std::int32_t> quadOfCell_;  // row-major
  std::vector<std::int32_t> nodeOfCell_;  // row-major
  std::vector<CellIndex> nodeCells_;
  std::vector<std::int32_t> nodeQuads_;
  std::vector<std::uint32_t> cellNeighbourStart_;  // per node and one more: its range in cellNeighbours_
  std::vector<std::int32_t> cellNeighbours_;
  std::vector<std::int32_t> componentOfQuad_;
};

}  // namespace rgnav
