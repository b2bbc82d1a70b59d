// The simulator's GroundTruth servant (see GroundTruthImpl.h).
#include "drivers/sim/GroundTruthImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/groundtruth/convert.h"
#include "servers/common/IdlErrors.h"

namespace rgnav {

GroundTruthImpl::GroundTruthImpl(ServerRuntime& runtime, std::shared_ptr<SimulatedRobot> robot)
    : ServiceServant(runtime), robot_(std::move(robot)) {}

RGNav::Pose2D GroundTruthImpl::truePose(RGNav::DataId scanId) {
  return toIdl(withIdlErrors([&] { return robot_->truePoseOfScan(scanId); }));
}

CORBA::Long GroundTruthImpl::roomAt(CORBA::Double x, CORBA::Double y) { return robot_->roomAt({x, y}); }

CORBA::ULong GroundTruthImpl::roomCount() { return robot_->roomCount(); }

RGNav::DoorLineSeq* GroundTruthImpl::doorLines() {
  return new RGNav::DoorLineSeq(
      toIdlSeq<RGNav::DoorLineSeq>(robot_->doorLines(), [](const DoorLine& d) { return toIdl(d); }));
}

}  // namespace rgnav
