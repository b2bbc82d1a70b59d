// PortHolder: which process listens on a TCP port of this host, read from /proc/net/tcp and
// /proc/net/tcp6 (the listening sockets' inodes) and /proc/<pid>/fd (who has them open). The
// watchdog uses it to accept a ping answer only from the module it started (a port clash with
// another set otherwise looks like a healthy module), and rgnav-ctl to name who holds a set's port.
#pragma once

#include <sys/types.h>

#include <optional>
#include <string>

#include "core/common/HostPort.h"

namespace rgnav {

struct PortHolder {
  pid_t pid = 0;        // 0: a socket listens, but its process is not visible (another user's)
  std::string command;  // its command line, space-separated; empty if pid is 0
};

// The process listening on the endpoint: on its port at its IPv4 address or at the wildcard
// address (any address if the host is not an IPv4 address); nullopt if nobody listens there.
std::optional<PortHolder> findPortHolder(const HostPort& endpoint);

// True if a process of the process group led by `leader` (a supervised module leads its own)
// listens on `port`, at any local address.
bool groupListensOn(pid_t leader, int port);

// Whether a module's process group listens on the module's port, read from /proc once per
// process: a module keeps its listening socket for its life, and reading /proc/net/tcp and every
// process's fds at every heartbeat cost the watchdog a third of a core on a host with many
// sockets. forget() (after a missed ping) makes the next call read /proc again. One module's
// pings call it from one thread; it is not for sharing between threads.
class PortOwnership {
 public:
  explicit PortOwnership(int port) : port_(port) {}
  // groupListensOn(leader, port), taken from the last call that found it true for `leader`.
  bool heldBy(pid_t leader);
  void forget() { verified_ = 0; }

 private:
  int port_;
  pid_t verified_ = 0;
};

// The command line of a process, its arguments joined by spaces; empty if it is gone.
std::string commandLineOf(pid_t pid);

}  // namespace rgnav
