// Tests the observation vector of a VLM hypothesis: the class weights first, unchanged, then
// W_d, W_r, the on-line and the over-line measures per sector (left, front, right); a weight
// vector of the wrong size is rejected; the observer fills it for every hypothesis; observing a
// hypothesis again at its own gateway points (VlmObserver::observeAt, the tracker's coasting)
// gives the same observation, and coinciding points or a VLM out of the scan's view give none.
#include "core/gateways/vlm/ObservationVector.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/gateways/vlm/VlmObserver.h"
#include "core/gateways/vlm/testing/JunctionScan.h"

class ObservationVectorTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ObservationVectorTest);
  CPPUNIT_TEST(weightsThenMeasures);
  CPPUNIT_TEST(rejectsAWrongWeightCount);
  CPPUNIT_TEST(observerFillsTheVector);
  CPPUNIT_TEST(observingAtTheGatewayPointsRepeatsTheObservation);
  CPPUNIT_TEST(coincidingGatewayPointsGiveNoObservation);
  CPPUNIT_TEST(aVlmOutOfViewGivesNoObservation);
  CPPUNIT_TEST_SUITE_END();

 public:
  void weightsThenMeasures() {
    rgnav::SectorFreespace fsm;
    fsm.onLine = {0.2, 0.9, 1.0};
    fsm.overLine = {0.7, 0.1, 0.0};
    const std::vector<double> weights{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8};
    const std::vector<double> v = rgnav::observationVector(weights, 0.8, 0.9, fsm);
    CPPUNIT_ASSERT_EQUAL(rgnav::kObservationSize, v.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{16}, v.size());
    const std::vector<double> expected{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.8, 0.9, 0.2, 0.9, 1.0, 0.7, 0.1, 0.0};
    CPPUNIT_ASSERT(v == expected);
  }

  void rejectsAWrongWeightCount() {
    CPPUNIT_ASSERT_THROW(rgnav::observationVector({0.1, 0.2}, 0.8, 0.9, {}), rgnav::InvalidArgumentError);
  }

  void observerFillsTheVector() {
    const rgnav::Pose2D pose{-2.5, 0.1, 0.0};
    const rgnav::VlmObserver observer;
    const auto observations =
        observer.observe(rgnav::testing::junctionScan(rgnav::GatewayClass::TJunction, 2.0, pose, 0.01, 3));
    CPPUNIT_ASSERT(!observations.empty());
    for (const rgnav::VlmObservation& o : observations) {
      CPPUNIT_ASSERT(o.observation ==
                     rgnav::observationVector(o.weights, o.distanceMeasure, o.rectangularityMeasure, o.freespace));
    }
  }

  // The lines of a detected hypothesis run through its gateway points, so the lines observeAt
  // draws through them are the same lines (up to rounding), and so are all measures.
  void observingAtTheGatewayPointsRepeatsTheObservation() {
    const rgnav::Pose2D pose{-3.0, 0.2, 0.05};
    const rgnav::VlmObserver observer;
    const rgnav::LaserScan scan = rgnav::testing::junctionScan(rgnav::GatewayClass::LTJunction, 2.0, pose, 0.01, 5);
    const auto observations = observer.observe(scan);
    CPPUNIT_ASSERT(!observations.empty());
    for (const rgnav::VlmObservation& o : observations) {
      const auto again = observer.observeAt(o.hypothesis.gatewayPoints, scan);
      CPPUNIT_ASSERT(again);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(o.distanceM, again->distanceM, 1e-12);
      CPPUNIT_ASSERT_EQUAL(o.observation.size(), again->observation.size());
      for (std::size_t i = 0; i < o.observation.size(); ++i)
        CPPUNIT_ASSERT_DOUBLES_EQUAL(o.observation[i], again->observation[i], 1e-6);
    }
  }

  void coincidingGatewayPointsGiveNoObservation() {
    const rgnav::VlmObserver observer;
    const rgnav::LaserScan scan = rgnav::testing::junctionScan(rgnav::GatewayClass::TJunction, 2.0, {-3.0, 0.0, 0.0});
    rgnav::GatewayPoints points = rgnav::transformed(rgnav::squareGatewayArea(2.0), rgnav::Pose2D{3.0, 0.0, 0.0});
    CPPUNIT_ASSERT(observer.observeAt(points, scan));
    points[rgnav::kFrontLeft] = points[rgnav::kHiddenLeft];
    CPPUNIT_ASSERT(!observer.observeAt(points, scan));
  }

  // Coasting must not invent observations of a VLM the scan cannot see: behind the sensor (out
  // of the field of view), beyond the maximum range, or straddling the edge of the view.
  void aVlmOutOfViewGivesNoObservation() {
    const rgnav::VlmObserver observer;
    const rgnav::LaserScan scan = rgnav::testing::junctionScan(rgnav::GatewayClass::TJunction, 2.0, {-3.0, 0.0, 0.0});
    const rgnav::GatewayPoints ahead = rgnav::transformed(rgnav::squareGatewayArea(2.0), rgnav::Pose2D{3.0, 0.0, 0.0});
    CPPUNIT_ASSERT(observer.observeAt(ahead, scan));
    CPPUNIT_ASSERT(!observer.observeAt(rgnav::transformed(ahead, rgnav::Pose2D{0.0, 0.0, M_PI}), scan));
    CPPUNIT_ASSERT(!observer.observeAt(rgnav::transformed(ahead, rgnav::Pose2D{0.0, 0.0, M_PI / 2}), scan));
    CPPUNIT_ASSERT(!observer.observeAt(rgnav::transformed(ahead, rgnav::Pose2D{scan.maxRange, 0.0, 0.0}), scan));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ObservationVectorTest);
