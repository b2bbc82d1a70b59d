// LaserImpl and BaseImpl: the Laser.idl and Base.idl servants of every driver (log playback,
// simulator, robot): convert in, call the driver's LaserStream / BaseStream, convert out, with
// typed errors mapped to the IDL exceptions and every batch capped by the server.
#pragma once

#include <memory>

#include "Base.hh"
#include "Laser.hh"
#include "core/common/SensorStreams.h"
#include "servers/common/ServiceServant.h"

namespace rgnav {

class LaserImpl : public ServiceServant<POA_RGNav::Laser> {
 public:
  LaserImpl(ServerRuntime& runtime, std::shared_ptr<LaserStream> stream, std::uint32_t maxBatch);

  RGNav::DataId latestId() override;
  RGNav::DataId oldestId() override;
  RGNav::ScanBatch* scansSince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) override;
  RGNav::LaserScan* scan(RGNav::DataId id) override;

 private:
  std::shared_ptr<LaserStream> stream_;
  std::uint32_t maxBatch_;
};

class BaseImpl : public ServiceServant<POA_RGNav::Base> {
 public:
  BaseImpl(ServerRuntime& runtime, std::shared_ptr<BaseStream> stream, std::uint32_t maxBatch);

  RGNav::DataId latestOdometryId() override;
  RGNav::OdometryBatch* odometrySince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) override;
  RGNav::Odometry odometryAt(const RGNav::Time& stamp) override;
  void setVelocity(CORBA::Double translational, CORBA::Double rotational) override;

 private:
  std::shared_ptr<BaseStream> stream_;
  std::uint32_t maxBatch_;
};

}  // namespace rgnav
