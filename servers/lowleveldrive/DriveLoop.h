// DriveLoop: the LowLevelDrive module's work behind its servant (thesis 5.5.3): the core
// LowLevelDrive run by a control thread at its configured period (20 Hz), on a steady-clock
// schedule (sleep_until; a tick that overruns its slot makes the loop skip the slots it missed,
// it never bunches ticks up). Each tick reads the newest odometry reading from the Base
// (odometrySince, the latest of those after the last one seen), lets the drive compute its
// command and sends it with Base::setVelocity while the drive is not idle, plus one zero command
// when it becomes idle; an idle drive sends nothing (so a Base that refuses commands, the demo's
// tour, sees none). Safety: a Base that does not answer within the tick's short call budget is an
// odometry lapse for the drive, which brakes; the Base's own command timeout (0.5 s in the
// simulator) stops the robot if this process dies.
// setChain is idempotent on the chain ID: the chain accepted last, sent again, changes nothing.
// Health (ModuleHealth counters): loop_period_last_us, loop_period_p99_us, drive_state
// (LowLevelDrive.idl's DriveState order), commands_sent, chains_accepted, loop_ticks; a Base that
// fails is the error of source "base_odometry" or "base_commands" until it answers again, logged
// once per change, never per tick.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "clientlibs/base/BaseClient.h"
#include "clientlibs/lowleveldrive/DriveReport.h"
#include "core/nav/motion/LowLevelDrive.h"
#include "servers/common/ModuleHealth.h"
#include "servers/lowleveldrive/LoopPeriods.h"

namespace rgnav {

class DriveLoop {
 public:
  // `baseSettings`: how to reach the Base; the loop bounds its calls to fit a tick.
  DriveLoop(const LowLevelDriveConfig& config, ClientSettings baseSettings, const std::string& baseObject,
            ModuleHealth& health);
  ~DriveLoop();
  DriveLoop(const DriveLoop&) = delete;
  DriveLoop& operator=(const DriveLoop&) = delete;

  void start();
  // Ends the control thread; a robot still commanded gets one zero command.
  void stop();

  // As LowLevelDrive::setChain, idempotent on the ID (see above).
  void setChain(const DriveChain& chain);
  // LowLevelDrive::stop: brakes to a standstill.
  void brake();
  DriveReport report();
  const MotionLimits& limits() const { return config_.limits; }

 private:
  void run();
  void tick(std::chrono::steady_clock::time_point start);
  // The newest reading the Base has (or the last one seen, if it has none newer or fails).
  std::optional<OdometryReading> newestOdometry();
  void send(const VelocityCommand& command);
  // Logs and records a Base call's failure (`error`), or its recovery (""), once per change.
  void baseResult(const char* source, std::string& lastError, const std::string& error);

  const LowLevelDriveConfig config_;
  ModuleHealth& health_;
  BaseClient base_;  // used by the control thread only

  std::mutex mutex_;  // guards the drive, the accepted chain and the statistics
  LowLevelDrive drive_;
  std::optional<DriveChain> accepted_;
  LoopPeriods periods_;
  std::uint64_t commandsSent_ = 0;
  std::uint64_t chainsAccepted_ = 0;

  // Control thread only.
  std::optional<OdometryReading> latest_;
  bool commanding_ = false;  // the last tick sent a command
  std::string odometryError_;  // the last failure of the odometry calls ("" while they answer)
  std::string commandError_;   // the same for the velocity commands

  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace rgnav
