// Tests the passage tracker: hypotheses of consecutive scans are associated by gateway-point
// distance (in either order), support counts scans, a gateway is confirmed at minSupport scans,
// unconfirmed tracks are forgotten, and a traversal is reported when the robot's path crosses a
// confirmed gateway, with its direction; a wider twin of a confirmed door (a shared gateway point,
// a similar direction) is superseded, whichever was confirmed first, and reports no traversal,
// while a different opening sharing the jamb (across it, or hardly wider) stays.
#include "core/gateways/passages/PassageTracker.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <vector>

#include "core/common/Errors.h"

using Eigen::Vector2d;
using rgnav::PassageHypothesis;
using rgnav::PassageTracker;
using rgnav::PassageTrackerConfig;
using rgnav::Pose2D;

namespace {

// A door at x = 2 from y = -0.45 (right) to 0.45 (left), as seen from the origin, shifted by
// `noise` metres.
PassageHypothesis door(rgnav::DataId scan, double noise = 0.0) {
  PassageHypothesis h;
  h.scanId = scan;
  h.left = Vector2d(2.0 + noise, 0.45 - noise);
  h.right = Vector2d(2.0 - noise, -0.45 + noise);
  h.widthM = (h.left - h.right).norm();
  h.confidence = 1.0;
  return h;
}

// A passage from the door's left jamb (2, 0.45) to a point `lengthM` away at `angleDeg` from the
// door's line, into the room beyond it (x > 2).
PassageHypothesis fromLeftJamb(rgnav::DataId scan, double lengthM, double angleDeg) {
  PassageHypothesis h = door(scan);
  const double a = angleDeg * M_PI / 180.0;
  h.right = h.left + lengthM * Vector2d(std::sin(a), -std::cos(a));
  h.widthM = lengthM;
  return h;
}

// The slanted line from the jamb to a cabinet's corner inside the room: twice the door's width.
PassageHypothesis twin(rgnav::DataId scan) { return fromLeftJamb(scan, 1.8, 30.0); }

// A robot step that crosses the twin's line and not the door's.
const Pose2D kBesideTwin{2.3, -1.2, 0.0}, kThroughTwin{2.8, -0.2, 0.0};

}  // namespace

class PassageTrackerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PassageTrackerTest);
  CPPUNIT_TEST(supportCountsScansUntilConfirmed);
  CPPUNIT_TEST(doorSeenFromTheOtherSideIsTheSameTrack);
  CPPUNIT_TEST(distantPassagesAreSeparateTracks);
  CPPUNIT_TEST(unconfirmedTracksAreForgotten);
  CPPUNIT_TEST(traversalsAreReportedWithTheirDirection);
  CPPUNIT_TEST(unconfirmedPassagesAreNotTraversed);
  CPPUNIT_TEST(twinConfirmedWithTheDoorIsNeverReported);
  CPPUNIT_TEST(twinConfirmedBeforeTheDoorIsSuperseded);
  CPPUNIT_TEST(twinCrossedAsTheDoorIsConfirmedIsNotTraversed);
  CPPUNIT_TEST(otherOpeningsAtTheJambStay);
  CPPUNIT_TEST(badConfigurationsAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void supportCountsScansUntilConfirmed() {
    PassageTracker tracker({0.3, 3, 50});
    CPPUNIT_ASSERT(tracker.update(1, {}, {door(1), door(1, 0.02)}).confirmed.empty());  // one scan, support 1
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), tracker.tracks().size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), tracker.tracks()[0].support);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), tracker.tracks()[0].observations);
    CPPUNIT_ASSERT(tracker.update(2, {}, {}).confirmed.empty());
    CPPUNIT_ASSERT(tracker.update(3, {}, {door(3, -0.02)}).confirmed.empty());
    CPPUNIT_ASSERT(tracker.gateways().empty());
    const auto update = tracker.update(4, {}, {door(4, 0.01)});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), update.confirmed.size());
    const auto gateways = tracker.gateways();
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), gateways.size());
    CPPUNIT_ASSERT_EQUAL(update.confirmed[0], gateways[0].id);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), gateways[0].support);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(1), gateways[0].firstScan);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(4), gateways[0].lastScan);
    CPPUNIT_ASSERT((gateways[0].midpoint() - Vector2d(2.0, 0.0)).norm() < 0.01);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.9, gateways[0].widthM(), 0.02);
    CPPUNIT_ASSERT(tracker.update(5, {}, {door(5)}).confirmed.empty());  // confirmed once
  }

  void doorSeenFromTheOtherSideIsTheSameTrack() {
    PassageTracker tracker({0.3, 2, 50});
    tracker.update(1, {}, {door(1)});
    PassageHypothesis behind = door(2, 0.05);
    std::swap(behind.left, behind.right);
    tracker.update(2, {4.0, 0.0, M_PI}, {behind});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), tracker.gateways().size());
    CPPUNIT_ASSERT((tracker.gateways()[0].left - Vector2d(2.0, 0.45)).norm() < 0.06);  // first view's order
  }

  void distantPassagesAreSeparateTracks() {
    PassageTracker tracker({0.3, 1, 50});
    PassageHypothesis next = door(1);
    next.left.y() += 2.0;
    next.right.y() += 2.0;
    const auto update = tracker.update(1, {}, {door(1), next});
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), update.confirmed.size());
    CPPUNIT_ASSERT(update.confirmed[0] != update.confirmed[1]);
  }

  void unconfirmedTracksAreForgotten() {
    PassageTracker tracker({0.3, 3, 5});
    tracker.update(1, {}, {door(1)});
    for (rgnav::DataId scan = 2; scan <= 5; ++scan) tracker.update(scan, {}, {});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), tracker.tracks().size());
    tracker.update(6, {}, {});
    CPPUNIT_ASSERT(tracker.tracks().empty());
  }

  void traversalsAreReportedWithTheirDirection() {
    PassageTracker tracker({0.3, 2, 50});
    tracker.update(1, {0.0, 0.0, 0.0}, {door(1)});
    CPPUNIT_ASSERT(tracker.update(2, {1.0, 0.0, 0.0}, {door(2)}).traversals.empty());
    CPPUNIT_ASSERT(tracker.update(3, {1.9, 0.2, 0.0}, {}).traversals.empty());  // not yet through
    const auto through = tracker.update(4, {2.3, 0.2, 0.0}, {});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), through.traversals.size());
    const rgnav::GatewayTraversal& t = through.traversals[0];
    CPPUNIT_ASSERT_EQUAL(tracker.gateways()[0].id, t.gateway);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId(4), t.scanId);
    CPPUNIT_ASSERT((t.crossing - Vector2d(2.0, 0.2)).norm() < 1e-9);
    CPPUNIT_ASSERT(t.fromObservedSide);
    CPPUNIT_ASSERT(tracker.update(5, {3.0, 1.0, 0.0}, {}).traversals.empty());  // beside the door
    const auto back = tracker.update(6, {1.0, -0.3, M_PI}, {});  // back through it
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), back.traversals.size());
    CPPUNIT_ASSERT(!back.traversals[0].fromObservedSide);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), tracker.gateways()[0].traversals);
    CPPUNIT_ASSERT(tracker.update(7, {2.5, 1.5, 0.0}, {}).traversals.empty());  // past the door's end
  }

  void unconfirmedPassagesAreNotTraversed() {
    PassageTracker tracker({0.3, 3, 50});
    tracker.update(1, {1.0, 0.0, 0.0}, {door(1)});
    CPPUNIT_ASSERT(tracker.update(2, {3.0, 0.0, 0.0}, {}).traversals.empty());
  }

  void twinConfirmedWithTheDoorIsNeverReported() {
    PassageTracker tracker({0.3, 2, 50});
    tracker.update(1, kBesideTwin, {door(1), twin(1)});
    const auto confirmed = tracker.update(2, kBesideTwin, {twin(2), door(2)});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), confirmed.confirmed.size());
    CPPUNIT_ASSERT(confirmed.superseded.empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), tracker.gateways().size());
    CPPUNIT_ASSERT_EQUAL(confirmed.confirmed[0], tracker.gateways()[0].id);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.9, tracker.gateways()[0].widthM(), 1e-9);
    CPPUNIT_ASSERT(tracker.update(3, kThroughTwin, {}).traversals.empty());
  }

  void twinConfirmedBeforeTheDoorIsSuperseded() {
    PassageTracker tracker({0.3, 2, 50});
    tracker.update(1, kBesideTwin, {twin(1)});
    const rgnav::PassageTrackId twinId = tracker.update(2, kBesideTwin, {twin(2)}).confirmed.at(0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), tracker.update(3, kThroughTwin, {}).traversals.size());
    tracker.update(4, kBesideTwin, {door(4)});
    const auto update = tracker.update(5, kBesideTwin, {door(5)});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), update.confirmed.size());
    CPPUNIT_ASSERT(update.confirmed[0] != twinId);
    CPPUNIT_ASSERT(update.superseded == std::vector<rgnav::PassageTrackId>{twinId});
    CPPUNIT_ASSERT(tracker.find(twinId)->superseded);
    CPPUNIT_ASSERT(tracker.update(6, kThroughTwin, {twin(6)}).traversals.empty());
    CPPUNIT_ASSERT(tracker.update(7, kBesideTwin, {twin(7), door(7)}).superseded.empty());  // once
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), tracker.gateways().size());
  }

  void twinCrossedAsTheDoorIsConfirmedIsNotTraversed() {
    PassageTracker tracker({0.3, 2, 50});
    tracker.update(1, kBesideTwin, {twin(1)});
    const rgnav::PassageTrackId twinId = tracker.update(2, kBesideTwin, {twin(2), door(2)}).confirmed.at(0);
    const auto update = tracker.update(3, kThroughTwin, {door(3)});  // crosses the twin as the door is confirmed
    CPPUNIT_ASSERT(update.superseded == std::vector<rgnav::PassageTrackId>{twinId});
    CPPUNIT_ASSERT(update.traversals.empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), tracker.find(twinId)->traversals);
  }

  void otherOpeningsAtTheJambStay() {
    PassageTracker tracker({0.3, 1, 50});
    const auto update = tracker.update(1, {}, {door(1), fromLeftJamb(1, 1.3, 100.0), fromLeftJamb(1, 1.0, 30.0)});
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), update.confirmed.size());  // across the jamb; only 11 % wider
    CPPUNIT_ASSERT(update.superseded.empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), tracker.gateways().size());
  }

  void badConfigurationsAreTypedErrors() {
    CPPUNIT_ASSERT_THROW(PassageTracker({0.0, 3, 50}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(PassageTracker({0.3, 0, 50}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(PassageTracker({0.3, 3, 0}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(PassageTracker({0.3, 3, 50, -0.1}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(PassageTracker({0.3, 3, 50, 0.25, 2.0}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(PassageTracker({0.3, 3, 50, 0.25, 1.0, 0.9}), rgnav::ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PassageTrackerTest);
