// parseHostPort: endpoints as users write them are accepted; a text that is no host:port is a
// ConfigError naming it (a host with a space once reached the ORB and aborted the tool).
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/HostPort.h"

using namespace rgnav;

namespace {

std::string refusal(const std::string& text) {
  try {
    parseHostPort(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

class HostPortTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HostPortTest);
  CPPUNIT_TEST(acceptsNamesAndAddresses);
  CPPUNIT_TEST(refusesBadPortsAndHosts);
  CPPUNIT_TEST_SUITE_END();

 public:
  void acceptsNamesAndAddresses() {
    CPPUNIT_ASSERT_EQUAL(std::string("127.0.0.1:2809"), parseHostPort("127.0.0.1:2809").str());
    CPPUNIT_ASSERT_EQUAL(std::string("robot-7.lab_net:65535"), parseHostPort("robot-7.lab_net:65535").str());
    CPPUNIT_ASSERT_EQUAL(std::string("[fe80::1%eth0]"), parseHostPort("[fe80::1%eth0]:12").host);
  }

  void refusesBadPortsAndHosts() {
    CPPUNIT_ASSERT_EQUAL(std::string("'a b:1' has no valid host (letters, digits and . - _ : [ ] % only)"), refusal("a b:1"));
    CPPUNIT_ASSERT(refusal("host/x:1").find("no valid host") != std::string::npos);
    CPPUNIT_ASSERT(refusal("h\n:1").find("no valid host") != std::string::npos);
    CPPUNIT_ASSERT_EQUAL(std::string("'h:0' has no valid port (1..65535)"), refusal("h:0"));
    CPPUNIT_ASSERT_EQUAL(std::string("':5' is not host:port"), refusal(":5"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(HostPortTest);
