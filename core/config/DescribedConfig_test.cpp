// Tests the reader and writer of described parameter structs on a small nested struct: the
// complete output, the round trip (degrees too), and each error naming the key path and line.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/config/DescribedConfig.h"

using rgnav::ConfigError;

namespace rgnav {

struct InnerParams {
  double angleRad = 5.0 * M_PI / 180.0;
  bool restrictive = true;
  int offset = -3;
};

template <class V>
void describe(V& v, InnerParams& c) {
  v.degrees("angle_deg", c.angleRad);
  v.field("restrictive", c.restrictive);
  v.field("offset", c.offset);
}

struct OuterParams {
  double rangeM = 0.1;
  std::size_t minPoints = 20;
  InnerParams inner;
};

template <class V>
void describe(V& v, OuterParams& c) {
  v.field("range_m", c.rangeM);
  v.field("min_points", c.minPoints);
  v.section("inner", c.inner);
}

}  // namespace rgnav

namespace {

const std::string kDefaults =
    "range_m: 0.1\n"
    "min_points: 20\n"
    "inner:\n"
    "  angle_deg: 5\n"
    "  restrictive: true\n"
    "  offset: -3\n";

rgnav::OuterParams parse(const std::string& text) { return rgnav::parseDescribed<rgnav::OuterParams>(text, "t.yaml"); }

std::string edited(const std::string& from, const std::string& to) {
  std::string text = kDefaults;
  const std::size_t at = text.find(from);
  CPPUNIT_ASSERT_MESSAGE(from, at != std::string::npos);
  return text.replace(at, from.size(), to);
}

void expectConfigError(const std::string& text, const std::string& expected) {
  try {
    parse(text);
    CPPUNIT_FAIL("expected ConfigError containing " + expected);
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    CPPUNIT_ASSERT_MESSAGE(message, message.find(expected) != std::string::npos);
    CPPUNIT_ASSERT_MESSAGE(message, message.rfind("t.yaml: ", 0) == 0);
  }
}

}  // namespace

class DescribedConfigTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DescribedConfigTest);
  CPPUNIT_TEST(writesEveryKeyInOrder);
  CPPUNIT_TEST(readsBackExactly);
  CPPUNIT_TEST(rejectsUnknownKey);
  CPPUNIT_TEST(rejectsMissingKey);
  CPPUNIT_TEST(rejectsWrongType);
  CPPUNIT_TEST(rejectsNonFiniteAndNegative);
  CPPUNIT_TEST(rejectsDegreesWithoutDegreeKey);
  CPPUNIT_TEST_SUITE_END();

 public:
  void writesEveryKeyInOrder() { CPPUNIT_ASSERT_EQUAL(kDefaults, rgnav::describedYaml(rgnav::OuterParams{})); }

  void readsBackExactly() {
    const rgnav::OuterParams defaults = parse(kDefaults);
    CPPUNIT_ASSERT_EQUAL(rgnav::OuterParams{}.inner.angleRad, defaults.inner.angleRad);
    rgnav::OuterParams odd;
    odd.rangeM = 0.1 + 0.2;
    odd.minPoints = 7;
    odd.inner.angleRad = 0.123456789;  // no short number of degrees
    odd.inner.restrictive = false;
    odd.inner.offset = 12;
    const rgnav::OuterParams read = parse(rgnav::describedYaml(odd));
    CPPUNIT_ASSERT_EQUAL(odd.rangeM, read.rangeM);
    CPPUNIT_ASSERT_EQUAL(odd.minPoints, read.minPoints);
    CPPUNIT_ASSERT_EQUAL(odd.inner.angleRad, read.inner.angleRad);
    CPPUNIT_ASSERT_EQUAL(odd.inner.restrictive, read.inner.restrictive);
    CPPUNIT_ASSERT_EQUAL(odd.inner.offset, read.inner.offset);
  }

  void rejectsUnknownKey() {
    expectConfigError(edited("  restrictive: true\n", "  restrictive: true\n  restrictiv: true\n"),
                      "inner.restrictiv: unknown key (line 6)");
    expectConfigError(edited("min_points: 20\n", "min_points: 20\nmin_points: 21\n"), "min_points: duplicate key");
  }

  void rejectsMissingKey() {
    expectConfigError(edited("  angle_deg: 5\n", ""), "inner.angle_deg: missing required key");
    expectConfigError(edited("range_m: 0.1\n", ""), "range_m: missing required key");
    expectConfigError("", "top level: wrong type, expected a mapping");
  }

  void rejectsWrongType() {
    expectConfigError(edited("range_m: 0.1", "range_m: near"), "range_m: wrong type, expected a number");
    expectConfigError(edited("min_points: 20", "min_points: 2.5"), "min_points: wrong type, expected an integer");
    expectConfigError(edited("restrictive: true", "restrictive: 1.5"), "inner.restrictive: wrong type");
    expectConfigError(edited("offset: -3", "offset: -3.5"), "inner.offset: wrong type, expected an integer");
    expectConfigError(edited("offset: -3", "offset: 3000000000"), "inner.offset: out of range");
    expectConfigError(edited("inner:\n  angle_deg: 5\n  restrictive: true\n  offset: -3\n", "inner: 3\n"),
                      "inner: wrong type, expected a mapping");
    expectConfigError("range_m: [0.1", "not YAML");
  }

  void rejectsNonFiniteAndNegative() {
    expectConfigError(edited("range_m: 0.1", "range_m: .inf"), "range_m: out of range: not a finite number");
    expectConfigError(edited("angle_deg: 5", "angle_deg: .nan"), "inner.angle_deg: out of range: not a finite number");
    expectConfigError(edited("min_points: 20", "min_points: -1"), "min_points: out of range");
  }

  void rejectsDegreesWithoutDegreeKey() {
    rgnav::ConfigWriter writer;
    double angleRad = 0.1;
    CPPUNIT_ASSERT_THROW(writer.degrees("angle_rad", angleRad), ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(DescribedConfigTest);
