// LaserClient: follows a laser module's scans by ID (Laser.idl) with core types in and out.
#pragma once

#include "Laser.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/common/DataBuffer.h"

namespace rgnav {

class LaserClient : public ModuleClientOf<RGNav::Laser> {
 public:
  explicit LaserClient(ClientSettings settings = ClientSettings::fromEnvironment(), std::string objectName = "Laser");

  DataId latestId();
  DataId oldestId();
  // Scans with ID > afterId, at most maxCount (the server may return fewer).
  DataBatch<LaserScan> scansSince(DataId afterId, std::uint32_t maxCount);
  // One scan; NotAvailableError if it is not held, InvalidArgumentError for ID 0.
  LaserScan scan(DataId id);

 private:
  std::string consumer_;
};

}  // namespace rgnav
