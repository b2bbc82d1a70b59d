// Tests the strict parsing of command-line numbers: whole texts only, refusals that name the
// argument and the text, and Boost options that refuse what Boost alone would wrap or accept.
#include <cppunit/extensions/HelperMacros.h>

#include "tools/common/CommandLine.h"
#include "tools/common/StrictArguments.h"

using namespace rgnav;

namespace {

// The message of the ArgumentError `parse` throws, after checking it names argument and text.
template <class Parse>
std::string refusal(Parse parse, const std::string& argument, const std::string& text) {
  try {
    parse();
  } catch (const ArgumentError& e) {
    CPPUNIT_ASSERT_EQUAL(argument, e.argument());
    CPPUNIT_ASSERT_EQUAL(text, e.text());
    return e.what();
  }
  CPPUNIT_FAIL("'" + text + "' was accepted");
  return "";
}

}  // namespace

class StrictArgumentsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(StrictArgumentsTest);
  CPPUNIT_TEST(wholeNumbersAreTheWholeText);
  CPPUNIT_TEST(idsStartAtOne);
  CPPUNIT_TEST(numbersAreFiniteAndTheWholeText);
  CPPUNIT_TEST(optionsAreParsedStrictly);
  CPPUNIT_TEST_SUITE_END();

 public:
  void wholeNumbersAreTheWholeText() {
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, parseWholeNumber("0", "--after"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{18446744073709551615u}, parseWholeNumber("18446744073709551615", "--after"));
    CPPUNIT_ASSERT_EQUAL(std::string("region ID '3x' is not a whole number"),
                         refusal([] { parseWholeNumber("3x", "region ID"); }, "region ID", "3x"));
    for (const char* bad : {"", "-5", "+5", " 5", "5 ", "0x10", "1.0", "abc"})
      refusal([&] { parseWholeNumber(bad, "--after"); }, "--after", bad);
    refusal([] { parseWholeNumber("18446744073709551616", "--after"); }, "--after", "18446744073709551616");
    CPPUNIT_ASSERT_EQUAL(std::string("--batch '300' is too large (at most 255)"),
                         refusal([] { parseWholeNumber("300", "--batch", 255); }, "--batch", "300"));
  }

  void idsStartAtOne() {
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{3}, parseId("3", "region ID"));
    refusal([] { parseId("0", "region ID"); }, "region ID", "0");
    refusal([] { parseId("3x", "region ID"); }, "region ID", "3x");
  }

  void numbersAreFiniteAndTheWholeText() {
    CPPUNIT_ASSERT_EQUAL(1.5, parseFiniteNumber("1.5", "x"));
    CPPUNIT_ASSERT_EQUAL(-2.0, parseFiniteNumber("-2", "x"));
    CPPUNIT_ASSERT_EQUAL(1000.0, parseFiniteNumber("1e3", "x"));
    CPPUNIT_ASSERT_EQUAL(std::string("x 'nan' is not a finite number"),
                         refusal([] { parseFiniteNumber("nan", "x"); }, "x", "nan"));
    for (const char* bad : {"inf", "-inf", "infinity", "1e999"}) refusal([&] { parseFiniteNumber(bad, "x"); }, "x", bad);
    for (const char* bad : {"", "1.5m", " 1", "1 ", "abc", "+1", "0x1p3", "1,5"})
      refusal([&] { parseFiniteNumber(bad, "x"); }, "x", bad);
  }

  void optionsAreParsedStrictly() {
    namespace po = boost::program_options;
    std::uint64_t after = 7;
    double timeout = 0;
    po::options_description desc;
    desc.add_options()("after", strictOption(&after, "--after")->default_value("0"), "")(
        "timeout", strictOption(&timeout, "--timeout")->default_value("30"), "");
    const auto parse = [&](std::vector<std::string> args) {
      args.insert(args.begin(), "tool");
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      return parseCommandLine(int(argv.size()), argv.data(), desc);
    };
    CPPUNIT_ASSERT(parse({}));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, after);
    CPPUNIT_ASSERT_EQUAL(30.0, timeout);
    CPPUNIT_ASSERT(parse({"--after", "12", "--timeout", "2.5"}));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{12}, after);
    CPPUNIT_ASSERT_EQUAL(2.5, timeout);
    refusal([&] { parse({"--after=-5"}); }, "--after", "-5");
    refusal([&] { parse({"--timeout", "nan"}); }, "--timeout", "nan");
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(StrictArgumentsTest);
