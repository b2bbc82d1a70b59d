// Tests A* path planning on the RG Graph (thesis 5.4): the path across the small hand-made floor
// and its cost, the direct route within one region, a blocked door avoided and used again once
// open, a neutralised gateway after a merge, the typed errors, and (property test, fixed seed)
// that A* finds the cost of an independent Dijkstra search on random graphs with learned costs.
#include "core/rgmap/graph/RgPathSearch.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <random>

#include "core/common/Errors.h"
#include "core/rgmap/graph/testing/SmallFloor.h"

using Eigen::Vector2d;
using rgnav::EdgeKind;
using rgnav::GatewayId;
using rgnav::GatewaySide;
using rgnav::NodeKey;
using rgnav::RegionId;
using rgnav::RgGraph;
using rgnav::RgGraphSpec;
using rgnav::RgPath;
using rgnav::RgPlace;
using namespace rgnav::testing;

namespace {

constexpr GatewaySide A = GatewaySide::A, B = GatewaySide::B;

RgGraph graphOf(const RgGraphSpec& spec) {
  RgGraph g;
  g.build(spec);
  return g;
}

std::vector<NodeKey> keys(const RgPath& path) {
  std::vector<NodeKey> out;
  for (const auto& n : path.crossings) out.push_back(n.key);
  return out;
}

// The Euclidean length of the polyline start, crossings..., goal.
double polyline(const RgPlace& start, const RgPath& path, const RgPlace& goal) {
  double length = 0.0;
  Vector2d at = start.position;
  for (const auto& n : path.crossings) {
    length += (n.position - at).norm();
    at = n.position;
  }
  return length + (goal.position - at).norm();
}

// Checks that the path is a chain of graph edges from start's region to goal's region and that its
// cost and length are the sums along it.
void checkConsistent(const RgGraph& g, const RgPlace& start, const RgPath& path, const RgPlace& goal) {
  const auto& c = path.crossings;
  CPPUNIT_ASSERT_EQUAL(c.empty() ? std::size_t(0) : c.size() - 1, path.edges.size());
  if (c.empty()) {
    CPPUNIT_ASSERT_EQUAL(start.region, goal.region);
    CPPUNIT_ASSERT_DOUBLES_EQUAL((goal.position - start.position).norm(), path.costM, 1e-9);
    return;
  }
  CPPUNIT_ASSERT_EQUAL(start.region, c.front().region);
  CPPUNIT_ASSERT_EQUAL(goal.region, c.back().region);
  double cost = (c.front().position - start.position).norm() + (goal.position - c.back().position).norm();
  for (std::size_t i = 0; i < path.edges.size(); ++i) {
    const auto e = g.findEdge(path.edges[i]);
    CPPUNIT_ASSERT(e.has_value());
    const auto& edge = g.edges()[*e];
    CPPUNIT_ASSERT(rgnav::edgeKey(edge.kind(), c[i].key, c[i + 1].key) == edge.key);
    cost += edge.costM;
  }
  CPPUNIT_ASSERT_DOUBLES_EQUAL(cost, path.costM, 1e-9);
  CPPUNIT_ASSERT_DOUBLES_EQUAL(polyline(start, path, goal), path.lengthM, 1e-9);
}

// Plain Dijkstra over the exported nodes and edges plus the temporary start and goal links;
// nullopt when the goal cannot be reached.
std::optional<double> dijkstra(const RgGraph& g, const RgPlace& start, const RgPlace& goal) {
  const std::size_t n = g.nodes().size(), s = n, t = n + 1;
  std::vector<std::vector<std::pair<std::size_t, double>>> adjacent(n + 2);
  for (const auto& e : g.edges()) {
    adjacent[e.from].push_back({e.to, e.costM});
    adjacent[e.to].push_back({e.from, e.costM});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto& node = g.nodes()[i];
    if (node.region == start.region) adjacent[s].push_back({i, (node.position - start.position).norm()});
    if (node.region == goal.region) adjacent[i].push_back({t, (node.position - goal.position).norm()});
  }
  if (start.region == goal.region) adjacent[s].push_back({t, (goal.position - start.position).norm()});
  std::vector<double> dist(n + 2, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  dist[s] = 0.0;
  open.push({0.0, s});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    for (const auto& [v, w] : adjacent[u]) {
      if (d + w < dist[v]) {
        dist[v] = d + w;
        open.push({dist[v], v});
      }
    }
  }
  if (std::isinf(dist[t])) return std::nullopt;
  return dist[t];
}

// A random map: regions on a grid of rooms, gateways between random pairs of regions (some
// neutralised, some doors), crossing points near the border, random learned costs.
RgGraph randomGraph(std::mt19937& random) {
  std::uniform_int_distribution<int> regionCount(1, 10), gatewayCount(0, 18);
  std::uniform_real_distribution<double> coordinate(0.0, 30.0), offset(-0.6, 0.6), unit(0.0, 1.0);
  RgGraphSpec spec;
  const int regions = regionCount(random);
  for (int r = 0; r < regions; ++r) spec.regions.push_back(RegionId(100 + 7 * r));
  std::uniform_int_distribution<std::size_t> pick(0, spec.regions.size() - 1);
  const int gateways = gatewayCount(random);
  for (int i = 0; i < gateways; ++i) {
    const Vector2d at(coordinate(random), coordinate(random));
    const auto a = spec.regions[pick(random)];
    const auto b = unit(random) < 0.15 ? a : spec.regions[pick(random)];
    spec.gateways.push_back({static_cast<rgnav::GatewayId>(1000 - 3 * i), unit(random) < 0.3,
                             {a, at + Vector2d(offset(random), offset(random))},
                             {b, at + Vector2d(offset(random), offset(random))}});
  }
  RgGraph g;
  g.build(spec);
  for (std::size_t i = 0; i < g.edges().size(); ++i) {
    if (unit(random) < 0.4) {
      const auto& e = g.edges()[i];
      g.recordTraversal(e.key, e.lengthM * (0.8 + unit(random)), 40.0 * unit(random));
    }
  }
  for (const auto& gw : spec.gateways)
    if (gw.isDoor && unit(random) < 0.5) g.recordDoorState(gw.id, unit(random) < 0.5);
  return g;
}

}  // namespace

class RgPathSearchTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgPathSearchTest);
  CPPUNIT_TEST(pathAcrossTheFloor);
  CPPUNIT_TEST(directRouteWithinOneRegion);
  CPPUNIT_TEST(blockedDoorIsAvoidedUntilOpen);
  CPPUNIT_TEST(measuredCostsChangeThePath);
  CPPUNIT_TEST(neutralisedGatewayAfterMerge);
  CPPUNIT_TEST(noPathIsNotAvailable);
  CPPUNIT_TEST(unknownRegionIsInvalidArgument);
  CPPUNIT_TEST(aStarEqualsDijkstraOnRandomGraphs);
  CPPUNIT_TEST_SUITE_END();

 public:
  void pathAcrossTheFloor() {
    const RgGraph g = graphOf(smallFloor());
    const RgPlace start{kOffice, {2.0, 6.0}}, goal{kLobby, {28.0, 1.0}};
    const RgPath path = rgnav::findPath(g, start, goal);
    // Through the door into the lab, out into the hallway and along it to the lobby.
    const std::vector<NodeKey> expected{{kOfficeLabDoor, A}, {kOfficeLabDoor, B}, {kHallLab, B},
                                        {kHallLab, A},       {kHallLobby, A},     {kHallLobby, B}};
    CPPUNIT_ASSERT(keys(path) == expected);
    const double cost = std::hypot(3.5, 1.0) + 1.0 + std::hypot(2.5, 2.5) + 1.0 + std::hypot(10.5, 0.5) + 1.0 + 7.5;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(cost, path.costM, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(cost, path.lengthM, 1e-9);
    CPPUNIT_ASSERT(path.edges[0] == rgnav::gatewayEdgeKey(kOfficeLabDoor));
    CPPUNIT_ASSERT(path.edges[1].kind == EdgeKind::Region);
    CPPUNIT_ASSERT_EQUAL(kLab, path.crossings[1].region);
    checkConsistent(g, start, path, goal);
  }

  void directRouteWithinOneRegion() {
    const RgGraph g = graphOf(smallFloor());
    const RgPlace start{kHallway, {1.0, 1.0}}, goal{kHallway, {15.0, 1.0}};
    const RgPath path = rgnav::findPath(g, start, goal);
    CPPUNIT_ASSERT(path.crossings.empty() && path.edges.empty());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(14.0, path.costM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, rgnav::findPath(g, goal, goal).costM, 1e-12);
  }

  void blockedDoorIsAvoidedUntilOpen() {
    RgGraph g = graphOf(smallFloor());
    const RgPlace start{kOffice, {2.0, 6.0}}, goal{kLab, {10.0, 6.0}};
    const std::vector<NodeKey> viaDoor{{kOfficeLabDoor, A}, {kOfficeLabDoor, B}};
    const std::vector<NodeKey> viaHallway{{kHallOffice, B}, {kHallOffice, A}, {kHallLab, A}, {kHallLab, B}};
    const double doorCost = 2.0 * std::hypot(3.5, 1.0) + 1.0;
    const double hallwayCost = std::hypot(1.0, 3.5) + 1.0 + 6.0 + 1.0 + std::hypot(1.0, 3.5);
    RgPath path = rgnav::findPath(g, start, goal);
    CPPUNIT_ASSERT(keys(path) == viaDoor);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(doorCost, path.costM, 1e-9);

    g.recordDoorState(kOfficeLabDoor, false);
    path = rgnav::findPath(g, start, goal);
    CPPUNIT_ASSERT(keys(path) == viaHallway);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(hallwayCost, path.costM, 1e-9);
    checkConsistent(g, start, path, goal);

    g.recordDoorState(kOfficeLabDoor, true);
    path = rgnav::findPath(g, start, goal);
    CPPUNIT_ASSERT(keys(path) == viaDoor);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(doorCost, path.costM, 1e-9);
  }

  void measuredCostsChangeThePath() {
    RgGraph g = graphOf(smallFloor());
    const RgPlace start{kOffice, {2.0, 6.0}}, goal{kLobby, {28.0, 1.0}};
    // The lab turns out to be cluttered: crossing it took 60 s for 5 m.
    g.recordTraversal(rgnav::edgeKey(EdgeKind::Region, {kOfficeLabDoor, B}, {kHallLab, B}), 5.0, 60.0);
    const RgPath path = rgnav::findPath(g, start, goal);
    const std::vector<NodeKey> expected{{kHallOffice, B}, {kHallOffice, A}, {kHallLobby, A}, {kHallLobby, B}};
    CPPUNIT_ASSERT(keys(path) == expected);
    checkConsistent(g, start, path, goal);
  }

  void neutralisedGatewayAfterMerge() {
    RgGraphSpec spec = smallFloor();
    std::erase(spec.regions, kLab);
    for (auto& gw : spec.gateways) {
      if (gw.sideA.region == kLab) gw.sideA.region = kOffice;
      if (gw.sideB.region == kLab) gw.sideB.region = kOffice;
    }
    RgGraph g = graphOf(spec);
    g.recordDoorState(kOfficeLabDoor, false);  // the neutralised door: the region goes around it
    const RgPlace office{kOffice, {2.0, 6.0}}, formerLab{kOffice, {10.0, 6.0}}, lobby{kLobby, {28.0, 1.0}};
    CPPUNIT_ASSERT(rgnav::findPath(g, office, formerLab).crossings.empty());
    const RgPath path = rgnav::findPath(g, lobby, formerLab);
    const std::vector<NodeKey> expected{{kHallLobby, B}, {kHallLobby, A}, {kHallLab, A}, {kHallLab, B}};
    CPPUNIT_ASSERT(keys(path) == expected);
    checkConsistent(g, lobby, path, formerLab);
    // From one side of the lobby's false gateway to the other: straight, not through it.
    CPPUNIT_ASSERT(rgnav::findPath(g, {kLobby, {24.0, 4.0}}, {kLobby, {26.0, 4.0}}).crossings.empty());
  }

  void noPathIsNotAvailable() {
    RgGraphSpec spec = smallFloor();
    spec.regions.push_back(RegionId{5});
    spec.gateways.push_back({GatewayId{20}, true, {RegionId{5}, {40.0, 0.0}}, {RegionId{5}, {41.0, 0.0}}});  // only within region 5
    const RgGraph g = graphOf(spec);
    CPPUNIT_ASSERT_THROW(rgnav::findPath(g, {kHallway, {1.0, 1.0}}, {RegionId{5}, {40.0, 2.0}}), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(rgnav::findPath(g, {RegionId{5}, {40.0, 2.0}}, {kOffice, {2.0, 6.0}}), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, rgnav::findPath(g, {RegionId{5}, {40.0, 2.0}}, {RegionId{5}, {40.0, 4.0}}).costM, 1e-12);
  }

  void unknownRegionIsInvalidArgument() {
    const RgGraph g = graphOf(smallFloor());
    CPPUNIT_ASSERT_THROW(rgnav::findPath(g, {RegionId{99}, {0.0, 0.0}}, {kOffice, {2.0, 6.0}}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::findPath(g, {kOffice, {2.0, 6.0}}, {RegionId{99}, {0.0, 0.0}}), rgnav::InvalidArgumentError);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CPPUNIT_ASSERT_THROW(rgnav::findPath(g, {kOffice, {nan, 6.0}}, {kLab, {9.0, 6.0}}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::findPath(RgGraph(), {RegionId{1}, {0.0, 0.0}}, {RegionId{1}, {1.0, 0.0}}), rgnav::InvalidArgumentError);
  }

  void aStarEqualsDijkstraOnRandomGraphs() {
    std::mt19937 random(20240611);
    std::uniform_real_distribution<double> coordinate(-2.0, 32.0);
    std::size_t found = 0, unreachable = 0;
    for (int graph = 0; graph < 300; ++graph) {
      const RgGraph g = randomGraph(random);
      std::uniform_int_distribution<std::size_t> pick(0, g.regions().size() - 1);
      for (int query = 0; query < 20; ++query) {
        const RgPlace start{g.regions()[pick(random)], {coordinate(random), coordinate(random)}};
        const RgPlace goal{g.regions()[pick(random)], {coordinate(random), coordinate(random)}};
        const auto expected = dijkstra(g, start, goal);
        if (!expected) {
          CPPUNIT_ASSERT_THROW(rgnav::findPath(g, start, goal), rgnav::NotAvailableError);
          ++unreachable;
          continue;
        }
        const RgPath path = rgnav::findPath(g, start, goal);
        CPPUNIT_ASSERT_DOUBLES_EQUAL(*expected, path.costM, 1e-9 * (1.0 + *expected));
        CPPUNIT_ASSERT(path.lengthM <= path.costM + 1e-9);
        checkConsistent(g, start, path, goal);
        ++found;
      }
    }
    CPPUNIT_ASSERT(found > 1000 && unreachable > 100);  // both outcomes well exercised
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgPathSearchTest);
