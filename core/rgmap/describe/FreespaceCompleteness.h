// freespaceCompleteness: how much of a region's freespace border is still open to unexplored
// space (thesis 2.1.1, table 2.1 "characteristic measures: completeness": "whether or not there
// are still unexplored areas in that region"; the thesis names the measure but does not define
// it). Definition, on the cells of the RegionFreespace (4-neighbourhood):
//   - a border cell is a free cell with at least one neighbour that is not free;
//   - gateway cells are the cells a gateway segment runs through (GridTraversal.h);
//   - a border cell is open if it is no gateway cell and has a neighbour that is unknown and no
//     gateway cell: there the freespace ends in space nobody has seen, not at an obstacle and not
//     at a gateway (gateways close a region by definition);
//   frontierShare = open / border cells, completeness = 1 - frontierShare.
// A fully explored closed room has completeness close to 1; a region with a side never seen, or
// whose beams ran out of range, clearly less. Without freespace: frontierShare 1, completeness 0.
#pragma once

#include <cstddef>
#include <span>

#include "core/rgmap/describe/GatewaySegment.h"
#include "core/rgmap/describe/RegionFreespace.h"

namespace rgnav {

struct FreespaceCompleteness {
  std::size_t borderCells = 0;
  std::size_t openCells = 0;
  double frontierShare = 1.0;
  double completeness = 0.0;
};

// Throws InvalidArgumentError for a non-finite gateway end or one 10^8 cells away.
FreespaceCompleteness freespaceCompleteness(const RegionFreespace& freespace, std::span<const GatewaySegment> gateways);

}  // namespace rgnav
