// Tests the k-means start values from distance-sorted sliding windows and the determinism of
// k-means from them (thesis 4.1.3.3).
#include "core/gateways/classify/KMeans.h"

#include <cppunit/extensions/HelperMacros.h>

#include <random>

#include "core/common/Errors.h"
#include "core/gateways/classify/WindowSeeds.h"

namespace {

// 3 x 50 points around three centres, in blob order (as if sorted by distance), seeded.
Eigen::MatrixXd blobs() {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.1);
  const Eigen::MatrixXd centres = (Eigen::MatrixXd(2, 3) << 0.0, 1.0, 0.0, 0.0, 0.0, 1.0).finished();
  Eigen::MatrixXd points(2, 150);
  for (Eigen::Index p = 0; p < points.cols(); ++p) {
    points.col(p) = centres.col(p / 50) + Eigen::Vector2d(noise(rng), noise(rng));
  }
  return points;
}

}  // namespace

class KMeansTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(KMeansTest);
  CPPUNIT_TEST(windowMeansCoverTheSortedData);
  CPPUNIT_TEST(kMeansFromWindowsIsDeterministic);
  CPPUNIT_TEST(kMeansFindsSeparatedBlobs);
  CPPUNIT_TEST(rejectsBadArguments);
  CPPUNIT_TEST_SUITE_END();

 public:
  void windowMeansCoverTheSortedData() {
    const Eigen::MatrixXd values = Eigen::RowVectorXd::LinSpaced(10, 0.0, 9.0);
    // Window 5, stride 2.5: [0, 5), [3, 8), [5, 10).
    const Eigen::MatrixXd overlapping = rgnav::slidingWindowMeans(values, 3, 0.5);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, overlapping(0, 0), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, overlapping(0, 1), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0, overlapping(0, 2), 1e-12);
    const Eigen::MatrixXd disjoint = rgnav::slidingWindowMeans(values, 2, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, disjoint(0, 0), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0, disjoint(0, 1), 1e-12);
    const Eigen::MatrixXd single = rgnav::slidingWindowMeans(values, 10, 0.9);
    CPPUNIT_ASSERT_EQUAL(Eigen::Index(10), single.cols());
  }

  void kMeansFromWindowsIsDeterministic() {
    const Eigen::MatrixXd points = blobs();
    const rgnav::KMeansResult first = rgnav::kMeans(points, rgnav::slidingWindowMeans(points, 4, 0.5));
    const rgnav::KMeansResult second = rgnav::kMeans(points, rgnav::slidingWindowMeans(points, 4, 0.5));
    CPPUNIT_ASSERT(first.converged);
    CPPUNIT_ASSERT(first.centres == second.centres);
    CPPUNIT_ASSERT(first.assignment == second.assignment);
    CPPUNIT_ASSERT_EQUAL(first.iterations, second.iterations);
  }

  void kMeansFindsSeparatedBlobs() {
    const Eigen::MatrixXd points = blobs();
    const rgnav::KMeansResult result = rgnav::kMeans(points, rgnav::slidingWindowMeans(points, 3, 0.2));
    CPPUNIT_ASSERT(result.converged);
    for (Eigen::Index p = 0; p < points.cols(); ++p) {
      CPPUNIT_ASSERT_EQUAL(p / 50, result.assignment[static_cast<std::size_t>(p)]);
    }
    CPPUNIT_ASSERT((result.centres.col(1) - Eigen::Vector2d(1.0, 0.0)).norm() < 0.05);
    // A limit of no updates keeps the start centres and assigns every point to its nearest.
    const Eigen::MatrixXd start = Eigen::MatrixXd::Zero(2, 2);
    const rgnav::KMeansResult none = rgnav::kMeans(points, start, 0);
    CPPUNIT_ASSERT(none.centres == start);
    CPPUNIT_ASSERT_EQUAL(0, none.iterations);
  }

  void rejectsBadArguments() {
    const Eigen::MatrixXd points = blobs();
    CPPUNIT_ASSERT_THROW(rgnav::slidingWindowMeans(points, 151, 0.5), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::slidingWindowMeans(points, 0, 0.5), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::slidingWindowMeans(points, 3, 1.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::kMeans(points, Eigen::MatrixXd::Zero(3, 2)), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::kMeans(Eigen::MatrixXd(2, 0), Eigen::MatrixXd::Zero(2, 2)),
                         rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(KMeansTest);
