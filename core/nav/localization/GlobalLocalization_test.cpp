// Tests of global localization on the two-room map (testing/TwoRooms.h): the recognizer finds
// the room and the pose from scans whose odometry frame has nothing to do with the map's, the
// descriptor distance counts what a partial view cannot explain, and the localizer finds the
// robot from an unknown start, then notices when it is carried into the other room and finds it
// there.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/nav/localization/GlobalLocalizer.h"
#include "core/nav/localization/testing/TwoRooms.h"

using namespace rgnav;

namespace {

const Pose2D kOdometryFrame{40.0, -12.0, 2.1};  // where the odometry's origin lies in the map frame

bool near(const Pose2D& a, const Pose2D& b, double m, double rad) {
  return std::hypot(a.x - b.x, a.y - b.y) <= m && std::abs(normalizeAngle(a.theta - b.theta)) <= rad;
}

// The true pose on a circle of radius 1 m around a room's centre, `s` metres along it.
Pose2D onCircle(const Eigen::Vector2d& centre, double s) {
  const double a = s / 1.0;
  return {centre.x() + std::cos(a), centre.y() + std::sin(a), normalizeAngle(a + M_PI / 2.0)};
}

}  // namespace

class GlobalLocalizationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GlobalLocalizationTest);
  CPPUNIT_TEST(recognizesTheRoomAndThePose);
  CPPUNIT_TEST(descriptorCountsOnlyWhatAPartialViewCannotExplain);
  CPPUNIT_TEST(localizesFromAnUnknownStartAndAfterAKidnapping);
  CPPUNIT_TEST_SUITE_END();

 public:
  void recognizesTheRoomAndThePose() {
    const testing::TwoRooms rooms = testing::twoRooms();
    const MclConfig mcl;
    const LocalizationMap map = LocalizationMap::fromViews(rooms.regions, rooms.gateways, mcl.beam);
    const RegionRecognizer recognizer(RecognitionConfig{}, mcl.beam, map, rooms.regions, rooms.gateways);
    // Scans along 0.5 m in the right room, looking towards its west wall and the door.
    RecentScans recent;
    Pose2D truth{6.9, 3.2, 2.8};
    for (DataId id = 1; id <= 11; ++id, truth = compose(truth, Pose2D{0.05, 0.0, 0.02}))
      recent.add(testing::simulatedScan(rooms.walls, truth, compose(kOdometryFrame, truth), id));
    truth = compose(truth, Pose2D{-0.05, 0.0, -0.02});
    const std::vector<PoseCandidate> candidates = recognizer.recognize(recent.observation());
    CPPUNIT_ASSERT(!candidates.empty());
    CPPUNIT_ASSERT_EQUAL(RegionId{2}, candidates.front().region);
    CPPUNIT_ASSERT(near(candidates.front().mapPose, truth, 0.1, 3.0 * M_PI / 180.0));
    // A candidate's pose in its region's frame and in the map frame say the same.
    const Pose2D frame = rooms.regions[1].summary.frame;
    CPPUNIT_ASSERT(near(compose(frame, candidates.front().regionPose), candidates.front().mapPose, 1e-9, 1e-9));
  }

  void descriptorCountsOnlyWhatAPartialViewCannotExplain() {
    RegionDescriptor mapped;
    mapped.areaM2 = 20.0;
    mapped.neighbourAreaM2 = 10.0;
    mapped.majorSigmaM = 1.5;
    mapped.minorSigmaM = 1.0;
    RegionDescriptor glimpse;  // a small part: says nothing against the region
    glimpse.areaM2 = 2.0;
    glimpse.majorSigmaM = 0.4;
    glimpse.minorSigmaM = 0.3;
    RegionDescriptor tooLarge = mapped;  // more freespace than region and neighbours hold
    tooLarge.areaM2 = 60.0;
    RegionDescriptor wrongShape = mapped;  // the whole area, but a long corridor
    wrongShape.majorSigmaM = 4.0;
    wrongShape.minorSigmaM = 0.4;
    CPPUNIT_ASSERT(descriptorDistance(mapped, mapped) < 1e-9);
    CPPUNIT_ASSERT(descriptorDistance(glimpse, mapped) < 0.3);
    CPPUNIT_ASSERT(descriptorDistance(tooLarge, mapped) > 1.0);
    CPPUNIT_ASSERT(descriptorDistance(wrongShape, mapped) > 1.0);
  }

  void localizesFromAnUnknownStartAndAfterAKidnapping() {
    const testing::TwoRooms rooms = testing::twoRooms();
    const MclConfig mcl;
    const LocalizationMap map = LocalizationMap::fromViews(rooms.regions, rooms.gateways, mcl.beam);
    GlobalLocalizer localizer(GlobalLocalizerConfig{}, mcl, map, rooms.regions, rooms.gateways, 7);
    DataId id = 1;
    Pose2D odometry = kOdometryFrame;
    Pose2D previous = onCircle({2.0, 2.0}, 0.0);
    const auto drive = [&](const Eigen::Vector2d& centre, double fromS, double toS) {
      for (double s = fromS; s <= toS; s += 0.05) {
        const Pose2D truth = onCircle(centre, s);
        odometry = compose(odometry, between(previous, truth));
        previous = truth;
        localizer.update(testing::simulatedScan(rooms.walls, truth, odometry, id++));
      }
      return previous;
    };
    CPPUNIT_ASSERT(localizer.state() == LocalizerState::kSearching);
    Pose2D truth = drive({2.0, 2.0}, 0.0, 6.0);
    CPPUNIT_ASSERT(localizer.localized());
    CPPUNIT_ASSERT(near(localizer.estimate()->mapPose, truth, 0.15, 5.0 * M_PI / 180.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), localizer.kidnapsDetected());
    // Carried into the right room: the odometry does not notice.
    previous = onCircle({6.6, 2.6}, 0.0);
    truth = drive({6.6, 2.6}, 0.0, 8.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), localizer.kidnapsDetected());
    CPPUNIT_ASSERT(localizer.localized());
    CPPUNIT_ASSERT(near(localizer.estimate()->mapPose, truth, 0.15, 5.0 * M_PI / 180.0));
    CPPUNIT_ASSERT_EQUAL(RegionId{2}, localizer.estimate()->region);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(GlobalLocalizationTest);
