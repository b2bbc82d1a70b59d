// LowLevelDriveImpl: the LowLevelDrive.idl servant: check and convert in, drive loop call,
// convert out. A chain the core refuses (invalid or disjoint segments, an ID not above the last,
// a start speed the limits cannot brake) becomes InvalidArgument naming "chain".
#pragma once

#include "LowLevelDrive.hh"
#include "servers/common/ServiceServant.h"
#include "servers/lowleveldrive/DriveLoop.h"

namespace rgnav {

class LowLevelDriveImpl : public ServiceServant<POA_RGNav::LowLevelDrive> {
 public:
  LowLevelDriveImpl(ServerRuntime& runtime, DriveLoop& loop);

  void setChain(const RGNav::DriveChain& chain) override;
  void stop() override;
  RGNav::DriveReport driveStatus() override;
  RGNav::MotionLimits limits() override;

 private:
  DriveLoop& loop_;
};

}  // namespace rgnav
