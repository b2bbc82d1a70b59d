// Tests the evaluation pieces: the Kümmerle et al. 2009 relative-pose error on hand-made
// relations, reading and stamp-matching of relations files, relations derived from a trajectory,
// and the seeded odometry noise.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <map>

#include "core/common/Errors.h"
#include "core/logs/LogTestFiles.h"
#include "core/slam/eval/OdometryNoise.h"
#include "core/slam/eval/Relations.h"
#include "core/slam/eval/RelativePoseMetric.h"

using rgnav::Pose2D;
using rgnav::ScanRelation;

class RelativePoseMetricTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RelativePoseMetricTest);
  CPPUNIT_TEST(perfectPosesScoreZero);
  CPPUNIT_TEST(knownErrorsGiveKnownMeanAndStd);
  CPPUNIT_TEST(errorIsMeasuredInTheRelationsFrame);
  CPPUNIT_TEST(relationsFileIsReadAndMatchedByStamp);
  CPPUNIT_TEST(malformedRelationsAreFormatErrors);
  CPPUNIT_TEST(derivedRelationsCoverPathAndRevisits);
  CPPUNIT_TEST(odometryNoiseIsSeeded);
  CPPUNIT_TEST_SUITE_END();

 public:
  void perfectPosesScoreZero() {
    const std::map<rgnav::DataId, Pose2D> poses{{1, {0, 0, 0}}, {2, {1, 0, 0.5}}, {3, {5, 5, -2}}};
    std::vector<ScanRelation> relations{{1, 2, rgnav::between(poses.at(1), poses.at(2))},
                                        {3, 1, rgnav::between(poses.at(3), poses.at(1))}};
    const auto e = rgnav::relativePoseError(relations, [&](rgnav::DataId id) { return poses.at(id); });
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, e.relations);
    CPPUNIT_ASSERT(e.translationMean < 1e-12 && e.rotationMean < 1e-12);
  }
  void knownErrorsGiveKnownMeanAndStd() {
    // Estimated displacements are 1 m along x; the references say 1.1 m (error 0.1) and
    // 1.3 m (error 0.3), and rotations 0.02 and 0 rad.
    const std::map<rgnav::DataId, Pose2D> poses{{1, {0, 0, 0}}, {2, {1, 0, 0}}, {3, {2, 0, 0}}};
    std::vector<ScanRelation> relations{{1, 2, {1.1, 0, 0.02}}, {2, 3, {1.3, 0, 0}}};
    const auto e = rgnav::relativePoseError(relations, [&](rgnav::DataId id) { return poses.at(id); });
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2, e.translationMean, 1e-3);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, e.translationStd, 1e-3);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.01, e.rotationMean, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.01, e.rotationStd, 1e-12);
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rgnav::relativePoseError({}, [](rgnav::DataId) { return Pose2D{}; }).relations);
  }
  void errorIsMeasuredInTheRelationsFrame() {
    // A whole trajectory rotated and shifted has no relative error.
    const Pose2D offset{3, -2, 1.2};
    const std::map<rgnav::DataId, Pose2D> truth{{1, {0, 0, 0}}, {2, {1, 1, 0.7}}};
    std::vector<ScanRelation> relations{{1, 2, rgnav::between(truth.at(1), truth.at(2))}};
    const auto e = rgnav::relativePoseError(relations, [&](rgnav::DataId id) { return rgnav::compose(offset, truth.at(id)); });
    CPPUNIT_ASSERT(e.translationMean < 1e-12 && e.rotationMean < 1e-12);
  }
  void relationsFileIsReadAndMatchedByStamp() {
    rgnav::testing::TempDir dir;
    rgnav::testing::writeFile(dir.file("r.relations"),
                              "# comment\n"
                              "100.0000 101.0005 0.5 0.1 0 0 0 0.2\n"
                              "\n"
                              "101.0005 105.0100 1.0 0 0 0 0 -0.1\n"  // 105.01: no scan within 2 ms
                              "102.0019 100.0 0.3 0 0 0 0 7.0\n");
    const auto relations = rgnav::readRelations(dir.file("r.relations"));
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, relations.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0 - 2 * M_PI, relations[2].relative.theta, 1e-12);
    // Scan stamps 10 s earlier than the relation stamps: offset +10.
    const std::vector<rgnav::StampedScan> scans{{1, 90.0}, {2, 91.0}, {3, 92.0}, {4, 95.0}};
    const auto matched = rgnav::matchRelations(relations, scans, 10.0, 0.002);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, matched.size());
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{1}, matched[0].first);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{2}, matched[0].second);
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{3}, matched[1].first);
    CPPUNIT_ASSERT(rgnav::matchRelations(relations, scans, 0.0, 0.002).empty());
    CPPUNIT_ASSERT_THROW(rgnav::readRelations(dir.file("missing")), rgnav::FileError);
  }
  void malformedRelationsAreFormatErrors() {
    rgnav::testing::TempDir dir;
    rgnav::testing::writeFile(dir.file("bad.relations"), "1 2 0 0 0 0 0 0\n1 2 0.5 nan 0 0 0 0\n");
    try {
      rgnav::readRelations(dir.file("bad.relations"));
      CPPUNIT_FAIL("no FormatError");
    } catch (const rgnav::FormatError& e) {
      CPPUNIT_ASSERT_EQUAL(std::size_t{2}, e.line());
    }
  }
  void derivedRelationsCoverPathAndRevisits() {
    // Out 10 m along x and back, 0.1 m and 1 s per pose, turning at the end.
    std::vector<rgnav::TrajectoryPose> trajectory;
    rgnav::DataId id = 1;
    for (int i = 0; i <= 100; ++i, ++id) trajectory.push_back({id, double(id), {i * 0.1, 0, 0}});
    for (int i = 100; i >= 0; --i, ++id) trajectory.push_back({id, double(id), {i * 0.1, 0.2, M_PI}});
    const auto relations = rgnav::relationsFromTrajectory(trajectory);
    std::size_t revisits = 0;
    for (const auto& r : relations) {
      const auto& a = trajectory[r.first - 1].pose;
      const auto& b = trajectory[r.second - 1].pose;
      const Pose2D expected = rgnav::between(a, b);
      CPPUNIT_ASSERT(std::hypot(expected.x - r.relative.x, expected.y - r.relative.y) < 1e-12);
      if (r.second - r.first > 30) ++revisits;
    }
    CPPUNIT_ASSERT(relations.size() > 40);
    CPPUNIT_ASSERT(revisits == 0);  // coming back heads the other way: no revisit by heading
    for (auto& p : trajectory)
      if (p.id > 101) p.pose.theta = 0;  // walking back facing forwards
    std::size_t forwards = 0;
    for (const auto& r : rgnav::relationsFromTrajectory(trajectory)) forwards += r.second - r.first > 30 ? 1 : 0;
    CPPUNIT_ASSERT(forwards > 10);
  }
  void odometryNoiseIsSeeded() {
    std::vector<Pose2D> reference;
    for (int i = 0; i < 200; ++i) reference.push_back({0.1 * i, 0, 0.01 * i});
    const auto a = rgnav::noisyOdometry(reference, {}, 7);
    const auto b = rgnav::noisyOdometry(reference, {}, 7);
    const auto c = rgnav::noisyOdometry(reference, {}, 8);
    CPPUNIT_ASSERT_EQUAL(reference.size(), a.size());
    CPPUNIT_ASSERT(a == b);
    CPPUNIT_ASSERT(!(a == c));
    CPPUNIT_ASSERT(a.front() == reference.front());
    const double drift = std::hypot(a.back().x - reference.back().x, a.back().y - reference.back().y);
    CPPUNIT_ASSERT(drift > 0.01 && drift < 5.0);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RelativePoseMetricTest);
