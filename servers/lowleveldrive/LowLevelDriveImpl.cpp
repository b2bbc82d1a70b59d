// The LowLevelDrive.idl servant (see LowLevelDriveImpl.h).
#include "servers/lowleveldrive/LowLevelDriveImpl.h"

#include "clientlibs/lowleveldrive/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {

LowLevelDriveImpl::LowLevelDriveImpl(ServerRuntime& runtime, DriveLoop& loop) : ServiceServant(runtime), loop_(loop) {}

void LowLevelDriveImpl::setChain(const RGNav::DriveChain& chain) {
  serve(Raises::InvalidArgument, [&] {
    wire::requireId(chain.id, "chain");
    wire::requireFinite(chain.startSpeed, "chain");
    wire::requireFinite(chain.cruiseSpeed, "chain");
    if (chain.cruiseSpeed < 0.0) wire::refuse("chain", "the cruise speed is negative");
    wire::requireValid(chain.startTime, "chain");
    if (chain.segments.length() == 0 || chain.segments.length() > RGNav::MAX_CHAIN_SEGMENTS)
      wire::refuse("chain", "a chain has 1 to " + std::to_string(RGNav::MAX_CHAIN_SEGMENTS) + " segments, not " +
                                std::to_string(chain.segments.length()));
    try {
      loop_.setChain(fromIdl(chain));
    } catch (const InvalidArgumentError& e) {
      wire::refuse("chain", e.what());
    }
  });
}

void LowLevelDriveImpl::stop() {
  serve(Raises::FailedOnly, [&] { loop_.brake(); });
}

RGNav::DriveReport LowLevelDriveImpl::driveStatus() {
  return serve(Raises::FailedOnly, [&] { return toIdl(loop_.report()); });
}

RGNav::MotionLimits LowLevelDriveImpl::limits() {
  return serve(Raises::FailedOnly, [&] { return toIdl(loop_.limits()); });
}

}  // namespace rgnav
