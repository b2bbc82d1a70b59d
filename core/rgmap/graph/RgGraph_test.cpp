// Tests the RG Graph (thesis 2.1.3) of a small hand-made floor: its nodes and edges with their
// annotations, the neutralised gateway, cost adaptation through the graph (5.4), learned costs
// that survive a rebuild and a merge of regions, costs never below the Euclidean length, and
// descriptions that are rejected without touching the graph.
#include "core/rgmap/graph/RgGraph.h"

#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <limits>
#include <random>

#include "core/common/Errors.h"
#include "core/rgmap/graph/testing/SmallFloor.h"

using rgnav::EdgeKind;
using rgnav::GatewayId;
using rgnav::GatewaySide;
using rgnav::NodeKey;
using rgnav::RegionId;
using rgnav::RgGraph;
using rgnav::RgGraphSpec;
using namespace rgnav::testing;

namespace {

constexpr GatewaySide A = GatewaySide::A, B = GatewaySide::B;

RgGraph smallGraph() {
  RgGraph g;
  g.build(smallFloor());
  return g;
}

const rgnav::RgEdge& edge(const RgGraph& g, const rgnav::EdgeKey& key) {
  const auto i = g.findEdge(key);
  CPPUNIT_ASSERT(i.has_value());
  return g.edges()[*i];
}

rgnav::EdgeKey regionEdge(NodeKey u, NodeKey v) { return rgnav::edgeKey(EdgeKind::Region, u, v); }

// The floor with the lab absorbed into the office: door 12 is neutralised.
RgGraphSpec labMergedIntoOffice() {
  RgGraphSpec spec = smallFloor();
  std::erase(spec.regions, kLab);
  for (auto& gw : spec.gateways) {
    for (auto* side : {&gw.sideA, &gw.sideB})
      if (side->region == kLab) side->region = kOffice;
  }
  return spec;
}

}  // namespace

class RgGraphTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgGraphTest);
  CPPUNIT_TEST(nodesAreCrossingPoints);
  CPPUNIT_TEST(edgesThroughGatewaysAndRegions);
  CPPUNIT_TEST(neutralisedGatewayConnectsNothingNew);
  CPPUNIT_TEST(regionWithoutGateways);
  CPPUNIT_TEST(traversalAndDoorStateChangeCosts);
  CPPUNIT_TEST(costsSurviveRebuild);
  CPPUNIT_TEST(costsSurviveMergeOfRegions);
  CPPUNIT_TEST(costsNeverBelowEuclidean);
  CPPUNIT_TEST(restoredCostTable);
  CPPUNIT_TEST(badDescriptionLeavesGraphUnchanged);
  CPPUNIT_TEST(unknownEdgeOrGatewayIsInvalidArgument);
  CPPUNIT_TEST_SUITE_END();

 public:
  void nodesAreCrossingPoints() {
    const RgGraph g = smallGraph();
    CPPUNIT_ASSERT_EQUAL(std::size_t(10), g.nodes().size());
    CPPUNIT_ASSERT(g.regions() == (std::vector<rgnav::RegionId>{kHallway, kOffice, kLab, kLobby}));
    const auto& door = g.nodes()[*g.findNode({kOfficeLabDoor, B})];
    CPPUNIT_ASSERT_EQUAL(kOfficeLabDoor, door.gateway());
    CPPUNIT_ASSERT_EQUAL(kLab, door.region);
    CPPUNIT_ASSERT(door.door);
    CPPUNIT_ASSERT(door.position.isApprox(Eigen::Vector2d(6.5, 5.0)));
    CPPUNIT_ASSERT(!g.nodes()[*g.findNode({kHallLab, A})].door);
    for (std::size_t i = 1; i < g.nodes().size(); ++i) CPPUNIT_ASSERT(g.nodes()[i - 1].key < g.nodes()[i].key);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), g.nodesInRegion(kHallway).size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), g.nodesInRegion(kOffice).size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), g.nodesInRegion(kLobby).size());
    for (const std::size_t i : g.nodesInRegion(kLobby)) CPPUNIT_ASSERT_EQUAL(kLobby, g.nodes()[i].region);
    CPPUNIT_ASSERT(!g.findNode({GatewayId{99}, A}).has_value());
  }

  void edgesThroughGatewaysAndRegions() {
    const RgGraph g = smallGraph();
    // 5 gateway edges; region edges: hallway 3, office 1, lab 1, lobby 3.
    CPPUNIT_ASSERT_EQUAL(std::size_t(13), g.edges().size());
    std::size_t gatewayEdges = 0;
    for (const auto& e : g.edges()) {
      const auto& u = g.nodes()[e.from];
      const auto& v = g.nodes()[e.to];
      CPPUNIT_ASSERT(u.key == e.key.a && v.key == e.key.b);
      if (e.kind() == EdgeKind::Gateway) {
        ++gatewayEdges;
        CPPUNIT_ASSERT(u.gateway() == e.gateway && v.gateway() == e.gateway && e.region.isNone());
      } else {
        CPPUNIT_ASSERT(u.region == e.region && v.region == e.region && e.gateway.isNone());
      }
      CPPUNIT_ASSERT_DOUBLES_EQUAL((u.position - v.position).norm(), e.lengthM, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(e.lengthM, e.costM, 1e-12);
      const std::size_t i = static_cast<std::size_t>(&e - g.edges().data());
      CPPUNIT_ASSERT(std::ranges::count(g.edgesAt(e.from), i) == 1 && std::ranges::count(g.edgesAt(e.to), i) == 1);
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(5), gatewayEdges);
    const auto& hall = edge(g, regionEdge({kHallLobby, A}, {kHallOffice, A}));  // either order
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::hypot(16.5, 0.5), hall.lengthM, 1e-12);
    CPPUNIT_ASSERT_EQUAL(kHallway, hall.region);
    CPPUNIT_ASSERT(!g.findEdge(regionEdge({kHallOffice, A}, {kHallLab, B})).has_value());  // different regions
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), g.edgesAt(*g.findNode({kHallOffice, A})).size());  // gateway + 2 in hallway
  }

  void neutralisedGatewayConnectsNothingNew() {
    const RgGraph g = smallGraph();
    const auto& through = edge(g, rgnav::gatewayEdgeKey(kLobbyFalse));
    const auto& around = edge(g, regionEdge({kLobbyFalse, A}, {kLobbyFalse, B}));
    CPPUNIT_ASSERT(g.nodes()[through.from].region == kLobby && g.nodes()[through.to].region == kLobby);
    CPPUNIT_ASSERT_EQUAL(kLobby, around.region);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, through.lengthM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, around.lengthM, 1e-12);
    // Each of its crossing points: the gateway edge and the two other lobby crossing points.
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), g.edgesAt(*g.findNode({kLobbyFalse, A})).size());
  }

  void regionWithoutGateways() {
    RgGraphSpec spec = smallFloor();
    spec.regions.push_back(RegionId{5});
    RgGraph g;
    g.build(spec);
    CPPUNIT_ASSERT(g.hasRegion(RegionId{5}));
    CPPUNIT_ASSERT(g.nodesInRegion(RegionId{5}).empty());
    CPPUNIT_ASSERT(!g.hasRegion(RegionId{6}));
    CPPUNIT_ASSERT_THROW(g.nodesInRegion(RegionId{6}), rgnav::InvalidArgumentError);
    RgGraph empty;
    CPPUNIT_ASSERT(empty.nodes().empty() && empty.edges().empty() && empty.regions().empty());
  }

  void traversalAndDoorStateChangeCosts() {
    RgGraph g = smallGraph();
    const auto key = regionEdge({kHallOffice, A}, {kHallLab, A});  // 6 m along the hallway
    g.recordTraversal(key, 7.0, 0.0);
    g.recordTraversal(key, 9.0, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(8.0, edge(g, key).costM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(6.0, edge(g, key).lengthM, 1e-12);
    g.recordDoorState(kOfficeLabDoor, false);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(31.0, edge(g, rgnav::gatewayEdgeKey(kOfficeLabDoor)).costM, 1e-12);
    g.recordDoorState(kOfficeLabDoor, true);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, edge(g, rgnav::gatewayEdgeKey(kOfficeLabDoor)).costM, 1e-12);
  }

  void costsSurviveRebuild() {
    RgGraph g = smallGraph();
    const auto key = regionEdge({kHallOffice, A}, {kHallLobby, A});
    g.recordTraversal(key, 20.0, 0.0);
    g.recordDoorState(kOfficeLabDoor, false);
    RgGraphSpec moved = smallFloor();
    moved.gateways.back().sideB.position.x() += 0.5;  // a refined crossing point elsewhere
    std::ranges::reverse(moved.gateways);             // and another order
    g.build(moved);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(20.0, edge(g, key).costM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(31.0, edge(g, rgnav::gatewayEdgeKey(kOfficeLabDoor)).costM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.5, edge(g, rgnav::gatewayEdgeKey(kLobbyFalse)).costM, 1e-12);
  }

  void costsSurviveMergeOfRegions() {
    RgGraph g = smallGraph();
    const auto officeEdge = regionEdge({kHallOffice, B}, {kOfficeLabDoor, A});
    g.recordTraversal(officeEdge, 5.0, 0.0);
    g.recordDoorState(kOfficeLabDoor, false);
    g.build(labMergedIntoOffice());
    CPPUNIT_ASSERT(!g.hasRegion(kLab));
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), g.nodesInRegion(kOffice).size());
    CPPUNIT_ASSERT_EQUAL(kOffice, g.nodes()[*g.findNode({kHallLab, B})].region);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, edge(g, officeEdge).costM, 1e-12);
    // The door is neutralised but still a door edge with its offset, and the new region edges
    // between former office and lab crossing points are there at their Euclidean length.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(31.0, edge(g, rgnav::gatewayEdgeKey(kOfficeLabDoor)).costM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, edge(g, regionEdge({kOfficeLabDoor, A}, {kOfficeLabDoor, B})).costM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(6.0, edge(g, regionEdge({kHallOffice, B}, {kHallLab, B})).costM, 1e-12);
    CPPUNIT_ASSERT_EQUAL(std::size_t(5 + 3 + 6 + 3), g.edges().size());
  }

  void costsNeverBelowEuclidean() {
    RgGraph g = smallGraph();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> fraction(0.0, 2.0);
    std::bernoulli_distribution open(0.6);
    for (int i = 0; i < 500; ++i) {
      const auto& e = g.edges()[random() % g.edges().size()];
      g.recordTraversal(e.key, fraction(random) * e.lengthM, fraction(random) * e.lengthM);
      g.recordDoorState(kOfficeLabDoor, open(random));
      for (const auto& f : g.edges()) CPPUNIT_ASSERT(f.costM >= f.lengthM);
    }
  }

  void restoredCostTable() {
    RgGraph learned = smallGraph();
    learned.recordTraversal(rgnav::gatewayEdgeKey(kHallLab), 3.0, 0.0);
    learned.recordDoorState(kOfficeLabDoor, false);
    rgnav::EdgeCostTable table(learned.costs().config());
    for (const auto& [key, stats] : learned.costs().traversals()) table.restoreTraversal(key, stats);
    for (const auto& [gw, offset] : learned.costs().doorOffsets()) table.restoreDoorOffset(gw, offset);
    RgGraph restored(table);
    restored.build(smallFloor());
    for (std::size_t i = 0; i < learned.edges().size(); ++i)
      CPPUNIT_ASSERT_DOUBLES_EQUAL(learned.edges()[i].costM, restored.edges()[i].costM, 1e-12);
  }

  void badDescriptionLeavesGraphUnchanged() {
    RgGraph g = smallGraph();
    const auto bad = [&g](auto change) {
      RgGraphSpec spec = smallFloor();
      change(spec);
      CPPUNIT_ASSERT_THROW(g.build(spec), rgnav::InvalidArgumentError);
      CPPUNIT_ASSERT_EQUAL(std::size_t(10), g.nodes().size());
      CPPUNIT_ASSERT_EQUAL(std::size_t(13), g.edges().size());
      CPPUNIT_ASSERT_EQUAL(std::size_t(4), g.regions().size());
    };
    bad([](RgGraphSpec& s) { s.regions.push_back(kOffice); });
    bad([](RgGraphSpec& s) { s.gateways.push_back(s.gateways.front()); });
    bad([](RgGraphSpec& s) { s.gateways.front().sideB.region = RegionId{42}; });
    bad([](RgGraphSpec& s) { std::erase(s.regions, kLobby); });
    bad([](RgGraphSpec& s) { s.gateways.front().sideA.position.y() = std::numeric_limits<double>::infinity(); });
  }

  void unknownEdgeOrGatewayIsInvalidArgument() {
    RgGraph g = smallGraph();
    CPPUNIT_ASSERT_THROW(g.recordTraversal(regionEdge({kHallOffice, A}, {kHallLab, B}), 1.0, 0.0),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(g.recordTraversal(rgnav::gatewayEdgeKey(kHallLab), -1.0, 0.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(g.recordDoorState(GatewayId{99}, false), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(g.recordDoorState(kHallLab, false), rgnav::InvalidArgumentError);  // not a door
    CPPUNIT_ASSERT(g.costs().traversals().empty() && g.costs().doorOffsets().empty());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgGraphTest);
