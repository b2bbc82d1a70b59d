// Listening sockets and their processes from /proc (see PortHolder.h).
#include "watchdog/PortHolder.h"

#include <arpa/inet.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>
#include <vector>

#include "watchdog/ProcStat.h"

namespace rgnav {

namespace fs = std::filesystem;

namespace {

constexpr const char* kListen = "0A";  // TCP_LISTEN in the "st" column

constexpr const char* kAnyAddress = "00000000";

// The address of a host as /proc/net/tcp writes it (the 32 bits of the in_addr as hex in the
// machine's byte order); nullopt for a host that is not an IPv4 address.
std::optional<std::string> procAddressOf(const std::string& host) {
  in_addr address{};
  if (::inet_pton(AF_INET, host.c_str(), &address) != 1) return std::nullopt;
  char text[9];
  std::snprintf(text, sizeof text, "%08X", address.s_addr);
  return std::string(text);
}

// The inodes of the sockets listening on `port`, as "socket:[<inode>]" (the fd link text): at
// `address` (and the wildcard address) if given, else at any address.
std::set<std::string> listeningSockets(int port, const std::optional<std::string>& address = std::nullopt) {
  std::set<std::string> sockets;
  for (const char* table : {"/proc/net/tcp", "/proc/net/tcp6"}) {
    std::ifstream in(table);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      std::string slot, local, remote, state, queues, timer, retransmits, uid, timeout, inode;
      if (!(fields >> slot >> local >> remote >> state >> queues >> timer >> retransmits >> uid >> timeout >> inode))
        continue;
      const std::size_t colon = local.rfind(':');
      if (state != kListen || colon == std::string::npos || inode == "0") continue;
      const std::string at = local.substr(0, colon);
      const bool anywhere = at.find_first_not_of('0') == std::string::npos;  // IPv4 or IPv6 wildcard
      if (address && !anywhere && at != *address) continue;
      if (std::stoi(local.substr(colon + 1), nullptr, 16) == port) sockets.insert("socket:[" + inode + "]");
    }
  }
  return sockets;
}

bool hasOpen(pid_t pid, const std::set<std::string>& sockets) {
  std::error_code ec;
  for (fs::directory_iterator fd("/proc/" + std::to_string(pid) + "/fd", ec), end; !ec && fd != end;
       fd.increment(ec)) {
    std::error_code linkError;
    const fs::path target = fs::read_symlink(fd->path(), linkError);
    if (!linkError && sockets.count(target.string())) return true;
  }
  return false;
}

std::vector<pid_t> processes() {
  std::vector<pid_t> pids;
  std::error_code ec;
  for (fs::directory_iterator entry("/proc", ec), end; !ec && entry != end; entry.increment(ec)) {
    const std::string name = entry->path().filename().string();
    if (!name.empty() && std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; }))
      pids.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return pids;
}

}  // namespace

std::optional<PortHolder> findPortHolder(const HostPort& endpoint) {
  const std::set<std::string> sockets = listeningSockets(endpoint.port, procAddressOf(endpoint.host));
  if (sockets.empty()) return std::nullopt;
  for (const pid_t pid : processes())
    if (hasOpen(pid, sockets)) return PortHolder{pid, commandLineOf(pid)};
  return PortHolder{};
}

bool groupListensOn(pid_t leader, int port) {
  const std::set<std::string> sockets = listeningSockets(port);
  if (sockets.empty()) return false;
  if (hasOpen(leader, sockets)) return true;
  for (const pid_t pid : processes()) {
    if (pid == leader) continue;
    const std::optional<ProcStat> stat = readProcStat(pid);
    if (stat && stat->group == leader && hasOpen(pid, sockets)) return true;
  }
  return false;
}

bool PortOwnership::heldBy(pid_t leader) {
  if (leader != 0 && leader == verified_) return true;
  verified_ = groupListensOn(leader, port_) ? leader : 0;
  return verified_ != 0;
}

std::string commandLineOf(pid_t pid) {
  std::string text = readProcFile(pid, "cmdline");
  while (!text.empty() && text.back() == '\0') text.pop_back();
  std::replace(text.begin(), text.end(), '\0', ' ');
  return text;
}

}  // namespace rgnav
