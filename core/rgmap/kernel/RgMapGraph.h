// The RG Graph of an RG Map (thesis 2.1.3, 5.4): the plain description RgGraph::build takes, with
// every crossing point in the map frame (the global frame the thesis transforms them into), and
// the learned edge costs, which the map state keeps so that they survive checkpoints.
// A gateway joins the graph once a region is known on both of its sides; one known on a single
// side leads nowhere the robot could plan to yet. Sides keep their order (side A is the graph's
// side A), so learned costs, kept by gateway and side, stay with their edges across rebuilds and
// merges.
#pragma once

#include "core/rgmap/graph/EdgeCostTable.h"
#include "core/rgmap/graph/RgGraph.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

RgGraphSpec graphSpec(const RgMapState& state);

// The cost table with the state's learned costs. Throws InvalidArgumentError for a learned value
// the table refuses (negative, non-finite, a zero count).
EdgeCostTable costTable(const RgMapState& state, const EdgeCostConfig& config);

// Keeps the table's learned costs in the state.
void storeCosts(RgMapState& state, const EdgeCostTable& table);

}  // namespace rgnav
