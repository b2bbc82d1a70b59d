// LowLevelDriveClient calls through the retrying connection (see LowLevelDriveClient.h).
#include "clientlibs/lowleveldrive/LowLevelDriveClient.h"

#include "clientlibs/lowleveldrive/convert.h"

namespace rgnav {

using Drive = RGNav::LowLevelDrive_ptr;

LowLevelDriveClient::LowLevelDriveClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), std::move(settings)) {}

void LowLevelDriveClient::setChain(const DriveChain& chain) {
  const RGNav::DriveChain wire = toIdl(chain);
  connection_.call("setChain", [&](Drive d) { d->setChain(wire); });
}

void LowLevelDriveClient::stop() {
  connection_.call("stop", [](Drive d) { d->stop(); });
}

DriveReport LowLevelDriveClient::driveStatus() {
  return connection_.call("driveStatus", [](Drive d) { return fromIdl(d->driveStatus()); });
}

MotionLimits LowLevelDriveClient::limits() {
  return connection_.call("limits", [](Drive d) { return fromIdl(d->limits()); });
}

}  // namespace rgnav
