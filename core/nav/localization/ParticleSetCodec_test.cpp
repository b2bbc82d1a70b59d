// The particle set checkpoint (ParticleSetCodec.h): a set reads back bit for bit (weights and
// poses that need all 17 digits), an empty set too, and damaged texts are FormatErrors naming
// the source.
#include <cppunit/extensions/HelperMacros.h>

#include <limits>

#include "core/common/Errors.h"
#include "core/nav/localization/ParticleSetCodec.h"

using namespace rgnav;

class ParticleSetCodecTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ParticleSetCodecTest);
  CPPUNIT_TEST(roundTripIsExact);
  CPPUNIT_TEST(emptySetRoundTrips);
  CPPUNIT_TEST(damagedTextsAreFormatErrors);
  CPPUNIT_TEST_SUITE_END();

  static std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    CPPUNIT_ASSERT_MESSAGE(from, at != std::string::npos);
    return text.replace(at, from.size(), to);
  }

  static void expectFormatError(const std::string& text) {
    try {
      deserializeParticles(text, "particles.state");
      CPPUNIT_FAIL("accepted: " + text);
    } catch (const FormatError& e) {
      CPPUNIT_ASSERT_MESSAGE(e.what(), std::string(e.what()).find("particles.state") != std::string::npos);
    }
  }

 public:
  void roundTripIsExact() {
    ParticleSetCheckpoint c;
    c.scanId = 123456789012ULL;
    c.particles = {{RegionId(3), {1.0 / 3.0, -2.0 / 7.0, 3.141592653589793}, 0.1},
                   {RegionId(12), {1e-300, 123456.789, -0.5}, std::numeric_limits<double>::denorm_min()},
                   {RegionId(3), {0.0, -0.0, 1.0 / 9.0}, 0.9 - 1e-17}};
    const ParticleSetCheckpoint back = deserializeParticles(serializeParticles(c), "particles.state");
    CPPUNIT_ASSERT(c == back);
  }

  void emptySetRoundTrips() {
    const ParticleSetCheckpoint empty;
    CPPUNIT_ASSERT(empty == deserializeParticles(serializeParticles(empty), "particles.state"));
  }

  void damagedTextsAreFormatErrors() {
    ParticleSetCheckpoint c;
    c.scanId = 7;
    c.particles = {{RegionId(2), {1.5, 2.5, 0.25}, 0.5}};
    const std::string good = serializeParticles(c);
    expectFormatError(good.substr(0, good.size() / 2));
    expectFormatError(replaced(good, "rgnav-particles", "rgnav-plans"));
    expectFormatError(replaced(good, "\"version\":1", "\"version\":2"));
    expectFormatError(replaced(good, "[2,", "[0,"));
    expectFormatError(replaced(good, "0.5]", "-0.5]"));
    expectFormatError(replaced(good, "0.5]", "null]"));
    expectFormatError(replaced(good, "\"scan\":7", "\"scan\":-7"));
    expectFormatError(replaced(good, "[2,[1.5,2.5,0.25],0.5]", "[2,[1.5,2.5],0.5]"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ParticleSetCodecTest);
