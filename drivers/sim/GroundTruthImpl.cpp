// The simulator's GroundTruth servant (see GroundTruthImpl.h).
#include "drivers/sim/GroundTruthImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/groundtruth/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {

GroundTruthImpl::GroundTruthImpl(ServerRuntime& runtime, std::shared_ptr<SimulatedRobot> robot)
    : ServiceServant(runtime), robot_(std::move(robot)) {}

RGNav::Pose2D GroundTruthImpl::truePose(RGNav::DataId scanId) {
  return serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireId(scanId, "scanId");
    return toIdl(robot_->truePoseOfScan(scanId));
  });
}

CORBA::Long GroundTruthImpl::roomAt(CORBA::Double x, CORBA::Double y) {
  return serve(Raises::InvalidArgument, [&] {
    wire::requireFinite(x, "x");
    wire::requireFinite(y, "y");
    return static_cast<CORBA::Long>(robot_->roomAt({x, y}));
  });
}

CORBA::ULong GroundTruthImpl::roomCount() {
  return serve(Raises::FailedOnly, [&] { return static_cast<CORBA::ULong>(robot_->roomCount()); });
}

RGNav::DoorLineSeq* GroundTruthImpl::doorLines() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::DoorLineSeq(
        toIdlSeq<RGNav::DoorLineSeq>(robot_->doorLines(), [](const DoorLine& d) { return toIdl(d); }));
  });
}

RGNav::PersonSeq* GroundTruthImpl::people() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::PersonSeq(toIdlSeq<RGNav::PersonSeq>(robot_->people(), [](const Person& p) { return toIdl(p); }));
  });
}

}  // namespace rgnav
