// Tests finding a port's holder from /proc: a socket this test listens on names this process
// and its command line; a port nobody listens on has no holder; a process group listens on a port
// only if one of its processes does; a socket at another loopback address is another host's; a
// module's ownership of its port is read once per process, and again after it is forgotten.
#include <cppunit/extensions/HelperMacros.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <optional>
#include <stdexcept>

#include "watchdog/PortHolder.h"
#include "watchdog/UniqueFd.h"

using rgnav::UniqueFd;

namespace {

// A TCP socket bound to a free loopback port; listening if asked.
struct LoopbackSocket {
  explicit LoopbackSocket(bool listening) : fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (::bind(fd.get(), reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        (listening && ::listen(fd.get(), 1) != 0) ||
        ::getsockname(fd.get(), reinterpret_cast<sockaddr*>(&address), &length) != 0)
      throw std::runtime_error("cannot set up a loopback socket");
    port = ntohs(address.sin_port);
  }
  UniqueFd fd;
  int port = 0;
};

}  // namespace

class PortHolderTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PortHolderTest);
  CPPUNIT_TEST(listeningSocketNamesThisProcess);
  CPPUNIT_TEST(boundButNotListeningHasNoHolder);
  CPPUNIT_TEST(ownershipIsReadOncePerProcess);
  CPPUNIT_TEST_SUITE_END();

 public:
  void listeningSocketNamesThisProcess() {
    LoopbackSocket socket(true);
    const std::optional<rgnav::PortHolder> holder = rgnav::findPortHolder({"127.0.0.1", socket.port});
    CPPUNIT_ASSERT(holder);
    CPPUNIT_ASSERT_EQUAL(::getpid(), holder->pid);
    CPPUNIT_ASSERT(holder->command.find("port_holder_test") != std::string::npos);
    CPPUNIT_ASSERT(rgnav::groupListensOn(::getpid(), socket.port));
    CPPUNIT_ASSERT(!rgnav::groupListensOn(::getppid(), socket.port));
    // Another loopback address is another host: the same port number there is free.
    CPPUNIT_ASSERT(!rgnav::findPortHolder({"127.0.0.2", socket.port}));
    CPPUNIT_ASSERT(rgnav::findPortHolder({"localhost", socket.port}));  // not an address: any address
  }

  void boundButNotListeningHasNoHolder() {
    LoopbackSocket socket(false);
    CPPUNIT_ASSERT(!rgnav::findPortHolder({"127.0.0.1", socket.port}));
    CPPUNIT_ASSERT(!rgnav::groupListensOn(::getpid(), socket.port));
  }

  void ownershipIsReadOncePerProcess() {
    std::optional<LoopbackSocket> socket(std::in_place, true);
    rgnav::PortOwnership owner(socket->port);
    CPPUNIT_ASSERT(!owner.heldBy(::getppid()));
    CPPUNIT_ASSERT(owner.heldBy(::getpid()));
    socket.reset();  // the socket closes: the process's ownership stands until forgotten
    CPPUNIT_ASSERT(owner.heldBy(::getpid()));
    owner.forget();
    CPPUNIT_ASSERT(!owner.heldBy(::getpid()));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PortHolderTest);
