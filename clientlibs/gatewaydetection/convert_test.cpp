// Round trips of the GatewayDetection.idl conversions: a batch with a detected narrow passage,
// an updated hallway area and a traversal, every field set.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/gatewaydetection/convert.h"

using namespace rgnav;

class GatewayDetectionConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GatewayDetectionConvertTest);
  CPPUNIT_TEST(batchRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void batchRoundTrip() {
    GatewayRecord door;
    door.id = DetectorGatewayId(3);
    door.kind = GatewayKind::NarrowPassage;
    door.classes = {{kNarrowPassageClass, 0.8}};
    door.gatewayPoints = {{1.0, 2.0}, {1.0, 1.1}};
    door.crossingPoints = {{0.5, 1.55}, {1.5, 1.55}};
    door.widthM = 0.9;
    door.firstScan = 10;
    door.lastScan = 40;
    door.lastPose = {0.2, 1.5, 0.1};
    door.support = 25;
    door.traversals = 1;
    GatewayRecord crossing = door;
    crossing.id = DetectorGatewayId(4);
    crossing.kind = GatewayKind::HallwayArea;
    crossing.classes = {{"X-Crossing", 0.7}, {"T-Junction", 0.2}, {"Hallway", 0.1}};
    crossing.gatewayPoints = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};
    crossing.crossingPoints = {{-1.5, 0}, {0, 1.5}, {1.5, 0}, {0, -1.5}};
    GatewayEventBatch batch;
    batch.events = {GatewayEvent{7, GatewayEventKind::Detected, door, {}, 40},
                    GatewayEvent{8, GatewayEventKind::Updated, crossing, {}, 40},
                    GatewayEvent{9, GatewayEventKind::Traversed, door, {41, 1, 0, {1.0, 1.5}, {-1.0, 0.0}}, 41}};
    batch.latestId = 12;
    batch.lastScan = 44;
    batch.endOfData = true;
    const GatewayEventBatch back = fromIdl(toIdl(batch));
    CPPUNIT_ASSERT(back.events == batch.events);
    CPPUNIT_ASSERT_EQUAL(batch.latestId, back.latestId);
    CPPUNIT_ASSERT_EQUAL(batch.lastScan, back.lastScan);
    CPPUNIT_ASSERT(back.endOfData);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(GatewayDetectionConvertTest);
