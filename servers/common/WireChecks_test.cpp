// Tests the argument checks of the servants: NaN and infinite numbers, ID 0, reversed ranges,
// zero and huge counts, over-long names and control characters are refused naming the argument;
// good arguments pass.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>
#include <string>

#include "servers/common/RefusedField.h"
#include "servers/common/WireChecks.h"

using namespace rgnav;

class WireChecksTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(WireChecksTest);
  CPPUNIT_TEST(numbersMustBeFinite);
  CPPUNIT_TEST(idsAndRanges);
  CPPUNIT_TEST(countsAreAtLeastOneAndCapped);
  CPPUNIT_TEST(namesAreBounded);
  CPPUNIT_TEST_SUITE_END();

 public:
  void numbersMustBeFinite() {
    const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
    CPPUNIT_ASSERT_EQUAL(std::string("x"), refusedField([&] { wire::requireFinite(nan, "x"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("start"), refusedField([&] { wire::requireFinite(RGNav::Point2D{1.0, -inf}, "start"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("pose"), refusedField([&] { wire::requireFinite(RGNav::Pose2D{0.0, 0.0, nan}, "pose"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("(accepted)"), refusedField([] { wire::requireFinite(RGNav::Pose2D{1.0, 2.0, 3.0}, "pose"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("stamp"), refusedField([] { wire::requireValid(RGNav::Time{5, 1'000'000'000u}, "stamp"); }));
  }

  void idsAndRanges() {
    CPPUNIT_ASSERT_EQUAL(std::string("id"), refusedField([] { wire::requireId(0, "id"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("lastId"), refusedField([] { wire::requireIdRange(5, 4, "firstId", "lastId"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("firstId"), refusedField([] { wire::requireIdRange(0, 4, "firstId", "lastId"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("(accepted)"), refusedField([] { wire::requireIdRange(4, 4, "firstId", "lastId"); }));
  }

  void countsAreAtLeastOneAndCapped() {
    CPPUNIT_ASSERT_EQUAL(std::string("maxCount"), refusedField([] { wire::cappedCount(0, 500, "maxCount"); }));
    CPPUNIT_ASSERT_EQUAL(std::size_t{500}, wire::cappedCount(0xffffffffu, 500, "maxCount"));  // -1 on the wire
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, wire::cappedCount(3, 500, "maxCount"));
  }

  void namesAreBounded() {
    const std::string longName(wire::kMaxNameLength + 1, 'a');
    CPPUNIT_ASSERT_EQUAL(std::string("name"), refusedField([&] { wire::checkedName(longName.c_str(), "name"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("name"), refusedField([] { wire::checkedName("kitchen\n", "name"); }));
    CPPUNIT_ASSERT_EQUAL(std::string("name"), refusedField([] { wire::checkedName("", "name", false); }));
    CPPUNIT_ASSERT_EQUAL(std::string("kitchen"), wire::checkedName("kitchen", "name", false));
    CPPUNIT_ASSERT_EQUAL(std::string(), wire::checkedName("", "consumer"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(WireChecksTest);
