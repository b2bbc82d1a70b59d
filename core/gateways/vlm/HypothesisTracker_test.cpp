// Tests the tracking of VLM hypotheses into observation sequences (thesis 4.1.2.3): on an
// approach to a junction the true gateway gives a sequence over the whole approach that starts
// below the start distance, has decreasing distances and ends when the robot enters the gateway; a hypothesis
// that is no longer seen is lost after the allowed missed scans, or first coasts (is observed at
// its last gateway points) for the allowed scans once it has enough detections, but only while
// the gateway is in the scan's view and within the start distance; a sequence the robot has
// entered ends as entered even without a hypothesis; flush ends the rest. (From
// afar the hidden line jumps with the beam that last hits a corner, so short duplicate
// sequences of the same gateway can occur; the tests look at the longest one.)
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/gateways/vlm/HypothesisTracker.h"
#include "core/gateways/vlm/ObservationVector.h"
#include "core/gateways/vlm/testing/JunctionScan.h"

using rgnav::GatewayClass;
using rgnav::TrackedSequence;

namespace {

// Drives along y = 0.1 from x = `from` to `to` in 0.2 m steps, turned slightly, feeding every scan.
void approach(rgnav::HypothesisTracker& tracker, GatewayClass c, double from, double to) {
  const rgnav::VlmObserver observer;
  unsigned seed = 1;
  for (double x = from; x <= to + 1e-9; x += 0.2) {
    const rgnav::Pose2D pose{x, 0.1, -0.03};
    tracker.update(pose, observer.observe(rgnav::testing::junctionScan(c, 2.0, pose, 0.01, seed++)));
  }
}

// The running sequence of the true gateway.
const rgnav::RunningSequence* runningTrueGateway(const rgnav::HypothesisTracker& tracker) {
  for (const rgnav::RunningSequence& r : tracker.state().running)
    if (rgnav::largestPointDistance(r.sequence.gatewayPoints, rgnav::squareGatewayArea(2.0)) < 0.3) return &r;
  return nullptr;
}

// A tracker, lost after 2 missed scans, that has followed a T-junction from x = -6 to -4.
rgnav::HypothesisTracker afterTJunctionApproach(rgnav::TrackerParams params) {
  params.maxMissedScans = 2;
  rgnav::HypothesisTracker tracker(params);
  approach(tracker, GatewayClass::TJunction, -6.0, -4.0);
  return tracker;
}

// Scans at x = -3.8, -3.6, ... (or from `x`, heading `heading`) of the T-junction without
// hypotheses: only coasting observes.
class UndetectedScans {
 public:
  explicit UndetectedScans(rgnav::HypothesisTracker& tracker, double x = -3.8, double heading = 0.0)
      : tracker_(tracker), x_(x), heading_(heading) {}
  void next() {
    const rgnav::Pose2D pose{x_, 0.1, heading_};
    const rgnav::LaserScan scan = rgnav::testing::junctionScan(GatewayClass::TJunction, 2.0, pose, 0.01, 7);
    tracker_.update(pose, {}, [&](const rgnav::GatewayPoints& points) { return observer_.observeAt(points, scan); });
    x_ += 0.2;
  }

 private:
  rgnav::HypothesisTracker& tracker_;
  const rgnav::VlmObserver observer_;
  double x_;
  double heading_;
};

std::vector<TrackedSequence> ofTrueGateway(const std::vector<TrackedSequence>& all) {
  std::vector<TrackedSequence> out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out), [](const TrackedSequence& s) {
    return rgnav::largestPointDistance(s.gatewayPoints, rgnav::squareGatewayArea(2.0)) < 0.3;
  });
  std::stable_sort(out.begin(), out.end(), [](const TrackedSequence& a, const TrackedSequence& b) {
    return a.distances.size() > b.distances.size();
  });
  return out;
}

// Three undetected scans from `x` with `heading` on (UndetectedScans): the true gateway's
// sequence is lost then, with its detections and no coasted observation.
void expectLostWithDetectionsOnly(rgnav::HypothesisTracker tracker, double x = -3.8, double heading = 0.0) {
  const std::size_t detected = runningTrueGateway(tracker)->sequence.observations.size();
  UndetectedScans scans(tracker, x, heading);
  for (int i = 0; i < 3; ++i) scans.next();
  CPPUNIT_ASSERT(!runningTrueGateway(tracker));
  const auto lost = ofTrueGateway(tracker.takeFinished());
  CPPUNIT_ASSERT(!lost.empty());
  CPPUNIT_ASSERT_EQUAL(detected, lost.front().observations.size());
}

}  // namespace

class HypothesisTrackerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HypothesisTrackerTest);
  CPPUNIT_TEST(approachGivesALongDecreasingSequence);
  CPPUNIT_TEST(lostAfterMissedScans);
  CPPUNIT_TEST(undetectedSequenceCoastsThenIsLost);
  CPPUNIT_TEST(fewDetectionsDoNotCoast);
  CPPUNIT_TEST(noCoastingOutOfViewOrBeyondStartDistance);
  CPPUNIT_TEST(unmatchedPastTheEntranceIsEntered);
  CPPUNIT_TEST(flushEndsRunningSequences);
  CPPUNIT_TEST(badParametersAreRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  // In an X-crossing the walls beyond the crossing keep the VLM in view until the robot enters.
  void approachGivesALongDecreasingSequence() {
    rgnav::HypothesisTracker tracker;
    approach(tracker, GatewayClass::XCrossing, -8.0, -0.4);
    const std::vector<TrackedSequence> finished = tracker.takeFinished();
    tracker.flush();
    std::vector<TrackedSequence> all = finished;
    for (TrackedSequence& s : tracker.takeFinished()) all.push_back(std::move(s));
    const auto truth = ofTrueGateway(all);
    CPPUNIT_ASSERT(!truth.empty());
    const TrackedSequence& s = truth.front();
    CPPUNIT_ASSERT(s.end == rgnav::SequenceEnd::Entered);
    CPPUNIT_ASSERT(s.distances.size() >= 25);  // 6.8 m ... 1.0 m in 0.2 m steps: 30 scans
    CPPUNIT_ASSERT(rgnav::largestPointDistance(s.gatewayPoints, rgnav::squareGatewayArea(2.0)) < 0.05);
    CPPUNIT_ASSERT_EQUAL(s.distances.size(), s.observations.size());
    CPPUNIT_ASSERT(s.distances.front() <= 7.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, s.distances.back(), 0.1);  // last seen at the entrance
    for (std::size_t i = 1; i < s.distances.size(); ++i) CPPUNIT_ASSERT(s.distances[i] < s.distances[i - 1]);
    for (const auto& o : s.observations) CPPUNIT_ASSERT_EQUAL(rgnav::kObservationSize, o.size());
    for (const TrackedSequence& any : all) CPPUNIT_ASSERT(any.distances.front() <= 7.0);
  }

  void lostAfterMissedScans() {
    rgnav::TrackerParams params;
    params.maxMissedScans = 2;
    rgnav::HypothesisTracker tracker(params);
    approach(tracker, GatewayClass::TJunction, -6.0, -3.0);
    tracker.takeFinished();
    const std::size_t running = tracker.runningCount();
    CPPUNIT_ASSERT(running >= 1);
    tracker.update({-2.8, 0.1, 0.0}, {});
    tracker.update({-2.6, 0.1, 0.0}, {});
    CPPUNIT_ASSERT(tracker.takeFinished().empty());
    CPPUNIT_ASSERT_EQUAL(running, tracker.runningCount());
    tracker.update({-2.4, 0.1, 0.0}, {});
    const auto lost = tracker.takeFinished();
    CPPUNIT_ASSERT_EQUAL(running, lost.size());
    for (const TrackedSequence& s : lost) CPPUNIT_ASSERT(s.end == rgnav::SequenceEnd::Lost);
    const auto truth = ofTrueGateway(lost);
    CPPUNIT_ASSERT(!truth.empty());
    CPPUNIT_ASSERT(truth.front().distances.size() >= 14);  // x = -6.0 ... -3.0: 16 scans
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, tracker.runningCount());
  }

  void undetectedSequenceCoastsThenIsLost() {
    rgnav::TrackerParams params;
    params.maxCoastedScans = 4;
    rgnav::HypothesisTracker tracker = afterTJunctionApproach(params);
    const rgnav::RunningSequence* before = runningTrueGateway(tracker);
    CPPUNIT_ASSERT(before && before->sequence.observations.size() >= params.minDetectionsToCoast);
    const std::uint64_t id = before->sequence.id;
    const std::size_t detected = before->sequence.observations.size();
    const double lastDistance = before->sequence.distances.back();
    UndetectedScans scans(tracker);
    for (std::size_t i = 1; i <= params.maxCoastedScans; ++i) {
      scans.next();
      const rgnav::RunningSequence* r = runningTrueGateway(tracker);
      CPPUNIT_ASSERT(r && r->sequence.id == id);
      CPPUNIT_ASSERT_EQUAL(i, r->coasted);
      CPPUNIT_ASSERT_EQUAL(detected + i, r->sequence.observations.size());
      CPPUNIT_ASSERT_EQUAL(r->sequence.observations.size(), r->sequence.distances.size());
    }
    const auto& coasted = runningTrueGateway(tracker)->sequence.distances;
    CPPUNIT_ASSERT(coasted[detected] < lastDistance);
    for (std::size_t i = detected + 1; i < coasted.size(); ++i) CPPUNIT_ASSERT(coasted[i] < coasted[i - 1]);
    scans.next();
    scans.next();
    CPPUNIT_ASSERT(runningTrueGateway(tracker));
    scans.next();
    CPPUNIT_ASSERT(!runningTrueGateway(tracker));
    const auto lost = ofTrueGateway(tracker.takeFinished());
    CPPUNIT_ASSERT(!lost.empty() && lost.front().id == id);
    CPPUNIT_ASSERT(lost.front().end == rgnav::SequenceEnd::Lost);
    CPPUNIT_ASSERT_EQUAL(detected + params.maxCoastedScans, lost.front().observations.size());
  }

  void fewDetectionsDoNotCoast() {
    rgnav::TrackerParams params;
    params.minDetectionsToCoast = 1000;
    expectLostWithDetectionsOnly(afterTJunctionApproach(params));
  }

  // Turned away from the junction, the scan cannot see it; 8 m back, it is beyond the start
  // distance. Either way the sequence is lost with its detections only.
  void noCoastingOutOfViewOrBeyondStartDistance() {
    expectLostWithDetectionsOnly(afterTJunctionApproach({}), -3.8, M_PI);
    expectLostWithDetectionsOnly(afterTJunctionApproach({}), -8.0, 0.0);
  }

  // A sequence that may not coast still ends as entered when the robot is past its entrance,
  // in the first scan, without any hypothesis.
  void unmatchedPastTheEntranceIsEntered() {
    rgnav::TrackerParams params;
    params.minDetectionsToCoast = 1000;
    rgnav::HypothesisTracker tracker = afterTJunctionApproach(params);
    const std::uint64_t id = runningTrueGateway(tracker)->sequence.id;
    tracker.takeFinished();
    tracker.update({0.0, 0.1, 0.0}, {});
    const auto finished = ofTrueGateway(tracker.takeFinished());
    CPPUNIT_ASSERT(!finished.empty() && finished.front().id == id);
    CPPUNIT_ASSERT(finished.front().end == rgnav::SequenceEnd::Entered);
  }

  void flushEndsRunningSequences() {
    rgnav::HypothesisTracker tracker;
    approach(tracker, GatewayClass::LTurn, -5.0, -4.0);
    const std::size_t running = tracker.runningCount();
    CPPUNIT_ASSERT(running >= 1);
    tracker.flush();
    const auto flushed = tracker.takeFinished();
    CPPUNIT_ASSERT_EQUAL(running, flushed.size());
    for (const TrackedSequence& s : flushed) CPPUNIT_ASSERT(s.end == rgnav::SequenceEnd::Flushed);
    CPPUNIT_ASSERT(tracker.takeFinished().empty());
  }

  void badParametersAreRejected() {
    rgnav::TrackerParams p;
    p.matchToleranceM = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::HypothesisTracker{p}, rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(HypothesisTrackerTest);
