// GatewayDetectionClient calls through the retrying connection (see GatewayDetectionClient.h).
#include "clientlibs/gatewaydetection/GatewayDetectionClient.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"

namespace rgnav {

GatewayDetectionClient::GatewayDetectionClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), settings), consumer_(settings.consumer) {}

GatewayEventBatch GatewayDetectionClient::eventsSince(GatewayEventId afterId, std::uint32_t maxCount) {
  return connection_.call("eventsSince", [&](RGNav::GatewayDetection_ptr m) {
    RGNav::GatewayEventBatch_var batch = m->eventsSince(afterId, maxCount, consumer_.c_str());
    return fromIdl(batch.in());
  });
}

std::vector<GatewayRecord> GatewayDetectionClient::gateways() {
  return connection_.call("gateways", [](RGNav::GatewayDetection_ptr m) {
    RGNav::GatewayInfoSeq_var all = m->gateways();
    return fromIdlSeq<std::vector<GatewayRecord>>(all.in(), [](const RGNav::GatewayInfo& g) { return fromIdl(g); });
  });
}

GatewayRecord GatewayDetectionClient::gateway(DetectorGatewayId id) {
  return connection_.call("gateway", [&](RGNav::GatewayDetection_ptr m) {
    RGNav::GatewayInfo_var g = m->gatewayById(id.value());
    return fromIdl(g.in());
  });
}

DataId GatewayDetectionClient::lastProcessedScan() {
  return connection_.call("lastProcessedScan", [](RGNav::GatewayDetection_ptr m) { return m->lastProcessedScan(); });
}

bool GatewayDetectionClient::detectsHallways() {
  return connection_.call("detectsHallways",
                          [](RGNav::GatewayDetection_ptr m) { return static_cast<bool>(m->detectsHallways()); });
}

}  // namespace rgnav
