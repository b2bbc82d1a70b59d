// rgnav-bench-middleware: figures of the component framework, measured on a real server set:
//   ping_us           median round trip of Service::ping through the client library
//   scan_fetch_ratio  median time to fetch one scan by ID through LaserClient (conversion
//                     included) / median time of a bare omniORB call returning as many bytes as
//                     that scan marshals to, in the same run, same machine
//   restart_p95_s     SIGKILL of the playback server until the client library gets an answer
//   hang_detect_s     worst time from SIGSTOP until the watchdog declares the module hung
//   restarts, hangs   SIGKILL restarts and SIGSTOP hangs timed (as many as asked for)
//   scan_bytes        what one scan marshals to (the size the ratio compares at)
// Last line: middleware: ping_us=… scan_fetch_ratio=… restart_p95_s=… hang_detect_s=… restarts=…
//   hangs=… scan_bytes=…
#include <omniORB4/CORBA.h>
#include <sched.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "Echo.hh"
#include "clientlibs/common/ClientOrb.h"
#include "clientlibs/common/convert.h"
#include "clientlibs/laser/LaserClient.h"
#include "tests/support/WaitUntil.h"
#include "tests/support/cluster/Interruption.h"
#include "tests/support/cluster/TestCluster.h"
#include "watchdog/Spawn.h"
#include "tools/common/CommandLine.h"
#include "tests/support/Statistics.h"

namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;
using Clock = std::chrono::steady_clock;

namespace {

// Seconds one call of f takes.
template <class F>
double timed(F&& f) {
  const auto start = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Bytes one scan occupies in GIOP (CDR) encoding.
CORBA::ULong marshalledSize(const LaserScan& scan) {
  cdrMemoryStream stream;
  toIdl(scan) >>= stream;
  return static_cast<CORBA::ULong>(stream.bufSize());
}

bool running(const ModuleProcessInfo& m) { return m.state == ProcessState::Running; }

// Puts every thread of a process on the given CPUs. Client and both servers share CPU 0 while call
// latencies are compared, so that neither side of the ratio gets cheaper or dearer wake-ups
// from the scheduler's placement (on two cores that alone moved a call between 20 and 57 us).
void setAffinity(pid_t pid, const cpu_set_t& cpus) {
  for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/task"))
    sched_setaffinity(std::stoi(task.path().filename().string()), sizeof cpus, &cpus);
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 7, calls = 2000, restarts = 20, hangs = 5;
  po::options_description desc("rgnav-bench-middleware [options]");
  desc.add_options()
      ("help", "this text")
      ("rounds", po::value(&rounds)->default_value(rounds), "timing rounds")
      ("calls", po::value(&calls)->default_value(calls), "calls of each kind per round")
      ("restarts", po::value(&restarts)->default_value(restarts), "SIGKILL restarts to time")
      ("hangs", po::value(&hangs)->default_value(hangs), "SIGSTOP hangs to time");
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc)) return 0;
    catchInterruptions();  // a stopped run still shuts its server set down and removes its directory

    TestCluster cluster({{"LogPlayback",
                          {TestCluster::program("rgnav-carmen-playback"), "--log",
                           TestCluster::shared("data/laser/corrected/intel-corrected.log.gz"), "--speed", "max"},
                          {"Laser", "Base"}, {}, "max_restarts: 1000"}});
    cluster.start();

    const int echoPort = freeLoopbackPort();
    SpawnSpec echoSpec;
    echoSpec.argv = {TestCluster::program("rgnav-bench-echo"), "--module", "Echo", "--endpoint",
                     "127.0.0.1:" + std::to_string(echoPort), "--naming",
                     "127.0.0.1:" + std::to_string(cluster.namingPort())};
    echoSpec.logFile = cluster.dir() + "/echo.log";
    echoSpec.parentDeathSignal = SIGTERM;
    const pid_t echoPid = spawnProcess(echoSpec);

    ClientSettings settings = cluster.clientSettings();
    settings.backoffInitial = std::chrono::milliseconds(2);
    settings.backoffMax = std::chrono::milliseconds(10);
    LaserClient laser(settings);
    const DataId scans = std::max<DataId>(1, laser.scansSince(0, 1000).latestId);
    const CORBA::ULong bytes = marshalledSize(laser.scan(1));

    CORBA::Object_var echoObj = processOrb(settings)->string_to_object(
        ("corbaloc::127.0.0.1:" + std::to_string(echoPort) + "/Echo").c_str());
    RGNavBench::Echo_var echo = RGNavBench::Echo::_narrow(echoObj);
    omniORB::setClientCallTimeout(echo, static_cast<CORBA::ULong>(settings.callTimeout.count()));
    const bool echoAnswers = pollUntil(  // the echo server may still be starting
        [&] {
          try {
            RGNavBench::Bytes_var warm = echo->fetch(bytes);
            return true;
          } catch (const CORBA::TRANSIENT&) {
            return false;
          }
        },
        std::chrono::seconds(20), std::chrono::milliseconds(10));
    if (!echoAnswers) throw std::runtime_error("the echo server did not answer");

    cpu_set_t allCpus, cpu0;
    sched_getaffinity(0, sizeof allCpus, &allCpus);
    CPU_ZERO(&cpu0);
    CPU_SET(0, &cpu0);
    for (pid_t pid : {::getpid(), echoPid, static_cast<pid_t>(cluster.describe("LogPlayback").pid)}) setAffinity(pid, cpu0);
    // Calls alternate one by one, so both kinds meet the same scheduler and cache conditions.
    std::vector<double> fetchTimes, echoTimes, pingTimes;
    for (int i = 0; i < rounds * calls; ++i) {
      throwIfInterrupted();
      fetchTimes.push_back(timed([&] { laser.scan(1 + DataId(i) % scans); }));
      echoTimes.push_back(timed([&] { RGNavBench::Bytes_var b = echo->fetch(bytes); }));
      pingTimes.push_back(timed([&] { laser.ping(); }));
    }

    setAffinity(::getpid(), allCpus);

    std::vector<double> restartTimes;
    for (int i = 0; i < restarts; ++i) {
      const auto victim = cluster.waitFor("LogPlayback", running, "running");
      const auto killed = Clock::now();
      ::kill(static_cast<pid_t>(victim.pid), SIGKILL);
      laser.latestId();
      restartTimes.push_back(std::chrono::duration<double>(Clock::now() - killed).count());
      cluster.waitFor("LogPlayback", [&](const ModuleProcessInfo& m) { return running(m) && m.pid != victim.pid; },
                      "running again");
    }

    std::vector<double> hangTimes;
    for (int i = 0; i < hangs; ++i) {
      const auto victim = cluster.waitFor("LogPlayback", running, "running");
      std::this_thread::sleep_for(std::chrono::milliseconds(150));  // a random phase of the heartbeat
      const auto stopped = Clock::now();
      ::kill(static_cast<pid_t>(victim.pid), SIGSTOP);
      cluster.waitFor("LogPlayback", [&](const ModuleProcessInfo& m) { return m.pid != victim.pid || m.state == ProcessState::Hung; },
                      "found hung", std::chrono::seconds(10));
      hangTimes.push_back(std::chrono::duration<double>(Clock::now() - stopped).count());
    }
    ::kill(echoPid, SIGTERM);

    const double ratio = median(fetchTimes) / median(echoTimes);
    std::printf("scan fetch: %.1f us per scan (%u bytes), bare omniORB call of the same size: %.1f us\n",
                median(fetchTimes) * 1e6, bytes, median(echoTimes) * 1e6);
    std::printf("restarts: %d, median %.3f s, max %.3f s; hangs: %d, median %.3f s\n", restarts,
                median(restartTimes), percentile(restartTimes, 1.0), hangs, median(hangTimes));
    std::printf("middleware: ping_us=%.1f scan_fetch_ratio=%.2f restart_p95_s=%.3f hang_detect_s=%.3f restarts=%zu "
                "hangs=%zu scan_bytes=%u\n",
                median(pingTimes) * 1e6, ratio, percentile(restartTimes, 0.95), percentile(hangTimes, 1.0),
                restartTimes.size(), hangTimes.size(), static_cast<unsigned>(bytes));
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-bench-middleware: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-bench-middleware: " << e.what() << std::endl;
  } catch (const CORBA::Exception& e) {
    std::cerr << "rgnav-bench-middleware: CORBA " << e._name() << std::endl;
  }
  return 2;
}
