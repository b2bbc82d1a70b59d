// Tests the TLS line fit on point moments: exact lines, combination of moments, the covariance
// against a Monte Carlo estimate, degenerate input.
#include "core/lines/PointMoments.h"

#include <cppunit/extensions/HelperMacros.h>

#include <random>

#include "core/common/Errors.h"

using Eigen::Vector2d;
using rgnav::PointMoments;

class PointMomentsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PointMomentsTest);
  CPPUNIT_TEST(fitsExactLineInHesseForm);
  CPPUNIT_TEST(combinedMomentsEqualMomentsOfAllPoints);
  CPPUNIT_TEST(covarianceMatchesMonteCarlo);
  CPPUNIT_TEST(degenerateInputIsTypedError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void fitsExactLineInHesseForm() {
    // The line y = -x + 2: normal (1,1)/sqrt2, distance sqrt2.
    PointMoments m;
    for (int i = 0; i < 10; ++i) m.add(Vector2d(0.3 * i, 2.0 - 0.3 * i));
    const auto fit = m.fitLine();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 4, fit.normalAngleRad, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::sqrt(2.0), fit.distanceM, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, fit.rmsResidualM, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, std::fabs(fit.direction.dot(fit.normal)), 1e-12);
  }

  void combinedMomentsEqualMomentsOfAllPoints() {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    PointMoments all, left, right;
    for (int i = 0; i < 50; ++i) {
      const Vector2d p(u(random), 0.2 * u(random));
      all.add(p);
      (i < 20 ? left : right).add(p);
    }
    left.add(right);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(all.count(), left.count(), 0.0);
    CPPUNIT_ASSERT((all.mean() - left.mean()).norm() < 1e-12);
    CPPUNIT_ASSERT((all.scatter() - left.scatter()).norm() < 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(all.fitLine().normalAngleRad, left.fitLine().normalAngleRad, 1e-12);
  }

  void covarianceMatchesMonteCarlo() {
    // 20 points along x in [2, 4] on the line y = 1, noise 1 cm: the centroid lies 3 m along the
    // line from the foot of the normal, so angle and distance are strongly correlated.
    const double sigma = 0.01;
    std::mt19937 random(7);
    std::normal_distribution<double> noise(0.0, sigma);
    const int trials = 4000;
    double sa = 0, sr = 0, saa = 0, srr = 0, sar = 0;
    Eigen::Matrix2d predicted = Eigen::Matrix2d::Zero();
    for (int t = 0; t < trials; ++t) {
      PointMoments m;
      for (int i = 0; i < 20; ++i) m.add(Vector2d(2.0 + 0.1 * i, 1.0 + noise(random)));
      const auto fit = m.fitLine();
      const double a = fit.normalAngleRad - M_PI / 2, r = fit.distanceM;
      sa += a, sr += r, saa += a * a, srr += r * r, sar += a * r;
      predicted += fit.covariance / trials;
    }
    const double ma = sa / trials, mr = sr / trials;
    const double vaa = saa / trials - ma * ma, vrr = srr / trials - mr * mr, var = sar / trials - ma * mr;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(vaa, predicted(0, 0), 0.1 * vaa);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(vrr, predicted(1, 1), 0.1 * vrr);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(var, predicted(0, 1), 0.1 * std::fabs(var));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(predicted(0, 1), predicted(1, 0), 1e-15);
  }

  void degenerateInputIsTypedError() {
    PointMoments m;
    CPPUNIT_ASSERT_THROW(m.fitLine(), rgnav::InvalidArgumentError);
    m.add(Vector2d(1, 1));
    CPPUNIT_ASSERT_THROW(m.fitLine(), rgnav::InvalidArgumentError);
    m.add(Vector2d(1, 1));
    CPPUNIT_ASSERT_THROW(m.fitLine(), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(PointMomentsTest);
