// DriveReport: the plain C++ form of the LowLevelDrive module's driveStatus() (LowLevelDrive.idl):
// the core drive's status and the module's control loop around it (real periods, commands sent).
// Shared by the server that reports it and the clients that read it.
#pragma once

#include <cstdint>

#include "core/nav/motion/LowLevelDrive.h"

namespace rgnav {

struct DriveReport {
  DriveStatus drive;
  double loopPeriodLastSeconds = 0.0;  // the control loop's last real period
  double loopPeriodP99Seconds = 0.0;   // its 99th percentile over the recent window
  std::uint64_t commandsSent = 0;      // velocity commands sent to the Base
};

}  // namespace rgnav
