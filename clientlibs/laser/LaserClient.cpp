// LaserClient calls through the retrying connection (see LaserClient.h).
#include "clientlibs/laser/LaserClient.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/laser/convert.h"

namespace rgnav {

LaserClient::LaserClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), settings), consumer_(settings.consumer) {}

DataId LaserClient::latestId() {
  return connection_.call("latestId", [](RGNav::Laser_ptr l) { return l->latestId(); });
}

DataId LaserClient::oldestId() {
  return connection_.call("oldestId", [](RGNav::Laser_ptr l) { return l->oldestId(); });
}

DataBatch<LaserScan> LaserClient::scansSince(DataId afterId, std::uint32_t maxCount) {
  return connection_.call("scansSince", [&](RGNav::Laser_ptr l) {
    RGNav::ScanBatch_var batch = l->scansSince(afterId, maxCount, consumer_.c_str());
    return fromIdl(batch.in());
  });
}

LaserScan LaserClient::scan(DataId id) {
  return connection_.call("scan", [&](RGNav::Laser_ptr l) {
    RGNav::LaserScan_var s = l->scan(id);
    return fromIdl(s.in());
  });
}

}  // namespace rgnav
