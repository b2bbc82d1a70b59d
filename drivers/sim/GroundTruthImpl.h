// GroundTruthImpl: the GroundTruth.idl servant of the simulator (evaluation programs only).
#pragma once

#include <memory>

#include "GroundTruth.hh"
#include "core/sim/SimulatedRobot.h"
#include "servers/common/ServiceServant.h"

namespace rgnav {

class GroundTruthImpl : public ServiceServant<POA_RGNav::GroundTruth> {
 public:
  GroundTruthImpl(ServerRuntime& runtime, std::shared_ptr<SimulatedRobot> robot);

  RGNav::Pose2D truePose(RGNav::DataId scanId) override;
  CORBA::Long roomAt(CORBA::Double x, CORBA::Double y) override;
  CORBA::ULong roomCount() override;
  RGNav::DoorLineSeq* doorLines() override;
  RGNav::PersonSeq* people() override;

 private:
  std::shared_ptr<SimulatedRobot> robot_;
};

}  // namespace rgnav
