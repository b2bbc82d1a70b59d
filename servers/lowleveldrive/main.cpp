// rgnav-lowleveldrive: the LowLevelDrive module (thesis 5.5.3): drives the robot along the chains
// of trajectory segments the Collision Avoidance sends, with Kanayama's Lyapunov-stable tracking
// law at 20 Hz on the Base's odometry, commanding Base::setVelocity; it stops the robot at a
// chain's end and brakes when its odometry lapses. It keeps no state over a restart: a restarted
// drive is idle until it gets the next chain (the Base's command timeout stopped the robot).
#include <iostream>

#include "core/nav/motion/LowLevelDriveConfigYaml.h"
#include "servers/lowleveldrive/LowLevelDriveImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  std::string baseObject, objectName, configFile;
  po::options_description options("LowLevelDrive options");
  options.add_options()
      ("base-object", po::value(&baseObject)->default_value("Base"), "Base module to read odometry from and command")
      ("object", po::value(&objectName)->default_value("LowLevelDrive"), "object name of the interface")
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/lowleveldrive.yaml)");
  std::unique_ptr<DriveLoop> loop;
  const int code = runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const LowLevelDriveConfig config = loadLowLevelDriveConfig(configFile);
    ClientSettings settings = runtime.clientSettings();
    loop = std::make_unique<DriveLoop>(config, settings, baseObject, runtime.health());
    runtime.activate(objectName, new LowLevelDriveImpl(runtime, *loop));
    loop->start();
    runtime.onShutdown([&] { loop->stop(); });
    std::cerr << "low-level drive on " << baseObject << " every " << config.periodSeconds * 1000 << " ms, serving on "
              << runtime.server().endpoint.str() << std::endl;
  });
  if (loop) loop->stop();
  return code;
}
