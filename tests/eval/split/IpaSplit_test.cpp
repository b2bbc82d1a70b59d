// Tests the IPA tuning/check split: the shipped file holds each of the ten benchmark maps in
// exactly one set, loading is strict, maps are pooled by set, and the per-set figure line prints
// n/a for an empty set.
#include "tests/eval/split/IpaSplit.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"

using namespace rgnav;

class IpaSplitTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(IpaSplitTest);
  CPPUNIT_TEST(shippedSplitHoldsEveryBenchmarkMapOnce);
  CPPUNIT_TEST(mapsAreNamedWithOrWithoutFurniture);
  CPPUNIT_TEST(loadingIsStrict);
  CPPUNIT_TEST(mapsArePooledBySet);
  CPPUNIT_TEST(unknownMapFailsBeforeAnyEvaluation);
  CPPUNIT_TEST(figureLinePrintsBothSets);
  CPPUNIT_TEST_SUITE_END();

 public:
  void shippedSplitHoldsEveryBenchmarkMapOnce() {
    const IpaSplit split = loadIpaSplit("config/eval/ipa-split.yaml");
    int tuning = 0;
    for (const char* map : {"Freiburg52_scan", "Freiburg79_scan", "lab_a_scan", "lab_b_scan", "lab_c_scan",
                            "lab_intel", "office_a", "office_b", "office_c", "office_d"})
      tuning += split.setOf(std::string(map) + "_furnitures.png") == MapSet::kTuning;
    CPPUNIT_ASSERT_EQUAL(5, tuning);
    CPPUNIT_ASSERT_THROW(split.setOf("lab_d.png"), ConfigError);
  }

  void mapsAreNamedWithOrWithoutFurniture() {
    CPPUNIT_ASSERT_EQUAL(std::string("lab_a_scan"), ipaMapName("/data/test_maps/lab_a_scan_furnitures.png"));
    CPPUNIT_ASSERT_EQUAL(std::string("lab_a_scan"), ipaMapName("lab_a_scan.png"));
    const IpaSplit split({"a"}, {"b"});
    CPPUNIT_ASSERT(split.setOf("x/a_furnitures.png") == MapSet::kTuning);
    CPPUNIT_ASSERT(split.setOf("b.png") == MapSet::kCheck);
  }

  void loadingIsStrict() {
    CPPUNIT_ASSERT_NO_THROW(parseIpaSplit("tuning: [a]\ncheck: [b]\n"));
    CPPUNIT_ASSERT_THROW(parseIpaSplit("tuning: [a]\ncheck: [b]\nvalidation: [c]\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(parseIpaSplit("tuning: [a]\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(parseIpaSplit("tuning: []\ncheck: [b]\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(parseIpaSplit("tuning: [a, b]\ncheck: [b]\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(parseIpaSplit("tuning: a\ncheck: [b]\n"), ConfigError);
    CPPUNIT_ASSERT_THROW(loadIpaSplit("no/such/split.yaml"), FileError);
  }

  struct Count {
    int n = 0;
    void add(const Count& o) { n += o.n; }
  };

  void mapsArePooledBySet() {
    const IpaSplit split({"a", "c"}, {"b"});
    const auto evaluate = [](const std::string& map) { return Count{map == "b.png" ? 10 : 1}; };
    const SplitTotals<Count> totals =
        evaluateMaps<Count>(split, {"x/a.png", "b.png", "c_furnitures.png"}, evaluate);
    CPPUNIT_ASSERT_EQUAL(12, totals.all.n);
    CPPUNIT_ASSERT_EQUAL(2, totals.tuning.n);
    CPPUNIT_ASSERT_EQUAL(10, totals.check.n);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, totals.tuningMaps);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, totals.checkMaps);
  }

  void unknownMapFailsBeforeAnyEvaluation() {
    int evaluated = 0;
    const auto evaluate = [&](const std::string&) { return Count{++evaluated}; };
    CPPUNIT_ASSERT_THROW(evaluateMaps<Count>(IpaSplit({"a"}, {"b"}), {"a.png", "z.png"}, evaluate), ConfigError);
    CPPUNIT_ASSERT_EQUAL(0, evaluated);
  }

  void figureLinePrintsBothSets() {
    CPPUNIT_ASSERT_EQUAL(std::string("doors: maps_tuning=2 recall_tuning=0.750 maps_check=0 recall_check=n/a"),
                         splitFiguresLine("doors", 2, {{"recall", 0.75}}, 0, {{"recall", 0.0}}));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(IpaSplitTest);
