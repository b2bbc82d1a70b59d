// Killing the PathPlanning module during a request (issue "Path planning", last acceptance
// bullet): the module is stopped (SIGSTOP), a plan request is sent, and once its bytes wait in the
// module's socket it is killed (SIGKILL; the line printed says whether it was, or whether the
// watchdog killed the stopped module as hung first); the watchdog restarts it and the client's
// own retry gets the plan from the restarted module: under the next ID (the numbering resumed from
// the checkpoint, no ID given twice) and with the targets the same request got before the kill (a
// plan depends only on its arguments and the map revision). The restarted module serves the plans
// made before the kill by ID, bit for bit. Killed again right after answering, the module answers
// a repeated request ID with the plan it made for it (same ID), not with a new one.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <set>
#include <sstream>

#include "clientlibs/pathplanning/PathPlanningClient.h"
#include "core/nav/planning/testing/SamePlan.h"
#include "tests/integration/IntegrationHelpers.h"
#include "tests/integration/PlanningSet.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

const Pose2D kHallway{1.0, 1.0, 0.0};

// The inodes of this process's sockets.
std::set<std::string> ownSocketInodes() {
  std::set<std::string> out;
  for (const auto& fd : std::filesystem::directory_iterator("/proc/self/fd")) {
    std::error_code error;
    const std::string target = std::filesystem::read_symlink(fd.path(), error).string();
    if (!error && target.rfind("socket:[", 0) == 0) out.insert(target.substr(8, target.size() - 9));
  }
  return out;
}

struct TcpEntry {
  unsigned localPort = 0, remotePort = 0;
  unsigned long rxQueue = 0;
  std::string inode;
};

std::vector<TcpEntry> tcpEntries() {
  std::ifstream in("/proc/net/tcp");
  std::string line;
  std::getline(in, line);  // header
  std::vector<TcpEntry> out;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string slot, local, remote, state, queues, timer, retransmits, uid, timeout, inode;
    fields >> slot >> local >> remote >> state >> queues >> timer >> retransmits >> uid >> timeout >> inode;
    TcpEntry e;
    e.localPort = std::stoul(local.substr(local.find(':') + 1), nullptr, 16);
    e.remotePort = std::stoul(remote.substr(remote.find(':') + 1), nullptr, 16);
    e.rxQueue = std::stoul(queues.substr(queues.find(':') + 1), nullptr, 16);
    e.inode = inode;
    out.push_back(e);
  }
  return out;
}

// Bytes this process sent to the server on `port` that wait unread in the server's socket.
unsigned long bytesWaitingAtServer(unsigned port) {
  const std::set<std::string> own = ownSocketInodes();
  const std::vector<TcpEntry> entries = tcpEntries();
  unsigned long waiting = 0;
  for (const TcpEntry& ours : entries) {
    if (ours.remotePort != port || !own.count(ours.inode)) continue;
    for (const TcpEntry& theirs : entries)
      if (theirs.localPort == port && theirs.remotePort == ours.localPort) waiting += theirs.rxQueue;
  }
  return waiting;
}

}  // namespace

class PathPlanningKillTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PathPlanningKillTest);
  CPPUNIT_TEST(retryAfterKillGetsTheSamePlan);
  CPPUNIT_TEST_SUITE_END();

 public:
  void retryAfterKillGetsTheSamePlan() {
    PlanningSet set(kFastBackoff);
    TestCluster& cluster = set.cluster();
    cluster.start();
    ClientSettings settings = cluster.clientSettings();
    settings.retryBudget = std::chrono::seconds(30);
    PathPlanningClient planning(settings);
    const PlanRecord toRoom1 = planning.plan(kHallway, PlanGoal::at({4.0, 4.0}));
    const PlanRecord toRoom2 = planning.plan(kHallway, PlanGoal::at({9.0, 4.0}));
    CPPUNIT_ASSERT_EQUAL(PlanId(2), toRoom2.id);

    // A request in flight when the module dies: sent to the stopped module, which is then killed.
    const ModuleProcessInfo before = cluster.describe("PathPlanning");
    const unsigned port = static_cast<unsigned>(cluster.modulePort("PathPlanning"));
    CPPUNIT_ASSERT_EQUAL(0, ::kill(static_cast<pid_t>(before.pid), SIGSTOP));
    const std::uint64_t request = 0x5eed0000beef0001ULL;
    std::future<PlanRecord> inFlight = std::async(std::launch::async, [&] {
      PathPlanningClient retrying(settings);
      return retrying.plan(kHallway, PlanGoal::at({9.0, 4.0}), request);
    });
    // The watchdog kills a module that stops answering its pings (hung) within a second; should it
    // do so before the request arrives, the retry still meets a restarted module, and it says so.
    bool queued = false;
    waitUntil(
        [&] {
          queued = bytesWaitingAtServer(port) > 0;
          return queued || cluster.describe("PathPlanning").pid != before.pid;
        },
        "the plan request to wait in the stopped module's socket");
    CPPUNIT_ASSERT(::kill(static_cast<pid_t>(before.pid), SIGKILL) == 0 || errno == ESRCH);
    const PlanRecord retried = inFlight.get();
    const ModuleProcessInfo after = cluster.waitFor("PathPlanning", runningAgainAfter(before.pid), "a restart");
    CPPUNIT_ASSERT(after.restarts > before.restarts);
    std::printf("\nplan request %s at SIGKILL of pid %lld: answered by pid %lld as plan %llu, %zu targets, %.3f m\n",
                queued ? "waiting in the module's socket" : "not yet sent (the watchdog killed the module first)",
                static_cast<long long>(before.pid), static_cast<long long>(after.pid),
                static_cast<unsigned long long>(retried.id), retried.plan.targets.size(), retried.plan.lengthM);
    CPPUNIT_ASSERT_EQUAL(PlanId(3), retried.id);
    CPPUNIT_ASSERT_EQUAL(request, retried.request);
    PlanRecord expected = toRoom2;  // the same arguments on the same map: the same plan, numbered on
    expected.id = 3;
    expected.request = request;
    CPPUNIT_ASSERT_EQUAL(std::string(), planDifference(expected, retried));
    CPPUNIT_ASSERT_EQUAL(std::string(), planDifference(toRoom1, planning.planById(1)));
    CPPUNIT_ASSERT_EQUAL(std::string(), planDifference(toRoom2, planning.planById(2)));
    CPPUNIT_ASSERT_EQUAL(std::string(), planDifference(retried, planning.lastPlan()));

    // An answer lost with the module: the module killed right after answering, the request asked again.
    CPPUNIT_ASSERT_EQUAL(0, ::kill(static_cast<pid_t>(after.pid), SIGKILL));
    cluster.waitFor("PathPlanning", runningAgainAfter(after.pid), "a second restart");
    CPPUNIT_ASSERT_EQUAL(std::string(), planDifference(retried, planning.plan(kHallway, PlanGoal::at({9.0, 4.0}), request)));
    CPPUNIT_ASSERT_EQUAL(std::string(),
                         planDifference(toRoom2, planning.plan(kHallway, PlanGoal::at({9.0, 4.0}), toRoom2.request)));
    CPPUNIT_ASSERT_EQUAL(PlanId(4), planning.plan(kHallway, PlanGoal::at({4.0, 4.0})).id);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PathPlanningKillTest);
