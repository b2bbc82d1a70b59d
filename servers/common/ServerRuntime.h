// ServerRuntime: everything a module server needs around its servants (DESIGN.md, issue
// "Foundation"): command-line options, ORB initialization with a fixed endpoint and server-side
// call limits, servants on the persistent INS POA under fixed object IDs (references stay valid
// across restarts and are reachable as corbaloc::host:port/<Object>), registration as
// RGNav/<robot>/<Object> with rebind at every start and re-registration whenever the naming
// service lost it, and a clean exit on SIGTERM/SIGINT or a shutdown() call (names unbound, exit 0).
#pragma once

#include <omniORB4/CORBA.h>

#include <boost/program_options.hpp>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "clientlibs/common/ClientSettings.h"
#include "core/common/HostPort.h"
#include "servers/common/ModuleHealth.h"

namespace rgnav {

struct ServerOptions {
  std::string module;           // module name in the set (for logs and status)
  std::string robot = "tumbot";
  HostPort endpoint;            // fixed address this server listens on and publishes
  HostPort naming;              // naming service
  std::string stateDir;         // where the module may checkpoint state
  int callLimitMs = 5000;       // server side: limit on receiving/sending one call
};

class ServerRuntime {
 public:
  // Parses the common options and the module's own; throws ConfigError on bad options.
  ServerRuntime(int argc, char** argv, const boost::program_options::options_description& moduleOptions);
  ~ServerRuntime();
  ServerRuntime(const ServerRuntime&) = delete;
  ServerRuntime& operator=(const ServerRuntime&) = delete;

  const boost::program_options::variables_map& options() const { return options_; }
  const ServerOptions& server() const { return server_; }
  ModuleHealth& health() { return health_; }
  CORBA::ORB_ptr orb() const { return orb_.in(); }
  // Settings for client libraries this server uses to reach other modules.
  ClientSettings clientSettings() const;

  // Activates a servant (created with new; the POA takes ownership) under the fixed object ID
  // objectId and registers it as RGNav/<robot>/<boundName> (boundName defaults to objectId).
  void activate(const std::string& objectId, PortableServer::ServantBase* servant, const std::string& boundName = "");

  // Runs `hook` when a stop was requested, before the names are unbound (calls are still
  // served meanwhile, so a hook may take its time).
  void onShutdown(std::function<void()> hook) { shutdownHooks_.push_back(std::move(hook)); }

  // Serves until SIGTERM/SIGINT or requestShutdown(); unbinds the names; returns 0.
  int run();
  void requestShutdown();

 private:
  void keepRegistered();
  bool registerAll();
  void unregisterAll();

  boost::program_options::variables_map options_;
  ServerOptions server_;
  ModuleHealth health_;
  CORBA::ORB_var orb_;
  PortableServer::POA_var poa_;
  std::vector<std::pair<std::string, CORBA::Object_var>> objects_;  // bound name, reference
  std::vector<std::function<void()>> shutdownHooks_;

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread registrar_;
};

// Runs a server's main: builds the runtime, lets setup() create and activate servants, serves.
// Any error before serving is printed as "<program>: <message>" and gives exit code 2.
int runServer(int argc, char** argv, const boost::program_options::options_description& moduleOptions,
              const std::function<void(ServerRuntime&)>& setup);

}  // namespace rgnav
