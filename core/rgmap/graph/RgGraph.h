// RgGraph: the Region & Gateway Graph of thesis 2.1.3 (figure 2.2). Nodes are crossing points,
// one on each side of every gateway, each annotated with its gateway and the region it lies in,
// at a position in one global frame. Edges are the routes through a gateway (between its two
// crossing points) and through a region (between every pair of crossing points in that region).
// Every edge has its Euclidean length, the lower bound of its cost, and its current cost from the
// graph's EdgeCostTable (thesis 5.4).
// The graph knows nothing of how regions and gateways are stored: build() takes a plain
// description and replaces the whole structure, keeping the learned costs, which are kept by
// stable edge identity (RgGraphKeys.h). The mapping kernel rebuilds the graph after every
// structural change (new gateway, merged regions, ...); a merge is a rebuild with the absorbed
// region's ID replaced, and learned costs carry over because node keys do not name regions.
// Deliberate differences: the thesis adds crossing points incrementally as the robot discovers
// them; we rebuild from the whole map, which costs O(sum over regions of k^2) for k crossing
// points per region. A neutralised gateway (the same region on both sides) keeps both crossing
// points and its gateway edge, and its two crossing points also get a region edge like any other
// pair in the region: it connects nothing new.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <map>
#include <optional>
#include <vector>

#include "core/rgmap/graph/EdgeCostTable.h"
#include "core/rgmap/graph/RgGraphKeys.h"

namespace rgnav {

struct CrossingPointSpec {
  RegionId region;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // global frame, metres
};

struct GatewaySpec {
  GatewayId id;
  bool isDoor = false;
  CrossingPointSpec sideA;  // the sides must keep their order across rebuilds
  CrossingPointSpec sideB;
};

struct RgGraphSpec {
  std::vector<RegionId> regions;  // every region, also those without a gateway
  std::vector<GatewaySpec> gateways;
};

struct RgNode {
  NodeKey key;
  RegionId region;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  bool door = false;  // its gateway is a door

  GatewayId gateway() const { return key.gateway; }
};

struct RgEdge {
  EdgeKey key;
  std::size_t from = 0;      // index in nodes() of key.a
  std::size_t to = 0;        // index in nodes() of key.b
  GatewayId gateway;         // a gateway edge: the gateway it goes through; a region edge: none
  RegionId region;           // a region edge: the region it goes through; a gateway edge: none
  double lengthM = 0.0;      // Euclidean length
  double costM = 0.0;        // current cost, >= lengthM

  EdgeKind kind() const { return key.kind; }
};

class RgGraph {
 public:
  // An empty graph (no regions) with the given learned costs.
  explicit RgGraph(EdgeCostTable costs = EdgeCostTable());

  // Replaces the structure with the one described by `spec`; learned costs are kept.
  // Nodes come in gateway ID order, side A before side B; edges are the gateway edges in gateway
  // order, then the region edges by region and node order. Throws InvalidArgumentError (and
  // leaves the graph unchanged) for a duplicate region or gateway ID, a crossing point in a region
  // not listed, or a non-finite position.
  void build(const RgGraphSpec& spec);

  const std::vector<RgNode>& nodes() const { return nodes_; }
  const std::vector<RgEdge>& edges() const { return edges_; }
  const std::vector<RegionId>& regions() const { return regions_; }  // ascending

  bool hasRegion(RegionId r) const { return regionNodes_.contains(r); }
  // Indices of the crossing points in region r. Throws InvalidArgumentError for an unknown region.
  const std::vector<std::size_t>& nodesInRegion(RegionId r) const;
  // Indices of the edges at node i (for i < nodes().size()).
  const std::vector<std::size_t>& edgesAt(std::size_t i) const { return adjacency_.at(i); }

  std::optional<std::size_t> findNode(const NodeKey& key) const;
  std::optional<std::size_t> findEdge(const EdgeKey& key) const;  // a and b in either order

  // Cost adaptation (EdgeCostTable.h); the affected edge's cost changes at once.
  // Throws InvalidArgumentError for an edge that is not in the graph or bad measurements.
  void recordTraversal(const EdgeKey& edge, double lengthM, double timeS);
  // Throws InvalidArgumentError for a gateway that is not in the graph or is not a door.
  void recordDoorState(GatewayId g, bool traversable);

  const EdgeCostTable& costs() const { return costs_; }

 private:
  EdgeCostTable costs_;
  std::vector<RegionId> regions_;
  std::vector<RgNode> nodes_;
  std::vector<RgEdge> edges_;
  std::vector<std::vector<std::size_t>> adjacency_;           // per node: edge indices
  std::map<RegionId, std::vector<std::size_t>> regionNodes_;  // per region: node indices
  std::map<NodeKey, std::size_t> nodeIndex_;
  std::map<EdgeKey, std::size_t> edgeIndex_;
};

}  // namespace rgnav
