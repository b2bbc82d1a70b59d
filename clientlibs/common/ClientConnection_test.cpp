// What ClientConnection says when it never reaches its module: within the first-contact budget
// (not the long retry budget modules ride restarts out with) a ModuleUnavailableError that names
// the call, the object looked up, the naming service's host:port (or the direct address) and the
// last failure. Nothing answers on the port used: it is bound by the test and never listens.
#include <cppunit/extensions/HelperMacros.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <stdexcept>

#include "clientlibs/common/ClientConnection.h"

using namespace rgnav;

namespace {

// A loopback port held (bound, not listening) for the test's lifetime: connecting is refused.
class RefusingPort {
 public:
  RefusingPort() : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len) != 0)
      throw std::runtime_error("cannot bind a loopback port");
    port_ = ntohs(addr.sin_port);
  }
  ~RefusingPort() { ::close(fd_); }
  RefusingPort(const RefusingPort&) = delete;
  RefusingPort& operator=(const RefusingPort&) = delete;
  int port() const { return port_; }

 private:
  int fd_;
  int port_ = 0;
};

ClientSettings settingsFor(int namingPort) {
  ClientSettings settings;
  settings.namingHost = "127.0.0.1";
  settings.namingPort = namingPort;
  settings.retryBudget = std::chrono::seconds(5);
  return settings;
}

// The message of the ModuleUnavailableError a ping through `connection` ends in.
std::string unavailableMessage(ClientConnection& connection) {
  try {
    connection.invoke("ping", Idempotence::Idempotent,
                      [](CORBA::Object_ptr object, std::uint64_t) { object->_non_existent(); });
  } catch (const ModuleUnavailableError& e) {
    return e.what();
  }
  return "(answered)";
}

void assertContains(const std::string& message, const std::string& part) {
  CPPUNIT_ASSERT_MESSAGE("'" + part + "' not in: " + message, message.find(part) != std::string::npos);
}

}  // namespace

class ClientConnectionTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ClientConnectionTest);
  CPPUNIT_TEST(noNamingServiceFailsWithinFirstContactBudgetNamingWhatItTried);
  CPPUNIT_TEST(withoutFirstContactBudgetTheRetryBudgetHolds);
  CPPUNIT_TEST(directAddressIsNamed);
  CPPUNIT_TEST_SUITE_END();

 public:
  void noNamingServiceFailsWithinFirstContactBudgetNamingWhatItTried() {
    RefusingPort naming;
    ClientSettings settings = settingsFor(naming.port());
    settings.robot = "testbot";
    settings.firstContactBudget = std::chrono::milliseconds(300);
    ClientConnection connection("RGMappingKernel", settings);
    const std::string message = unavailableMessage(connection);
    assertContains(message, "RGMappingKernel.ping: no answer within 300 ms");
    assertContains(message, "RGNav/testbot/RGMappingKernel");
    assertContains(message, "naming service at 127.0.0.1:" + std::to_string(naming.port()));
    assertContains(message, "naming service not reachable: TRANSIENT");
    CPPUNIT_ASSERT(connection.state() == ConnectionState::Down);
  }

  void withoutFirstContactBudgetTheRetryBudgetHolds() {
    RefusingPort naming;
    ClientSettings settings = settingsFor(naming.port());
    settings.retryBudget = std::chrono::milliseconds(200);
    ClientConnection connection("Laser", settings);
    assertContains(unavailableMessage(connection), "Laser.ping: no answer within 200 ms");
  }

  void directAddressIsNamed() {
    RefusingPort watchdog;
    ClientSettings settings = settingsFor(0);
    settings.firstContactBudget = std::chrono::milliseconds(300);
    ClientConnection connection("Watchdog", settings, HostPort{"127.0.0.1", watchdog.port()});
    const std::string message = unavailableMessage(connection);
    assertContains(message, "Watchdog.ping: no answer within 300 ms");
    assertContains(message, "corbaloc::127.0.0.1:" + std::to_string(watchdog.port()) + "/Watchdog");
    assertContains(message, "TRANSIENT");
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ClientConnectionTest);
