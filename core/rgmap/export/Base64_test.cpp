// Tests Base64 against the test vectors of RFC 4648 section 10, a round trip of every byte value
// and the refusal of malformed text.
#include "core/rgmap/export/Base64.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"

using namespace rgnav;

namespace {

std::vector<std::uint8_t> bytes(const std::string& s) { return {s.begin(), s.end()}; }

}  // namespace

class Base64Test : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(Base64Test);
  CPPUNIT_TEST(rfcVectors);
  CPPUNIT_TEST(everyByteRoundTrips);
  CPPUNIT_TEST(malformedTextIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void rfcVectors() {
    const std::pair<std::string, std::string> vectors[] = {
        {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="},
        {"foobar", "Zm9vYmFy"}};
    for (const auto& [plain, encoded] : vectors) {
      CPPUNIT_ASSERT_EQUAL(encoded, encodeBase64(bytes(plain)));
      CPPUNIT_ASSERT(bytes(plain) == decodeBase64(encoded));
    }
  }

  void everyByteRoundTrips() {
    std::vector<std::uint8_t> all;
    for (int b = 255; b >= 0; --b) all.push_back(std::uint8_t(b));
    for (std::size_t n = 0; n <= all.size(); n += 85) {
      const std::vector<std::uint8_t> part(all.begin(), all.begin() + std::ptrdiff_t(n));
      CPPUNIT_ASSERT(part == decodeBase64(encodeBase64(part)));
    }
  }

  void malformedTextIsRefused() {
    for (const char* bad : {"Zg=", "Z===", "Zg=a", "Zg==Zm8=", "Zm9*", "Zm 9"})
      CPPUNIT_ASSERT_THROW_MESSAGE(bad, decodeBase64(bad), InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(Base64Test);
