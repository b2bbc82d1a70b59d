// rgnav-watchdog: runs and supervises the server set of one host (config/sets/<set>.yaml):
// the naming service if managed, every module in dependency order, heartbeats, restarts. It
// serves Watchdog.idl at its fixed endpoint (corbaloc::host:port/Watchdog) and is bound as
// RGNav/<robot>/Watchdog-<set>. SIGTERM/SIGINT or shutdownSet() stop the set in reverse order;
// SIGKILL leaves the modules running for the next watchdog to adopt (see SupervisedSet.h).
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/common/Errors.h"
#include "servers/common/ServerRuntime.h"
#include "watchdog/CorbaPing.h"
#include "watchdog/PortHolder.h"
#include "watchdog/SetLoading.h"
#include "watchdog/WatchdogImpl.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
namespace fs = std::filesystem;

namespace {

// One watchdog per set: an exclusive lock on run_dir/watchdog.lock held for the process's life.
void lockRunDir(const std::string& runDir) {
  const std::string path = runDir + "/watchdog.lock";
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0 || ::flock(fd, LOCK_EX | LOCK_NB) != 0)
    throw rgnav::Error("another watchdog already runs this set (" + path + " is locked)");
  std::ofstream(runDir + "/watchdog.pid") << ::getpid() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string setFile, root;
  bool printRunDir = false;
  po::options_description desc("rgnav-watchdog --set config/sets/<set>.yaml");
  desc.add_options()
      ("help", "this text")
      ("set", po::value(&setFile)->required(), "server set file")
      ("root", po::value(&root)->default_value(rgnav::defaultProjectRoot()),
       "base for relative run_dir and ${RGNAV_ROOT}")
      ("print-run-dir", po::bool_switch(&printRunDir), "print the set's run directory and exit");
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc)) return 0;
    const rgnav::SetConfig config = rgnav::loadSet(setFile, root);
    if (printRunDir) {
      std::cout << config.runDir << std::endl;
      return 0;
    }
    fs::create_directories(config.runDir + "/logs");
    lockRunDir(config.runDir);

    const std::string endpoint = config.host + ":" + std::to_string(config.watchdog.port);
    const std::string naming = config.naming.host + ":" + std::to_string(config.naming.port);
    std::vector<std::string> args{"rgnav-watchdog", "--module", "Watchdog", "--robot", config.robot,
                                  "--endpoint", endpoint, "--naming", naming};
    std::vector<char*> runtimeArgv;
    for (auto& a : args) runtimeArgv.push_back(a.data());
    const int code = rgnav::runServer(static_cast<int>(runtimeArgv.size()), runtimeArgv.data(), {}, [&](rgnav::ServerRuntime& runtime) {
      const auto timeout =
          std::chrono::duration_cast<std::chrono::milliseconds>(config.watchdog.heartbeatTimeout);
      // A call that opens a connection is bounded by the connect timeout instead of its own, so
      // a probe that reconnects to a hung module must not wait longer than a heartbeat.
      omniORB::setClientConnectTimeout(static_cast<CORBA::ULong>(timeout.count()));
      auto set = std::make_shared<rgnav::SupervisedSet>(
          config, [&runtime, timeout](const rgnav::ModuleSpec& module, const rgnav::HostPort& at) {
            auto probe = std::make_shared<rgnav::CorbaPing>(runtime.orb(), at, module.objects.front(), timeout);
            // Only the process this watchdog started counts: after a port clash the answer would
            // come from somebody else's process.
            auto owner = std::make_shared<rgnav::PortOwnership>(at.port);
            return rgnav::PingThreads::Ping([probe, owner](pid_t pid) {
              if (!owner->heldBy(pid)) return false;
              if (probe->answers()) return true;
              owner->forget();
              return false;
            });
          });
      runtime.activate("Watchdog", new rgnav::WatchdogImpl(runtime, *set), "Watchdog-" + config.name);
      set->start();
      runtime.onShutdown([set] { set->stopAll(); });
    });
    fs::remove(config.runDir + "/watchdog.pid");
    return code;
  } catch (const po::error& e) {
    std::cerr << "rgnav-watchdog: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-watchdog: " << e.what() << std::endl;
  }
  return 2;
}
