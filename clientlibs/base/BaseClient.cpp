// BaseClient calls through the retrying connection (see BaseClient.h).
#include "clientlibs/base/BaseClient.h"

#include "clientlibs/base/convert.h"
#include "clientlibs/common/convert.h"

namespace rgnav {

BaseClient::BaseClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), settings), consumer_(settings.consumer) {}

DataId BaseClient::latestOdometryId() {
  return connection_.call("latestOdometryId", [](RGNav::Base_ptr b) { return b->latestOdometryId(); });
}

DataBatch<OdometryReading> BaseClient::odometrySince(DataId afterId, std::uint32_t maxCount) {
  return connection_.call("odometrySince", [&](RGNav::Base_ptr b) {
    RGNav::OdometryBatch_var batch = b->odometrySince(afterId, maxCount, consumer_.c_str());
    return fromIdl(batch.in());
  });
}

OdometryReading BaseClient::odometryAt(Timestamp stamp) {
  return connection_.call("odometryAt", [&](RGNav::Base_ptr b) { return fromIdl(b->odometryAt(toIdlTime(stamp))); });
}

void BaseClient::setVelocity(double translational, double rotational) {
  connection_.call("setVelocity", [&](RGNav::Base_ptr b) { b->setVelocity(translational, rotational); });
}

}  // namespace rgnav
