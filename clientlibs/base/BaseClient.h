// BaseClient: odometry by ID and by time stamp, and velocity commands (Base.idl).
#pragma once

#include "Base.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/common/DataBuffer.h"

namespace rgnav {

class BaseClient : public ModuleClientOf<RGNav::Base> {
 public:
  explicit BaseClient(ClientSettings settings = ClientSettings::fromEnvironment(), std::string objectName = "Base");

  DataId latestOdometryId();
  DataBatch<OdometryReading> odometrySince(DataId afterId, std::uint32_t maxCount);
  // Interpolated odometry at a time stamp; NotAvailableError outside the buffered span.
  OdometryReading odometryAt(Timestamp stamp);
  // NotSupportedError where the base cannot drive (log playback).
  void setVelocity(double translational, double rotational);

 private:
  std::string consumer_;
};

}  // namespace rgnav
