// LowLevelDriveClient: the LowLevelDrive module (idl/LowLevelDrive.idl): hand it a chain of
// trajectory segments, stop it, read its drive status and its motion limits. Every call is
// idempotent (setChain on the chain's ID) and retried as every client's (ClientConnection.h).
// Errors: BadArgumentError naming "chain" for a chain the module refuses, ModuleFailedError,
// ModuleUnavailableError.
#pragma once

#include "LowLevelDrive.hh"
#include "clientlibs/common/ModuleClient.h"
#include "clientlibs/lowleveldrive/DriveReport.h"
#include "core/nav/motion/DriveChain.h"
#include "core/nav/motion/MotionLimits.h"

namespace rgnav {

class LowLevelDriveClient : public ModuleClientOf<RGNav::LowLevelDrive> {
 public:
  explicit LowLevelDriveClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                               std::string objectName = "LowLevelDrive");

  void setChain(const DriveChain& chain);
  void stop();
  DriveReport driveStatus();
  MotionLimits limits();
};

}  // namespace rgnav
