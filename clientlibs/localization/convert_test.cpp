// Round trips of the Localization.idl conversions: an estimate with every field set (a full
// covariance, so that a transposed matrix shows), a particle, a snapshot, the module's state and
// the initial guess's sigma.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/localization/convert.h"

using namespace rgnav;

class LocalizationConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LocalizationConvertTest);
  CPPUNIT_TEST(estimateRoundTrip);
  CPPUNIT_TEST(covarianceIsRowMajor);
  CPPUNIT_TEST(snapshotRoundTrip);
  CPPUNIT_TEST(stateAndSigmaRoundTrip);
  CPPUNIT_TEST_SUITE_END();

  static ScanEstimate sample() {
    ScanEstimate s;
    s.scanId = 4711;
    PoseEstimate& e = s.estimate;
    e.scanId = 4702;
    e.region = RegionId(7);
    e.mapPose = {1.0 / 3.0, -2.5, 0.75};
    e.regionPose = {0.125, 4.0, -3.0};
    e.covariance << 0.01, 0.002, 0.003, 0.004, 0.02, 0.005, 0.006, 0.007, 0.03;
    e.bestParticle = {0.3, -2.4, 0.7};
    e.clusterWeight = 0.875;
    e.particles = 1234;
    e.fitPerBeam = -1.0 / 7.0;
    return s;
  }

 public:
  void estimateRoundTrip() {
    const ScanEstimate s = sample();
    const ScanEstimate back = fromIdl(toIdl(s));
    CPPUNIT_ASSERT_EQUAL(s.scanId, back.scanId);
    CPPUNIT_ASSERT_EQUAL(s.estimate.scanId, back.estimate.scanId);
    CPPUNIT_ASSERT(s.estimate.region == back.estimate.region);
    CPPUNIT_ASSERT(s.estimate.mapPose == back.estimate.mapPose);
    CPPUNIT_ASSERT(s.estimate.regionPose == back.estimate.regionPose);
    CPPUNIT_ASSERT(s.estimate.covariance == back.estimate.covariance);
    CPPUNIT_ASSERT(s.estimate.bestParticle == back.estimate.bestParticle);
    CPPUNIT_ASSERT_EQUAL(s.estimate.clusterWeight, back.estimate.clusterWeight);
    CPPUNIT_ASSERT_EQUAL(s.estimate.particles, back.estimate.particles);
    CPPUNIT_ASSERT_EQUAL(s.estimate.fitPerBeam, back.estimate.fitPerBeam);
  }

  // The IDL matrix is row-major: element (0, 1) is the x-y entry (a reader of the IDL alone must
  // find it there, not only a round trip through the same code).
  void covarianceIsRowMajor() {
    const RGNav::LocalizationEstimate idl = toIdl(sample());
    CPPUNIT_ASSERT_EQUAL(0.002, idl.covariance[1]);
    CPPUNIT_ASSERT_EQUAL(0.004, idl.covariance[3]);
    CPPUNIT_ASSERT_EQUAL(0.007, idl.covariance[7]);
  }

  void snapshotRoundTrip() {
    ParticleSnapshotView s;
    s.scanId = 99;
    s.total = 5000;
    s.particles = {{{RegionId(2), {1.5, 2.5, 0.1}, 0.25}, {11.5, 3.5, 0.6}},
                   {{RegionId(3), {-0.5, 0.25, -3.1}, 1e-9}, {20.0, -1.0, 2.9}}};
    CPPUNIT_ASSERT(s == fromIdl(toIdl(s)));
    CPPUNIT_ASSERT(ParticleSnapshotView{} == fromIdl(toIdl(ParticleSnapshotView{})));
  }

  void stateAndSigmaRoundTrip() {
    const LocalizationStateView s{true, 12, 345, 6789, 1011, 3};
    CPPUNIT_ASSERT(s == fromIdl(toIdl(s)));
    const Eigen::Vector3d sigma(0.25, 0.5, 0.0625);
    CPPUNIT_ASSERT(sigma == fromIdl(toIdlSigma(sigma)));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LocalizationConvertTest);
