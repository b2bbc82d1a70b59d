// RgGraph: the Region & Gateway Graph (thesis 2.1.3); see RgGraph.h.
#include "core/rgmap/graph/RgGraph.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

// The structure build() assembles before it swaps it in. Nodes are in NodeKey order (gateway
// order, side A first), so an edge between nodes u < v has from = u and to = v.
struct Structure {
  std::vector<RegionId> regions;
  std::vector<RgNode> nodes;
  std::vector<RgEdge> edges;
  std::vector<std::vector<std::size_t>> adjacency;
  std::map<RegionId, std::vector<std::size_t>> regionNodes;
  std::map<NodeKey, std::size_t> nodeIndex;
  std::map<EdgeKey, std::size_t> edgeIndex;
};

void checkCrossingPoint(const GatewaySpec& g, const CrossingPointSpec& c, const char* side,
                        const std::map<RegionId, std::vector<std::size_t>>& regionNodes) {
  const std::string name = "gateway " + std::to_string(g.id.value()) + " side " + side;
  if (!regionNodes.contains(c.region))
    throw InvalidArgumentError(name + " lies in region " + std::to_string(c.region.value()) + ", which is not listed");
  if (!c.position.allFinite()) throw InvalidArgumentError(name + " has a non-finite position");
}

// Appends gateway g's two crossing points and its gateway edge.
void addGateway(Structure& s, const GatewaySpec& g) {
  checkCrossingPoint(g, g.sideA, "A", s.regionNodes);
  checkCrossingPoint(g, g.sideB, "B", s.regionNodes);
  for (const auto& [side, c] : {std::pair{GatewaySide::A, &g.sideA}, std::pair{GatewaySide::B, &g.sideB}}) {
    s.regionNodes[c->region].push_back(s.nodes.size());
    s.nodes.push_back({{g.id, side}, c->region, c->position, g.isDoor});
  }
  const std::size_t a = s.nodes.size() - 2;
  s.edges.push_back({gatewayEdgeKey(g.id), a, a + 1, g.id, RegionId{}, 0.0, 0.0});
}

// Appends an edge between every pair of crossing points in the same region.
void addRegionEdges(Structure& s) {
  for (const auto& [region, members] : s.regionNodes) {
    for (std::size_t i = 0; i < members.size(); ++i) {
      for (std::size_t j = i + 1; j < members.size(); ++j) {
        const std::size_t u = members[i], v = members[j];
        s.edges.push_back({edgeKey(EdgeKind::Region, s.nodes[u].key, s.nodes[v].key), u, v, GatewayId{}, region, 0.0, 0.0});
      }
    }
  }
}

// Edge lengths, adjacency and the key indexes.
void index(Structure& s) {
  s.adjacency.resize(s.nodes.size());
  for (std::size_t i = 0; i < s.nodes.size(); ++i) s.nodeIndex[s.nodes[i].key] = i;
  for (std::size_t i = 0; i < s.edges.size(); ++i) {
    RgEdge& e = s.edges[i];
    e.lengthM = (s.nodes[e.from].position - s.nodes[e.to].position).norm();
    s.edgeIndex[e.key] = i;
    s.adjacency[e.from].push_back(i);
    s.adjacency[e.to].push_back(i);
  }
}

Structure assemble(const RgGraphSpec& spec) {
  Structure s;
  s.regions = spec.regions;
  std::sort(s.regions.begin(), s.regions.end());
  if (const auto d = std::adjacent_find(s.regions.begin(), s.regions.end()); d != s.regions.end())
    throw InvalidArgumentError("region " + std::to_string(d->value()) + " is listed twice");
  for (const RegionId r : s.regions) s.regionNodes[r];

  std::vector<const GatewaySpec*> gateways;
  for (const GatewaySpec& g : spec.gateways) gateways.push_back(&g);
  std::sort(gateways.begin(), gateways.end(), [](const auto* a, const auto* b) { return a->id < b->id; });
  for (std::size_t i = 0; i < gateways.size(); ++i) {
    if (i > 0 && gateways[i - 1]->id == gateways[i]->id)
      throw InvalidArgumentError("gateway " + std::to_string(gateways[i]->id.value()) + " is listed twice");
    addGateway(s, *gateways[i]);
  }
  addRegionEdges(s);
  index(s);
  return s;
}

bool isDoorEdge(const RgEdge& edge, const std::vector<RgNode>& nodes) {
  return edge.kind() == EdgeKind::Gateway && nodes[edge.from].door;
}

}  // namespace

RgGraph::RgGraph(EdgeCostTable costs) : costs_(std::move(costs)) {}

void RgGraph::build(const RgGraphSpec& spec) {
  Structure s = assemble(spec);
  for (RgEdge& e : s.edges) e.costM = costs_.cost(e.key, e.lengthM, isDoorEdge(e, s.nodes));
  regions_ = std::move(s.regions);
  nodes_ = std::move(s.nodes);
  edges_ = std::move(s.edges);
  adjacency_ = std::move(s.adjacency);
  regionNodes_ = std::move(s.regionNodes);
  nodeIndex_ = std::move(s.nodeIndex);
  edgeIndex_ = std::move(s.edgeIndex);
}

const std::vector<std::size_t>& RgGraph::nodesInRegion(RegionId r) const {
  const auto it = regionNodes_.find(r);
  if (it == regionNodes_.end()) throw InvalidArgumentError("region " + std::to_string(r.value()) + " is not in the RG graph");
  return it->second;
}

std::optional<std::size_t> RgGraph::findNode(const NodeKey& key) const {
  const auto it = nodeIndex_.find(key);
  if (it == nodeIndex_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::size_t> RgGraph::findEdge(const EdgeKey& key) const {
  const auto it = edgeIndex_.find(edgeKey(key.kind, key.a, key.b));
  if (it == edgeIndex_.end()) return std::nullopt;
  return it->second;
}

void RgGraph::recordTraversal(const EdgeKey& edge, double lengthM, double timeS) {
  const auto i = findEdge(edge);
  if (!i) throw InvalidArgumentError(toString(edge) + " is not in the RG graph");
  RgEdge& e = edges_[*i];
  costs_.recordTraversal(e.key, lengthM, timeS);
  e.costM = costs_.cost(e.key, e.lengthM, isDoorEdge(e, nodes_));
}

void RgGraph::recordDoorState(GatewayId g, bool traversable) {
  const auto i = findEdge(gatewayEdgeKey(g));
  if (!i) throw InvalidArgumentError("gateway " + std::to_string(g.value()) + " is not in the RG graph");
  RgEdge& e = edges_[*i];
  if (!isDoorEdge(e, nodes_)) throw InvalidArgumentError("gateway " + std::to_string(g.value()) + " is not a door");
  costs_.recordDoorState(g, traversable);
  e.costM = costs_.cost(e.key, e.lengthM, true);
}

}  // namespace rgnav
