// Tests the GatewayDetection module's core: a robot driving through a door reports the narrow
// passage once, then its traversal from the side it was seen from; a robot turning left at a
// hallway turn reports an L-Turn area (the trained HMMs of config/gateways) and its traversal
// from the entrance to the left side; a detector resumed from a serialized checkpoint goes on
// with exactly the events of one that never stopped, also through a hallway gateway, and a
// checkpoint keeps how far a running hallway sequence has coasted; an area made while the robot
// is inside it knows the robot's entry side only from a sequence that ended with the robot
// entering; scans out of order and damaged checkpoints are typed errors.
#include "core/gateways/detection/GatewayDetector.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cstdlib>
#include <string>

#include "core/common/Errors.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "core/gateways/detection/DetectionStateCodec.h"
#include "core/gateways/detection/HallwayAreaTracker.h"
#include "core/gateways/vlm/ObservationVector.h"
#include "core/gateways/vlm/testing/JunctionScan.h"
#include "core/lines/testing/SyntheticScan.h"

using Eigen::Vector2d;
using namespace rgnav;
using rgnav::testing::syntheticScan;
using rgnav::testing::Wall;

namespace {

// A hallway along x (y = ±1.5) ending in a wall at x = 2 with a 0.9 m door into a 4 x 4 m room.
std::vector<Wall> hallwayWithDoor() {
  return {{{-4, -1.5}, {2, -1.5}}, {{-4, 1.5}, {2, 1.5}}, {{2, -1.5}, {2, -0.45}}, {{2, 0.45}, {2, 1.5}},
          {{2, -2}, {6, -2}},      {{2, 2}, {6, 2}},      {{6, -2}, {6, 2}},        {{2, -2}, {2, -1.5}},
          {{2, 1.5}, {2, 2}},      {{-4, -1.5}, {-4, 1.5}}};
}

// The robot's poses from x = -2 through the door to x = 4, 5 cm apart.
std::vector<Pose2D> throughTheDoor() {
  std::vector<Pose2D> poses;
  for (int i = 0; i <= 120; ++i) poses.push_back({-2.0 + 0.05 * i, 0.0, 0.0});
  return poses;
}

LaserScan scanAt(const Pose2D& pose, DataId id) {
  LaserScan scan = syntheticScan(hallwayWithDoor(), pose);
  scan.id = id;
  return scan;
}


// Along the hallway of an L-turn (x = -6 ... 0) and out of its left leg (y = 0 ... 4), 5 cm apart.
std::vector<Pose2D> throughTheLeftTurn() {
  std::vector<Pose2D> path;
  for (int i = 0; i <= 120; ++i) path.push_back({-6.0 + 0.05 * i, 0.0, 0.0});
  for (int i = 1; i <= 80; ++i) path.push_back({0.0, 0.05 * i, M_PI / 2});
  return path;
}

LaserScan leftTurnScanAt(const Pose2D& pose, DataId id) {
  LaserScan scan = rgnav::testing::junctionScan(GatewayClass::LTurn, 2.0, pose);
  scan.id = id;
  return scan;
}

// The events of poses[from, to), the scan of pose i made by `scanOf` with ID i + 1.
using ScanMaker = LaserScan (*)(const Pose2D&, DataId);
std::vector<GatewayEvent> drive(GatewayDetector& detector, const std::vector<Pose2D>& poses, std::size_t from,
                                std::size_t to, ScanMaker scanOf = scanAt) {
  std::vector<GatewayEvent> events;
  for (std::size_t i = from; i < to; ++i)
    for (GatewayEvent& e : detector.addScan(scanOf(poses[i], i + 1), poses[i])) events.push_back(std::move(e));
  return events;
}

HmmClassifier trainedModels() {
  const char* root = std::getenv("RGNAV_ROOT");
  CPPUNIT_ASSERT_MESSAGE("RGNAV_ROOT must name the source tree", root != nullptr);
  return loadHmmModels(std::string(root) + "/config/gateways/gateway-hmms.txt");
}

}  // namespace

class GatewayDetectorTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GatewayDetectorTest);
  CPPUNIT_TEST(doorIsReportedOnceThenTraversed);
  CPPUNIT_TEST(leftTurnIsClassifiedAndTraversed);
  CPPUNIT_TEST(resumedDetectorContinuesExactly);
  CPPUNIT_TEST(resumedDetectorContinuesThroughAHallwayGateway);
  CPPUNIT_TEST(onlyAnEnteredSequenceGivesTheEntrySide);
  CPPUNIT_TEST(checkpointKeepsCoasting);
  CPPUNIT_TEST(scansOutOfOrderAreRejected);
  CPPUNIT_TEST(damagedCheckpointIsAFormatError);
  CPPUNIT_TEST(versionTwoCheckpointReads);
  CPPUNIT_TEST_SUITE_END();

 public:
  void doorIsReportedOnceThenTraversed() {
    GatewayDetector detector({}, std::nullopt);
    const std::vector<GatewayEvent> events = drive(detector, throughTheDoor(), 0, throughTheDoor().size());
    std::size_t detected = 0, traversed = 0;
    for (const GatewayEvent& e : events) {
      CPPUNIT_ASSERT(e.gateway.kind == GatewayKind::NarrowPassage);
      CPPUNIT_ASSERT_EQUAL(DetectorGatewayId(1), e.gateway.id);
      if (e.kind == GatewayEventKind::Detected) {
        ++detected;
        CPPUNIT_ASSERT_EQUAL(std::string(kNarrowPassageClass), e.gateway.label());
        CPPUNIT_ASSERT_DOUBLES_EQUAL(0.9, e.gateway.widthM, 0.05);
        // Crossing point 0 lies on the side it was seen from: the hallway.
        CPPUNIT_ASSERT(e.gateway.crossingPoints[0].x() < 2.0 && e.gateway.crossingPoints[1].x() > 2.0);
      } else if (e.kind == GatewayEventKind::Traversed) {
        ++traversed;
        CPPUNIT_ASSERT(detected == 1);
        CPPUNIT_ASSERT_EQUAL(std::size_t(0), e.traversal.fromSide);
        CPPUNIT_ASSERT_EQUAL(std::size_t(1), e.traversal.toSide);
        CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, e.traversal.at.x(), 0.06);
        CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, e.traversal.direction.x(), 0.01);
      }
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), detected);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), traversed);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), detector.gateways().size());
    for (std::size_t i = 1; i < events.size(); ++i) CPPUNIT_ASSERT_EQUAL(events[i - 1].id + 1, events[i].id);
  }

  void leftTurnIsClassifiedAndTraversed() {
    GatewayDetector detector({}, trainedModels());
    const std::vector<Pose2D> path = throughTheLeftTurn();
    const std::vector<GatewayEvent> events = drive(detector, path, 0, path.size(), leftTurnScanAt);
    const std::vector<GatewayRecord> gateways = detector.gateways();
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), gateways.size());
    CPPUNIT_ASSERT(gateways[0].kind == GatewayKind::HallwayArea);
    CPPUNIT_ASSERT_EQUAL(std::string("L-Turn"), gateways[0].label());
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), gateways[0].crossingPoints.size());
    std::size_t traversed = 0;
    for (const GatewayEvent& e : events) {
      if (e.kind != GatewayEventKind::Traversed) continue;
      ++traversed;
      CPPUNIT_ASSERT_EQUAL(std::size_t(0), e.traversal.fromSide);  // the entrance
      CPPUNIT_ASSERT_EQUAL(std::size_t(1), e.traversal.toSide);    // the left side
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), traversed);
  }

  void resumedDetectorContinuesExactly() {
    const std::vector<Pose2D> poses = throughTheDoor();
    GatewayDetector whole({}, std::nullopt);
    const std::vector<GatewayEvent> expected = drive(whole, poses, 0, poses.size());
    for (const std::size_t stop : {std::size_t(10), std::size_t(60), std::size_t(80)}) {
      GatewayDetector first({}, std::nullopt);
      std::vector<GatewayEvent> events = drive(first, poses, 0, stop);
      const DetectionCheckpoint saved = deserializeDetection(serializeDetection({first.state(), events}));
      CPPUNIT_ASSERT(saved.events == events);
      GatewayDetector resumed({}, std::nullopt, saved.detector);
      CPPUNIT_ASSERT_EQUAL(DataId(stop), resumed.lastScan());
      for (GatewayEvent& e : drive(resumed, poses, stop, poses.size())) events.push_back(std::move(e));
      CPPUNIT_ASSERT(events == expected);
    }
  }

  // Through the L-turn the hallway sequence coasts near the gateway; a detector stopped there (or
  // while the robot is inside the area) and resumed from its checkpoint reports the same events.
  void resumedDetectorContinuesThroughAHallwayGateway() {
    const HmmClassifier models = trainedModels();
    const std::vector<Pose2D> path = throughTheLeftTurn();
    GatewayDetector whole({}, models);
    std::vector<GatewayEvent> expected;
    std::size_t coastedScans = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
      for (GatewayEvent& e : drive(whole, path, i, i + 1, leftTurnScanAt)) expected.push_back(std::move(e));
      for (const RunningSequence& r : whole.state().sequences.running) coastedScans += r.coasted > 0 ? 1 : 0;
    }
    CPPUNIT_ASSERT(coastedScans > 0);
    CPPUNIT_ASSERT(!expected.empty());
    for (const std::size_t stop : {std::size_t(100), std::size_t(115), std::size_t(125)}) {
      GatewayDetector first({}, models);
      std::vector<GatewayEvent> events = drive(first, path, 0, stop, leftTurnScanAt);
      const DetectionCheckpoint saved = deserializeDetection(serializeDetection({first.state(), events}));
      GatewayDetector resumed({}, models, saved.detector);
      for (GatewayEvent& e : drive(resumed, path, stop, path.size(), leftTurnScanAt)) events.push_back(std::move(e));
      CPPUNIT_ASSERT(events == expected);
    }
  }

  // An area made by a lost sequence while the robot stands in it does not know where the robot
  // came in, so leaving it is no traversal; made by a sequence that ended with the robot
  // entering, it is (from the side the sequence saw it from).
  void onlyAnEnteredSequenceGivesTheEntrySide() {
    const HmmClassifier models = trainedModels();
    HypothesisTracker sequences;
    const VlmObserver observer;
    std::optional<TrackedSequence> entered;
    Pose2D enteredAt;
    for (const Pose2D& pose : throughTheLeftTurn()) {
      const LaserScan scan = leftTurnScanAt(pose, 1);
      sequences.update(pose, observer.observe(scan), [&](const GatewayPoints& p) { return observer.observeAt(p, scan); });
      for (TrackedSequence& s : sequences.takeFinished())
        if (s.end == SequenceEnd::Entered && (!entered || s.observations.size() > entered->observations.size())) {
          entered = std::move(s);
          enteredAt = pose;
        }
    }
    CPPUNIT_ASSERT(entered);
    for (const SequenceEnd end : {SequenceEnd::Entered, SequenceEnd::Lost}) {
      TrackedSequence sequence = *entered;
      sequence.end = end;
      HallwayAreaTracker areas({}, models);
      areas.move({enteredAt.x, enteredAt.y});
      const std::optional<std::size_t> area = areas.addSequence(sequence, 1, enteredAt);
      CPPUNIT_ASSERT(area && areas.isGateway(*area));
      const std::vector<AreaPassing> passings = areas.move({0.0, 3.0});
      CPPUNIT_ASSERT_EQUAL(end == SequenceEnd::Entered ? std::size_t(1) : std::size_t(0), passings.size());
      if (!passings.empty()) CPPUNIT_ASSERT_EQUAL(std::size_t(0), passings[0].fromSide);
    }
  }

  void checkpointKeepsCoasting() {
    GatewayDetectorState state;
    RunningSequence running;
    running.sequence.id = 7;
    running.sequence.gatewayPoints = squareGatewayArea(2.0);
    running.sequence.distances = {3.0, 2.8};
    running.sequence.observations = {std::vector<double>(kObservationSize, 0.5),
                                     std::vector<double>(kObservationSize, 0.25)};
    running.missed = 1;
    running.coasted = 1;
    state.sequences.running.push_back(running);
    const DetectionCheckpoint saved = deserializeDetection(serializeDetection({state, {}}));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), saved.detector.sequences.running.size());
    const RunningSequence& back = saved.detector.sequences.running[0];
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(7), back.sequence.id);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), back.missed);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), back.coasted);
    CPPUNIT_ASSERT(back.sequence.distances == running.sequence.distances);
    CPPUNIT_ASSERT(back.sequence.observations == running.sequence.observations);
  }

  void scansOutOfOrderAreRejected() {
    GatewayDetector detector({}, std::nullopt);
    detector.addScan(scanAt({}, 5), {});
    CPPUNIT_ASSERT_THROW(detector.addScan(scanAt({}, 5), {}), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(detector.addScan(scanAt({}, 4), {}), InvalidArgumentError);
  }

  void damagedCheckpointIsAFormatError() {
    GatewayDetector detector({}, std::nullopt);
    const std::string good = serializeDetection({detector.state(), {}});
    CPPUNIT_ASSERT_THROW(deserializeDetection(good.substr(0, good.size() / 2)), FormatError);
    CPPUNIT_ASSERT_THROW(deserializeDetection("{\"format\": \"something else\"}"), FormatError);
    std::string otherVersion = good;
    otherVersion.replace(otherVersion.find("\"version\":3"), 11, "\"version\":9");
    CPPUNIT_ASSERT_THROW(deserializeDetection(otherVersion), FormatError);
  }

  void versionTwoCheckpointReads() {
    GatewayDetector detector({}, std::nullopt);
    drive(detector, throughTheDoor(), 0, throughTheDoor().size());
    std::string text = serializeDetection({detector.state(), {}});
    CPPUNIT_ASSERT(text.find("\"superseded\":false") != std::string::npos);
    for (std::size_t at = text.find(",\"superseded\":false"); at != std::string::npos;
         at = text.find(",\"superseded\":false"))
      text.erase(at, std::string(",\"superseded\":false").size());
    text.replace(text.find("\"version\":3"), 11, "\"version\":2");
    CPPUNIT_ASSERT_EQUAL(serializeDetection({detector.state(), {}}), serializeDetection(deserializeDetection(text)));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(GatewayDetectorTest);
