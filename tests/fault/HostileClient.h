// HostileClient: a remote caller that calls every operation of every server of the mapping set
// (the simulator's or a log playback's Laser and Base, the simulator's GroundTruth, ScanMapper,
// GatewayDetection, the RG Mapping Kernel, the demo set's PathPlanning, LowLevelDrive and Localization modules and the watchdog) with arguments no well-behaved client sends: NaN and infinite coordinates, IDs 0 and
// 2^64-1, counts of 2^32-1, names with control characters or over the length bound, request ID
// 0, chains of trajectory segments that are not finite, do not join or are too long, initial poses
// and sigmas that are not finite or negative, traversals of gateways that do not exist, merges of a region with itself and with a region that does not exist, undoing merges into
// regions that do not exist, exports to /etc, to
// a directory behind a symbolic link and over a symbolic link, and unknown watchdog modules.
// None of them may change the map: valid names, merges and module control are not among them.
// Calls go over raw IDL (the client libraries check some arguments before sending them) through
// TypedConnection, which retries while a server restarts.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "Base.hh"
#include "GatewayDetection.hh"
#include "GroundTruth.hh"
#include "Laser.hh"
#include "Localization.hh"
#include "LowLevelDrive.hh"
#include "PathPlanning.hh"
#include "RGMappingKernel.hh"
#include "ScanMapper.hh"
#include "Watchdog.hh"
#include "clientlibs/common/ClientConnection.h"

namespace rgnav::testing {

// How the hostile calls ended. typed: a declared IDL exception; unknown: CORBA::UNKNOWN, any
// other system exception that is not a lost connection, or an undeclared user exception;
// unanswered: no answer within the client's retry budget (a hung or dead server).
struct HostileTally {
  std::atomic<std::uint64_t> calls{0}, accepted{0}, invalidArgument{0}, notAvailable{0}, notSupported{0}, failed{0},
      unknown{0}, unanswered{0};

  std::uint64_t typed() const { return invalidArgument + notAvailable + notSupported + failed; }
  void note(const std::string& what);            // keeps the first few unknown or unanswered calls
  std::vector<std::string> notes() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> notes_;
};

// Where the hostile exports aim; every one must be refused or stay inside the export root.
struct ExportTraps {
  std::string linkToOutside;  // a directory name in the export root that is a symbolic link out of it
  std::string linkFile;       // a map name whose <name>.rgmap.json in the export root is a symbolic link
};

// One operation with its hostile arguments.
struct HostileCall {
  std::string what;  // operation(arguments), for the report
  std::function<void()> run;
};

class HostileClient {
 public:
  // One client per thread; `seed` sets where its request IDs and its turn through the calls start,
  // so that threads send the same calls at different times.
  // groundTruth: the set has a simulator, whose GroundTruth object is called too; demoModules:
  // the set has the PathPlanning, LowLevelDrive and Localization modules (the demo set), called too.
  HostileClient(const ClientSettings& settings, const HostPort& watchdog, ExportTraps traps, bool groundTruth,
                bool demoModules, unsigned seed);
  HostileClient(const HostileClient&) = delete;  // its calls refer to its connections
  HostileClient& operator=(const HostileClient&) = delete;

  // Makes the next hostile call (they come in turn) and counts how it ended in `tally`.
  void callNext(HostileTally& tally);
  std::size_t operations() const { return calls_.size(); }

 private:
  void addSensorCalls();
  void addGroundTruthCalls();
  void addScanMapperCalls();
  void addDetectionCalls();
  void addKernelCalls(const ExportTraps& traps);
  void addPathPlanningCalls();
  void addLowLevelDriveCalls();
  void addLocalizationCalls();
  void addWatchdogCalls();
  std::uint64_t requestId() { return ++requests_; }

  TypedConnection<RGNav::Laser> laser_;
  TypedConnection<RGNav::Base> base_;
  TypedConnection<RGNav::GroundTruth> groundTruth_;
  TypedConnection<RGNav::ScanMapper> scanMapper_;
  TypedConnection<RGNav::GatewayDetection> detection_;
  TypedConnection<RGNav::RGMappingKernel> kernel_;
  TypedConnection<RGNav::PathPlanning> planning_;
  TypedConnection<RGNav::LowLevelDrive> drive_;
  TypedConnection<RGNav::Localization> localization_;
  TypedConnection<RGNav::Watchdog> watchdog_;
  std::vector<HostileCall> calls_;
  std::size_t next_ = 0;
  std::uint64_t requests_;
};

}  // namespace rgnav::testing
