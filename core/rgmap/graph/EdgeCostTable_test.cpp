// Tests the learned edge costs (thesis 5.4): Euclidean start, running mean of traversals with time
// converted at the nominal speed, door offsets added and taken back but never below the lower
// bound, the raised lower bound for doors, restoring from a checkpoint and the typed errors.
#include "core/rgmap/graph/EdgeCostTable.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>

#include "core/common/Errors.h"

using rgnav::EdgeCostConfig;
using rgnav::EdgeCostTable;
using rgnav::EdgeKey;
using rgnav::EdgeKind;
using rgnav::GatewaySide;

namespace {

constexpr rgnav::GatewayId kFirst{1}, kThird{3}, kDoor{7};
const EdgeKey kRegionEdge = rgnav::edgeKey(EdgeKind::Region, {kThird, GatewaySide::B}, {kFirst, GatewaySide::A});
const EdgeKey kDoorEdge = rgnav::gatewayEdgeKey(kDoor);
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

EdgeCostConfig withMemory(std::size_t memory) {
  EdgeCostConfig c;
  c.traversalMemory = memory;
  return c;
}

}  // namespace

class EdgeCostTableTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(EdgeCostTableTest);
  CPPUNIT_TEST(keysAreOrdered);
  CPPUNIT_TEST(unmeasuredEdgeCostsItsLength);
  CPPUNIT_TEST(traversalsArePlainMeanThenExponential);
  CPPUNIT_TEST(slowTraversalCountsAtNominalSpeed);
  CPPUNIT_TEST(neverBelowEuclideanLength);
  CPPUNIT_TEST(doorBlockedThenOpen);
  CPPUNIT_TEST(doorOffsetAddsToMeasuredBase);
  CPPUNIT_TEST(doorExtraRaisesLowerBound);
  CPPUNIT_TEST(restoreFromCheckpoint);
  CPPUNIT_TEST(badConfigIsConfigError);
  CPPUNIT_TEST(badMeasurementIsInvalidArgument);
  CPPUNIT_TEST_SUITE_END();

 public:
  void keysAreOrdered() {
    CPPUNIT_ASSERT(kRegionEdge.a == (rgnav::NodeKey{kFirst, GatewaySide::A}));
    CPPUNIT_ASSERT(kRegionEdge == rgnav::edgeKey(EdgeKind::Region, {kFirst, GatewaySide::A}, {kThird, GatewaySide::B}));
    CPPUNIT_ASSERT(kDoorEdge != rgnav::edgeKey(EdgeKind::Region, {kDoor, GatewaySide::A}, {kDoor, GatewaySide::B}));
    CPPUNIT_ASSERT_EQUAL(std::string("region edge G1A-G3B"), rgnav::toString(kRegionEdge));
  }

  void unmeasuredEdgeCostsItsLength() {
    const EdgeCostTable t;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.2, t.cost(kRegionEdge, 4.2, false), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
  }

  void traversalsArePlainMeanThenExponential() {
    EdgeCostTable t(withMemory(2));
    t.recordTraversal(kRegionEdge, 10.0, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(10.0, t.cost(kRegionEdge, 5.0, false), 1e-12);
    t.recordTraversal(kRegionEdge, 20.0, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(15.0, t.cost(kRegionEdge, 5.0, false), 1e-12);
    t.recordTraversal(kRegionEdge, 40.0, 0.0);  // weight 1/2 from now on
    CPPUNIT_ASSERT_DOUBLES_EQUAL(27.5, t.cost(kRegionEdge, 5.0, false), 1e-12);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), t.traversals().at(kRegionEdge).count);
  }

  void slowTraversalCountsAtNominalSpeed() {
    EdgeCostTable t;  // 0.5 m/s
    t.recordTraversal(kRegionEdge, 10.0, 30.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(15.0, t.cost(kRegionEdge, 8.0, false), 1e-12);
    EdgeCostTable fast;
    fast.recordTraversal(kRegionEdge, 10.0, 12.0);  // faster than nominal: the length counts
    CPPUNIT_ASSERT_DOUBLES_EQUAL(10.0, fast.cost(kRegionEdge, 8.0, false), 1e-12);
  }

  void neverBelowEuclideanLength() {
    EdgeCostTable t;
    t.recordTraversal(kRegionEdge, 3.0, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(8.0, t.cost(kRegionEdge, 8.0, false), 1e-12);
    for (int i = 0; i < 5; ++i) t.recordDoorState(kDoor, true);
    t.recordTraversal(kDoorEdge, 0.2, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
  }

  void doorBlockedThenOpen() {
    EdgeCostTable t;  // +30 m blocked, -30 m open
    t.recordDoorState(kDoor, false);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(31.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
    t.recordDoorState(kDoor, false);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(61.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
    t.recordDoorState(kDoor, true);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(31.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
    t.recordDoorState(kDoor, true);
    t.recordDoorState(kDoor, true);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
    t.recordDoorState(kDoor, false);  // open twice more did not bank credit
    CPPUNIT_ASSERT_DOUBLES_EQUAL(31.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
    // The offset belongs to the door edge only.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, t.cost(kDoorEdge, 1.0, false), 1e-12);
  }

  void doorOffsetAddsToMeasuredBase() {
    EdgeCostTable t;
    t.recordTraversal(kDoorEdge, 1.5, 0.0);
    t.recordDoorState(kDoor, false);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(31.5, t.cost(kDoorEdge, 1.0, true), 1e-12);
    t.recordDoorState(kDoor, true);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.5, t.cost(kDoorEdge, 1.0, true), 1e-12);
  }

  void doorExtraRaisesLowerBound() {
    EdgeCostConfig c;
    c.doorExtraM = 2.0;
    EdgeCostTable t(c);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, t.cost(kDoorEdge, 1.0, false), 1e-12);
    t.recordTraversal(kDoorEdge, 4.0, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, t.cost(kDoorEdge, 1.0, true), 1e-12);
  }

  void restoreFromCheckpoint() {
    EdgeCostTable learned(withMemory(3));
    learned.recordTraversal(kRegionEdge, 6.0, 0.0);
    learned.recordTraversal(kRegionEdge, 7.0, 0.0);
    learned.recordDoorState(kDoor, false);
    EdgeCostTable restored(withMemory(3));
    for (const auto& [key, stats] : learned.traversals()) restored.restoreTraversal(key, stats);
    for (const auto& [g, offset] : learned.doorOffsets()) restored.restoreDoorOffset(g, offset);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(learned.cost(kRegionEdge, 5.0, false), restored.cost(kRegionEdge, 5.0, false), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(learned.cost(kDoorEdge, 1.0, true), restored.cost(kDoorEdge, 1.0, true), 1e-12);
    learned.recordTraversal(kRegionEdge, 9.5, 0.0);
    restored.recordTraversal(kRegionEdge, 9.5, 0.0);  // the count carried over: same weight
    CPPUNIT_ASSERT_DOUBLES_EQUAL(learned.cost(kRegionEdge, 5.0, false), restored.cost(kRegionEdge, 5.0, false), 1e-12);
    CPPUNIT_ASSERT_THROW(restored.restoreTraversal(kRegionEdge, {5.0, 0}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(restored.restoreTraversal(kRegionEdge, {-1.0, 2}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(restored.restoreDoorOffset(kDoor, -0.1), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(restored.restoreDoorOffset(kDoor, kNaN), rgnav::InvalidArgumentError);
  }

  void badConfigIsConfigError() {
    const auto bad = [](auto change) {
      EdgeCostConfig c;
      change(c);
      CPPUNIT_ASSERT_THROW(EdgeCostTable{c}, rgnav::ConfigError);
    };
    bad([](EdgeCostConfig& c) { c.nominalSpeedMps = 0.0; });
    bad([](EdgeCostConfig& c) { c.nominalSpeedMps = kNaN; });
    bad([](EdgeCostConfig& c) { c.traversalMemory = 0; });
    bad([](EdgeCostConfig& c) { c.doorBlockedM = 0.0; });
    bad([](EdgeCostConfig& c) { c.doorOpenM = 0.5; });
    bad([](EdgeCostConfig& c) { c.doorOpenM = -INFINITY; });
    bad([](EdgeCostConfig& c) { c.doorExtraM = -1.0; });
    EdgeCostConfig zeroOpen;
    zeroOpen.doorOpenM = 0.0;  // an open door that never lowers the cost is allowed
    rgnav::validate(zeroOpen);
  }

  void badMeasurementIsInvalidArgument() {
    EdgeCostTable t;
    CPPUNIT_ASSERT_THROW(t.recordTraversal(kRegionEdge, -1.0, 0.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(t.recordTraversal(kRegionEdge, kNaN, 0.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(t.recordTraversal(kRegionEdge, 1.0, -2.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(t.recordTraversal(kRegionEdge, 1.0, INFINITY), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(t.cost(kRegionEdge, kNaN, false), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT(t.traversals().empty());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(EdgeCostTableTest);
