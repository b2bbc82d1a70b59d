// The server runtime (see ServerRuntime.h).
#include "servers/common/ServerRuntime.h"

#include <omniORB4/Naming.hh>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "clientlibs/common/ClientOrb.h"
#include "core/common/Errors.h"

namespace po = boost::program_options;

namespace rgnav {

namespace {

constexpr auto kRegistrationCheck = std::chrono::milliseconds(1000);
// After a failure: the first call to a restarted naming service fails on the old connection,
// the next one opens a new connection.
constexpr auto kRegistrationRetry = std::chrono::milliseconds(100);

sigset_t terminationSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGHUP);
  return set;
}

CosNaming::NamingContext_ptr childContext(CosNaming::NamingContext_ptr parent, const std::string& id) {
  CosNaming::Name name;
  name.length(1);
  name[0].id = id.c_str();
  try {
    return parent->bind_new_context(name);
  } catch (const CosNaming::NamingContext::AlreadyBound&) {
    CORBA::Object_var obj = parent->resolve(name);
    return CosNaming::NamingContext::_narrow(obj);
  }
}

CosNaming::Name leafName(const std::string& id) {
  CosNaming::Name name;
  name.length(1);
  name[0].id = id.c_str();
  return name;
}

}  // namespace

ServerRuntime::ServerRuntime(int argc, char** argv, const po::options_description& moduleOptions)
{
  const sigset_t signals = terminationSignals();
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);  // before the ORB starts threads

  std::string endpoint, naming;
  po::options_description common("Common server options");
  common.add_options()
      ("module", po::value(&server_.module)->required(), "module name in the server set")
      ("robot", po::value(&server_.robot)->default_value("tumbot"), "robot name: naming context RGNav/<robot>")
      ("endpoint", po::value(&endpoint)->required(), "fixed host:port to listen on and publish")
      ("naming", po::value(&naming)->required(), "naming service host:port")
      ("state-dir", po::value(&server_.stateDir)->default_value(""), "directory for checkpoints")
      ("call-limit-ms", po::value(&server_.callLimitMs)->default_value(5000), "server-side limit per call");
  po::options_description all;
  all.add(common).add(moduleOptions);
  try {
    po::store(po::parse_command_line(argc, argv, all), options_);
    po::notify(options_);
  } catch (const po::error& e) {
    throw ConfigError(std::string(e.what()) + "\n" + [&] {
      std::ostringstream help;
      help << all;
      return help.str();
    }());
  }
  server_.endpoint = parseHostPort(endpoint);
  server_.naming = parseHostPort(naming);
  if (!server_.stateDir.empty()) std::filesystem::create_directories(server_.stateDir);
  health_.setName(server_.module);

  orb_ = CORBA::ORB::_duplicate(processOrb(
      clientSettings(), {"-ORBendPoint", "giop:tcp:" + server_.endpoint.str(), "-ORBserverCallTimeOutPeriod",
                         std::to_string(server_.callLimitMs)}));
  CORBA::Object_var poaObj = orb_->resolve_initial_references("omniINSPOA");
  poa_ = PortableServer::POA::_narrow(poaObj);
  PortableServer::POAManager_var manager = poa_->the_POAManager();
  manager->activate();
}

ServerRuntime::~ServerRuntime() {
  requestShutdown();
  if (registrar_.joinable()) registrar_.join();
  if (!CORBA::is_nil(orb_)) orb_->destroy();
}

ClientSettings ServerRuntime::clientSettings() const {
  ClientSettings settings;
  settings.namingHost = server_.naming.host;
  settings.namingPort = server_.naming.port;
  settings.robot = server_.robot;
  settings.consumer = server_.module;
  return settings;
}

void ServerRuntime::activate(const std::string& objectId, PortableServer::ServantBase* servant,
                             const std::string& boundName) {
  PortableServer::ObjectId_var id = PortableServer::string_to_ObjectId(objectId.c_str());
  poa_->activate_object_with_id(id, servant);
  servant->_remove_ref();
  CORBA::Object_var ref = poa_->id_to_reference(id);
  objects_.emplace_back(boundName.empty() ? objectId : boundName, ref);
}

bool ServerRuntime::registerAll() {
  try {
    CORBA::Object_var obj = orb_->resolve_initial_references("NameService");
    omniORB::setClientCallTimeout(obj, 1000);
    CosNaming::NamingContext_var root = CosNaming::NamingContext::_narrow(obj);
    CosNaming::NamingContext_var rgnav = childContext(root, "RGNav");
    CosNaming::NamingContext_var robot = childContext(rgnav, server_.robot);
    for (auto& [name, ref] : objects_) {
      bool current = false;
      try {
        CORBA::Object_var bound = robot->resolve(leafName(name));
        current = bound->_is_equivalent(ref);
      } catch (const CosNaming::NamingContext::NotFound&) {
      }
      if (!current) robot->rebind(leafName(name), ref);
    }
    health_.clearError("naming");
    return true;
  } catch (const CORBA::Exception& e) {
    health_.setError("naming", std::string("cannot register: ") + e._name());
    return false;
  }
}

void ServerRuntime::unregisterAll() {
  try {
    CORBA::Object_var obj = orb_->resolve_initial_references("NameService");
    omniORB::setClientCallTimeout(obj, 1000);
    CosNaming::NamingContext_var root = CosNaming::NamingContext::_narrow(obj);
    for (auto& [name, ref] : objects_) {
      CosNaming::Name path;
      path.length(3);
      path[0].id = "RGNav";
      path[1].id = server_.robot.c_str();
      path[2].id = name.c_str();
      try {
        CORBA::Object_var bound = root->resolve(path);
        if (bound->_is_equivalent(ref)) root->unbind(path);
      } catch (const CosNaming::NamingContext::NotFound&) {
      }
    }
  } catch (const CORBA::Exception&) {
    // The naming service is away; a stale name is repaired by the next start's rebind.
  }
}

void ServerRuntime::keepRegistered() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    const bool registered = registerAll();
    lock.lock();
    wake_.wait_for(lock, registered ? kRegistrationCheck : kRegistrationRetry, [&] { return stopping_; });
  }
}

void ServerRuntime::requestShutdown() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
}

int ServerRuntime::run() {
  registrar_ = std::thread([this] { keepRegistered(); });
  health_.setState(ModuleRunState::Running);
  const sigset_t signals = terminationSignals();
  const timespec tick{0, 100'000'000};
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      if (stopping_) break;
    }
    if (sigtimedwait(&signals, nullptr, &tick) > 0) requestShutdown();
  }
  health_.setState(ModuleRunState::Stopping);
  registrar_.join();
  for (auto& hook : shutdownHooks_) hook();
  unregisterAll();
  return 0;
}

int runServer(int argc, char** argv, const po::options_description& moduleOptions,
              const std::function<void(ServerRuntime&)>& setup) {
  const std::string program = std::filesystem::path(argv[0]).filename().string();
  try {
    ServerRuntime runtime(argc, argv, moduleOptions);
    setup(runtime);
    return runtime.run();
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << std::endl;
  } catch (const CORBA::Exception& e) {
    std::cerr << program << ": CORBA " << e._name() << " while starting" << std::endl;
  }
  return 2;
}

}  // namespace rgnav
