// Stable identities in the Region & Gateway Graph (thesis 2.1.3): a node is a crossing point,
// named by its gateway and the side of that gateway it lies on; an edge is named by its kind and
// its two node keys. These keys outlive a rebuild of the graph, so adapted costs are kept by them.
// Deliberate difference: the thesis annotates a node with its gateway and region ID; we keep both
// on the node (RgGraph.h) but name it by gateway and side, because a neutralised gateway has the
// same region on both sides and a merge of regions changes region IDs but not crossing points.
#pragma once

#include <compare>
#include <cstdint>
#include <string>

#include "core/common/TypedId.h"

namespace rgnav {

// The kernel's numbering of regions and of the gateways it took in (see TypedId.h).
using RegionId = TypedId<struct RegionConcept>;
using GatewayId = TypedId<struct GatewayConcept>;

// The two sides of a gateway; each has one crossing point.
enum class GatewaySide : std::uint8_t { A = 0, B = 1 };

// A route through a gateway (between its two crossing points) or through a region (between two
// crossing points in the same region).
enum class EdgeKind : std::uint8_t { Gateway = 0, Region = 1 };

struct NodeKey {
  GatewayId gateway;
  GatewaySide side = GatewaySide::A;

  auto operator<=>(const NodeKey&) const = default;
};

// a < b; build keys with edgeKey() or gatewayEdgeKey() to get that order.
struct EdgeKey {
  EdgeKind kind = EdgeKind::Gateway;
  NodeKey a;
  NodeKey b;

  auto operator<=>(const EdgeKey&) const = default;
};

// The key of the edge of `kind` between u and v, in either order.
inline EdgeKey edgeKey(EdgeKind kind, const NodeKey& u, const NodeKey& v) {
  return v < u ? EdgeKey{kind, v, u} : EdgeKey{kind, u, v};
}

// The key of the edge through gateway g.
inline EdgeKey gatewayEdgeKey(GatewayId g) {
  return {EdgeKind::Gateway, {g, GatewaySide::A}, {g, GatewaySide::B}};
}

// "G7A", for messages.
inline std::string toString(const NodeKey& k) {
  std::string out = std::to_string(k.gateway.value());  // appended, not "G" + ...: GCC 12 -Wrestrict false alarm
  out.insert(out.begin(), 'G');
  out += k.side == GatewaySide::A ? 'A' : 'B';
  return out;
}

// "gateway edge G7A-G7B" or "region edge G3B-G7A", for messages.
inline std::string toString(const EdgeKey& k) {
  return std::string(k.kind == EdgeKind::Gateway ? "gateway" : "region") + " edge " + toString(k.a) + "-" +
         toString(k.b);
}

}  // namespace rgnav
